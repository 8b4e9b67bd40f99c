#!/usr/bin/env bash
# POST /api/studies/{name}/resume: a study cancelled while its first run was shearing (with a
# checkpoint) and its second was queued is resumed; the first goes on from its checkpoint, the
# second starts, and both series are, byte for byte, those of the same study run without a
# stop. Nothing left to resume is 409.
source "$(dirname "$0")/lib.sh"

DB=$TMP_ROOT/data/studies.db
CHECKPOINTS=$DB.checkpoints
# circular-quick, shearing 4x slower (about 4 s a run), a checkpoint every 0.2 s of wall time.
BASE=$("$GRAINLAB_CLI" preset circular-quick | node -e '
  const s = JSON.parse(require("fs").readFileSync(0, "utf8"));
  s.output.checkpoint_every_s = 0.2; s.stages[2].strain_rate = 0.25;
  console.log(JSON.stringify(s));')
spec() { echo "{ \"name\": \"$1\", \"base\": $BASE, \"vary\": { \"seed\": [1, 2] } }"; }

start_server "$TMP_ROOT/server.log" "$DB" --max-concurrent 1 --max-queued 4
req POST /api/studies -d "$(spec whole)"
whole=($(json 'b.run_parameters.map(r => r.id).join(" ")'))
for id in "${whole[@]}"; do check "uninterrupted run $id completes" wait_status "$id" completed 120; done

req POST /api/studies -d "$(spec paused)"
paused=($(json 'b.run_parameters.map(r => r.id).join(" ")'))
req POST /api/studies/paused/resume
expect "a study under way has nothing to resume: 409" 409 '"field":"study"'
first=${paused[0]}
for _ in $(seq 600); do
  req GET "/api/runs/$first"
  [[ $(json b.stage) == shearing && -e $CHECKPOINTS/run-$first.bin ]] && break
  sleep 0.05
done
sleep 0.3
req POST /api/studies/paused/cancel
expect "the study is cancelled while its first run is shearing" 202 '"cancelled":true'
check "...which ends cancelled" wait_status "$first" cancelled 30
req GET "/api/runs/${paused[1]}"
check "...and its queued run with it" test "$(json b.status)" = cancelled
req GET "/api/runs/$first/series?format=csv"
ROWS_AT_CANCEL=$(($(wc -l <<<"$BODY") - 1))
check "the cancelled run keeps its checkpoint ($ROWS_AT_CANCEL rows stored)" test -e "$CHECKPOINTS/run-$first.bin"

req POST /api/studies/paused/resume
expect "POST resume queues the study again" 202 '"cancelled":false'
check "...its runs under way" test "$(json '(b.by_status.queued ?? 0) + (b.by_status.running ?? 0)')" = 2
for id in "${paused[@]}"; do check "resumed run $id completes" wait_status "$id" completed 120; done
check "the first from its checkpoint in the shearing, not from the start" \
  grep -qE "run $first resumes at step [1-9][0-9]* \(sample [1-9]" "$TMP_ROOT/server.log"
for k in 0 1; do
  req GET "/api/runs/${whole[$k]}/series?format=csv"
  expected=$BODY
  req GET "/api/runs/${paused[$k]}/series?format=csv"
  check "seed $((k + 1)): the resumed study's series is the uninterrupted one's, byte for byte" test "$BODY" = "$expected"
done
req GET /api/studies/paused
check "the study is completed" test "$(json 'b.status + " " + b.by_status.completed')" = "completed 2"
check "...no checkpoint left behind" test ! -e "$CHECKPOINTS/run-$first.bin"
req POST /api/studies/paused/resume
expect "resuming a completed study is 409" 409 'no cancelled or interrupted run'
req POST /api/studies/nothing/resume
expect "an unknown study is 404" 404
req GET /api/studies/paused/resume
expect "resume is a POST" 405

check "server stops cleanly" stop_server
finish

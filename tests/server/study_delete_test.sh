#!/usr/bin/env bash
# DELETE /api/studies/{name}: a study with a run going and runs queued is deleted with all of
# it (runs, series, checkpoints, kept stages, its row); a finished one too; its name is free
# again. An unknown study is 404.
source "$(dirname "$0")/lib.sh"

DB=$TMP_ROOT/data/runs.db
CHECKPOINTS=$DB.checkpoints
start_server "$TMP_ROOT/server.log" "$DB" --max-concurrent 1 --max-queued 4

SPEC="{ \"name\": \"done\", \"base\": $TINY_SCENE, \"vary\": { \"stages.0.duration\": [0.001, 0.002] } }"
req POST /api/studies -d "$SPEC"
done_ids=($(json 'b.run_parameters.map(r => r.id).join(" ")'))
for id in "${done_ids[@]}"; do check "run $id completes" wait_status "$id" completed 30; done
# Three discs falling for 1000 s of simulated time with a checkpoint every 0.1 s of wall time.
LONG=$(node -e "const s = JSON.parse(process.argv[1]); s.output.checkpoint_every_s = 0.1; console.log(JSON.stringify(s))" "$LONG_SCENE")
req POST /api/studies -d "{ \"name\": \"going\", \"base\": $LONG, \"vary\": { \"gravity.1\": [-9.81, -9.7, -9.6] } }"
going=($(json 'b.run_parameters.map(r => r.id).join(" ")'))
check "the long study's first run starts" wait_status "${going[0]}" running 30
for _ in $(seq 100); do [[ -e $CHECKPOINTS/run-${going[0]}.bin ]] && break; sleep 0.05; done
check "...and keeps a checkpoint" test -e "$CHECKPOINTS/run-${going[0]}.bin"

req DELETE /api/studies/going
check "DELETE of a study under way: 204 once all of it is gone" test "$STATUS" = 204
req GET /api/studies/going
expect "...it is no study any more" 404
req GET "/api/runs?study=going"
check "...none of its runs is left" test "$(json b.total)" = 0
for id in "${going[@]}"; do
  req GET "/api/runs/$id"
  check "...run $id: 404" test "$STATUS" = 404
done
check "...nor its checkpoint" test ! -e "$CHECKPOINTS/run-${going[0]}.bin"

req DELETE /api/studies/done
check "DELETE of a finished study: 204" test "$STATUS" = 204
req GET "/api/runs/${done_ids[0]}/series"
expect "...its series are gone" 404
req GET /api/studies
check "no study is left" test "$(json b.studies.length)" = 0
req POST /api/studies -d "$SPEC"
expect "the name is free again" 201 '"name":"done"'
req DELETE /api/studies/nothing
expect "an unknown study: 404" 404

check "server stops cleanly" stop_server
finish

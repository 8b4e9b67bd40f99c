#!/usr/bin/env bash
# Resuming server runs: a run whose server was killed with -9 (or stopped with SIGTERM) comes
# back `interrupted` and `resumable`; POST /api/runs/{id}/resume (or grainlab serve
# --resume-interrupted) completes it, and its stored series and replay frames are then the
# same, byte for byte, as those of the same scene run without interruption: nothing the
# killed server stored past its last checkpoint is duplicated, nothing before it is lost.
source "$(dirname "$0")/lib.sh"

DB=$TMP_ROOT/data/resume.db
CHECKPOINTS=$DB.checkpoints
# circular-quick, shearing 4x slower (about 4 s in all), a checkpoint every 0.2 s of wall time.
SCENE=$("$GRAINLAB_CLI" preset circular-quick | node -e '
  const s = JSON.parse(require("fs").readFileSync(0, "utf8"));
  s.name = "resumable"; s.output.checkpoint_every_s = 0.2; s.stages[2].strain_rate = 0.25;
  console.log(JSON.stringify(s));')

start_server "$TMP_ROOT/1.log" "$DB" --max-concurrent 1
req POST /api/runs --data "$SCENE"
WHOLE=$(json b.id)
check "the uninterrupted run completes" wait_status "$WHOLE" completed 120
req GET "/api/runs/$WHOLE/series?format=csv"
CSV_WHOLE=$BODY
req GET "/api/runs/$WHOLE/frames"
FRAMES_WHOLE=$(json 'JSON.stringify(b.frames)')
check "it left no checkpoint behind" test ! -e "$CHECKPOINTS/run-$WHOLE.bin"
req POST "/api/runs/$WHOLE/resume"
expect "a completed run cannot be resumed" 409 'no checkpoint'
req POST "/api/runs/999999/resume"
expect "nor an unknown one" 404
req GET "/api/runs/$WHOLE/resume"
expect "resume is a POST" 405

# kill -9 in the shearing, after a checkpoint and with rows stored past it.
req POST /api/runs --data "$SCENE"
KILLED=$(json b.id)
req POST "/api/runs/$KILLED/resume"
expect "a live run cannot be resumed" 409 'not stopped'
for _ in $(seq 600); do
  req GET "/api/runs/$KILLED"
  [[ $(json b.stage) == shearing && -e $CHECKPOINTS/run-$KILLED.bin ]] && break
  sleep 0.05
done
sleep 0.3
req GET "/api/runs/$KILLED"
check "it is shearing, with a checkpoint, when killed" test "$(json b.stage)" = shearing -a -e "$CHECKPOINTS/run-$KILLED.bin"
stop_server KILL

start_server "$TMP_ROOT/2.log" "$DB" --max-concurrent 1
req GET "/api/runs/$KILLED"
expect "the killed run is interrupted and resumable" 200 '"resumable":true'
check "the server lists it on start-up" grep -q "run $KILLED (resumable) was interrupted" "$TMP_ROOT/2.log"
req GET "/api/runs/$KILLED/series?format=csv"
ROWS_AT_KILL=$(($(wc -l <<<"$BODY") - 1))
req POST "/api/runs/$KILLED/resume"
expect "POST resume accepts it" 202 '"status":"(queued|running)"'
check "the resumed run completes" wait_status "$KILLED" completed 120
check "from its checkpoint in the shearing, not from the start" \
  grep -qE "run $KILLED resumes at step [1-9][0-9]* \(sample [1-9]" "$TMP_ROOT/2.log"
req GET "/api/runs/$KILLED/series?format=csv"
check "its series is the uninterrupted run's, byte for byte ($ROWS_AT_KILL rows stored at the kill)" \
  test "$BODY" = "$CSV_WHOLE"
req GET "/api/runs/$KILLED/frames"
check "and so are its replay frames" test "$(json 'JSON.stringify(b.frames)')" = "$FRAMES_WHOLE"
req GET "/api/runs/$KILLED"
expect "it is no longer resumable" 200 '"resumable":false'
check "its checkpoint is gone" test ! -e "$CHECKPOINTS/run-$KILLED.bin"

# SIGTERM stops a run cleanly (a checkpoint at the stop); --resume-interrupted resumes it.
req POST /api/runs --data "$SCENE"
STOPPED=$(json b.id)
check "another run starts" wait_status "$STOPPED" running 30
sleep 1
stop_server TERM
check "SIGTERM with a run going exits 0" test $? -eq 0
check "the stopped run kept its checkpoint" test -e "$CHECKPOINTS/run-$STOPPED.bin"
start_server "$TMP_ROOT/3.log" "$DB" --max-concurrent 1 --resume-interrupted
check "--resume-interrupted resumes it" grep -q "resuming run $STOPPED" "$TMP_ROOT/3.log"
check "to the end" wait_status "$STOPPED" completed 120
check "from the step where SIGTERM stopped it" grep -qE "run $STOPPED resumes at step [1-9]" "$TMP_ROOT/3.log"
req GET "/api/runs/$STOPPED/series?format=csv"
check "with the uninterrupted run's series" test "$BODY" = "$CSV_WHOLE"

# A cancelled run is not resumable; deleting a stopped run deletes its checkpoint.
req POST /api/runs --data "$SCENE"
CANCELLED=$(json b.id)
check "a run to cancel starts" wait_status "$CANCELLED" running 30
req POST "/api/runs/$CANCELLED/cancel"
check "it is cancelled" wait_status "$CANCELLED" cancelled 30
req POST "/api/runs/$CANCELLED/resume"
expect "a cancelled run cannot be resumed" 409
stop_server TERM
finish

#!/usr/bin/env bash
# A launched study survives a restart: stopped (SIGTERM) with one run going and two queued,
# the next server (--resume-interrupted) resumes the run from its checkpoint and queues the
# others again; every run completes, the study's counts and progress follow, and the resumed
# run's series is the series of the same scene run without a stop, byte for byte.
source "$(dirname "$0")/lib.sh"

DB=$TMP_ROOT/runs.db
# Three discs for 60 s of simulated time: a few seconds of work each.
BASE=$(node -e 'const s = JSON.parse(process.argv[1]); s.stages[0].duration = 60; console.log(JSON.stringify(s))' "$LONG_SCENE")
start_server "$TMP_ROOT/1.log" "$DB" --max-concurrent 1
req POST /api/studies -d "{ \"name\": \"durable\", \"base\": $BASE, \"vary\": { \"stages.0.duration\": [60, 61, 62] } }"
expect "a study of three runs" 201
ids=($(json 'b.run_parameters.map(r => r.id).join(" ")'))
check "its first run starts" wait_status "${ids[0]}" running 30
for _ in $(seq 100); do
  req GET "/api/runs/${ids[0]}"
  (($(json b.steps) > 0)) && break
  sleep 0.1
done
stop_server TERM
check "SIGTERM with the study under way exits 0" test $? -eq 0

start_server "$TMP_ROOT/2.log" "$DB" --max-concurrent 1
req GET /api/studies/durable
# Without --resume-interrupted the queued runs go on, the interrupted one waits to be asked.
check "after a restart: 1 run interrupted, the 2 queued ones queued again (or running)" \
  test "$(json 'b.by_status.interrupted + " " + ((b.by_status.queued || 0) + (b.by_status.running || 0)) + " " + ["running", "queued"].includes(b.status)')" = "1 2 true"
req GET "/api/runs/${ids[0]}"
expect "the interrupted run is resumable" 200 '"resumable":true'
stop_server TERM

start_server "$TMP_ROOT/3.log" "$DB" --max-concurrent 1 --resume-interrupted
check "--resume-interrupted resumes the study's interrupted run" grep -q "resuming run ${ids[0]} " "$TMP_ROOT/3.log"
seen_partial=0
for _ in $(seq 600); do
  req GET /api/studies/durable
  done=$(json 'b.by_status.completed || 0')
  # Progress is the share of its runs that have ended, at every look.
  [[ $(json "b.progress === $done / 3") == true ]] || { fail "progress $(json b.progress) with $done of 3 done"; break; }
  ((done > 0 && done < 3)) && seen_partial=1
  ((done == 3)) && break
  sleep 0.1
done
check "every run of the study completes" test "$(json 'b.status + " " + b.progress + " " + b.by_status.completed')" = "completed 1 3"
check "...its progress seen between 0 and 1 on the way" test "$seen_partial" = 1
req GET "/api/runs/${ids[0]}/series?format=csv"
RESUMED=$BODY
# The same scene run without a stop.
req GET "/api/runs/${ids[0]}"
scene=$(json 'JSON.stringify(b.scene)')
req POST /api/runs -d "$scene"
again=$(json b.id)
check "the same scene as a plain run completes" wait_status "$again" completed 60
req GET "/api/runs/$again/series?format=csv"
check "the resumed run's series is the unstopped run's, byte for byte" test "$BODY" = "$RESUMED"

# A study cancelled while a run of it is interrupted: that run ends cancelled too, not
# resumable, and the next --resume-interrupted leaves it.
req POST /api/studies -d "{ \"name\": \"dropped\", \"base\": $BASE, \"vary\": { \"stages.0.duration\": [1000, 1001] } }"
dropped=($(json 'b.run_parameters.map(r => r.id).join(" ")'))
check "a second study's first run starts" wait_status "${dropped[0]}" running 30
stop_server TERM
start_server "$TMP_ROOT/4.log" "$DB" --max-concurrent 1
check "its second run starts after the restart" wait_status "${dropped[1]}" running 30
req GET "/api/runs/${dropped[0]}"
expect "its first is interrupted and resumable" 200 '"resumable":true'
req POST /api/studies/dropped/cancel
expect "cancelling the study" 202 '"cancelled":true'
check "its running run ends cancelled" wait_status "${dropped[1]}" cancelled 30
req GET "/api/runs/${dropped[0]}"
check "its interrupted run is cancelled, no longer resumable" \
  test "$(json 'b.status + " " + b.resumable')" = "cancelled false"
req GET /api/studies/dropped
check "the study is cancelled, progress 1" test "$(json 'b.status + " " + b.progress + " " + b.by_status.cancelled')" = "cancelled 1 2"
stop_server TERM
start_server "$TMP_ROOT/5.log" "$DB" --max-concurrent 1 --resume-interrupted
check "--resume-interrupted leaves the cancelled study's run" bash -c "! grep -q 'resuming run ${dropped[0]} ' '$TMP_ROOT/5.log'"
req GET "/api/runs/${dropped[0]}"
expect "...cancelled" 200 '"status":"cancelled"'
stop_server TERM
finish

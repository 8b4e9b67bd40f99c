#!/usr/bin/env bash
# A study's time left (GET /api/studies/{name}: seconds_left): four runs one at a time, watched
# until done. Before any run has finished it rests on the runs' estimates; after, on the pace
# the finished ones kept. It falls as runs finish (the first value seen after each finish is
# below the one after the finish before) and is 0 once the study is done, in the list too.
source "$(dirname "$0")/lib.sh"

start_server "$TMP_ROOT/server.log" "$TMP_ROOT/runs.db" --max-concurrent 1 --max-queued 8

# Three discs falling onto a wall for DURATION seconds of simulated time: a second or so of
# wall time each, long enough to be seen running.
SCENE=$(node -e "const s = JSON.parse(process.argv[1]); s.stages[0].duration = 15; s.output.sample_interval = 0.5; console.log(JSON.stringify(s))" "$LONG_SCENE")
req POST /api/studies -d "{ \"name\": \"paced\", \"base\": $SCENE, \"vary\": { \"gravity.1\": [-9.81, -9.7, -9.6, -9.5] } }"
expect "a 4-run study is launched" 201 '"runs":4'
check "...with a time left from the estimates before any run finished" \
  test "$(json 'b.seconds_left > 0 && b.seconds_left_basis')" = estimate

# Poll until done: each poll's completed count, seconds left and basis (the launch's answer first).
log=$TMP_ROOT/polls
json '[b.by_status.completed ?? 0, b.seconds_left, b.seconds_left_basis, b.status].join(" ")' >"$log"
for _ in $(seq 1200); do
  req GET /api/studies/paced
  json '[b.by_status.completed ?? 0, b.seconds_left, b.seconds_left_basis, b.status].join(" ")' >>"$log"
  [[ $(json b.status) == completed ]] && break
  sleep 0.05
done
echo "# completed seconds_left basis status (first poll after each finish):"
awk 'BEGIN { last = "none" } $1 != last { print "#   " $0; last = $1 }' "$log"
check "the study completed" test "$(tail -1 "$log" | cut -d' ' -f4)" = completed
check "...and its time left is then 0 (done)" test "$(tail -1 "$log" | cut -d' ' -f2,3)" = "0 done"
firsts=$(awk 'BEGIN { last = "none" } $1 != last { print $1 ":" $2 ":" $3; last = $1 }' "$log")
check "each finish was seen (0 to 4 completed)" test "$(cut -d: -f1 <<<"$firsts" | tr '\n' ' ')" = "0 1 2 3 4 "
check "...after the first, the pace measured" \
  test "$(cut -d: -f3 <<<"$firsts" | tr '\n' ' ')" = "estimate measured measured measured done "
falls() {  # the seconds left after 1, 2, 3 and 4 finished runs fall strictly
  local previous= value
  for value in $(awk -F: '$1 >= 1 { print $2 }' <<<"$firsts"); do
    [[ -z $previous ]] || node -e "process.exit($value < $previous ? 0 : 1)" || { echo "$value after $previous"; return 1; }
    previous=$value
  done
}
check "...and falls as runs finish" falls
req GET /api/studies
check "the list shows 0 s left for it too" test "$(json 'b.studies.find(s => s.name === "paced").seconds_left')" = 0

check "server stops cleanly" stop_server
finish

#!/usr/bin/env bash
# POST /api/studies: a sweep spec queued as a study. Its runs are grainlab sweep's runs (the
# same series, byte for byte); a spec of which any run would be refused is refused whole,
# naming the field, with nothing stored; a study is cancelled as its runs are.
source "$(dirname "$0")/lib.sh"
cli=$GRAINLAB_CLI

start_server "$TMP_ROOT/server.log" "$TMP_ROOT/runs.db" --max-concurrent 1 --max-queued 3 --max-particles 100 \
  --max-run-seconds 30

SPEC="{ \"name\": \"durations\", \"base\": $TINY_SCENE, \"vary\": { \"stages.0.duration\": [0.001, 0.002, 0.003] } }"
req POST /api/studies -d "$SPEC"
expect "POST /api/studies launches a study" 201 '"name":"durations"'
check "...at Location /api/studies/durations" test "$(header Location)" = /api/studies/durations
check "...of 3 runs, launched" test "$(json 'b.runs + " " + b.source + " " + b.run_parameters.length')" = "3 launched 3"
ids=$(json 'b.run_parameters.map(r => r.id).join(" ")')
for id in $ids; do check "run $id completes" wait_status "$id" completed 30; done
req GET /api/studies/durations
expect "the study is completed once its runs are" 200 '"status":"completed"'
check "...progress 1, 3 completed" test "$(json 'b.progress + " " + b.by_status.completed')" = "1 3"
check "...its spec as posted, keys in their order (vary's order is its runs' order)" \
  test "$(json 'Object.keys(b.spec).join() + " " + b.spec.vary["stages.0.duration"].join()')" = "name,base,vary 0.001,0.002,0.003"
req GET "/api/runs?study=durations&order=asc"
check "its runs carry the study, in the spec's order" \
  test "$(json 'b.runs.map(r => r.study + ":" + r.name).join(" ")')" = \
  "durations:durations/001-duration=0.001 durations:durations/002-duration=0.002 durations:durations/003-duration=0.003"
third=$(json 'b.runs[2].id')
req GET "/api/runs/$third"
check "a run's scene has its value" test "$(json 'b.scene.stages[0].duration')" = 0.003
# The same spec through grainlab sweep: the same runs, the same numbers.
printf '%s' "$SPEC" >"$TMP_ROOT/spec.json"
check "grainlab sweep on the same spec" "$cli" sweep "$TMP_ROOT/spec.json" --out "$TMP_ROOT/sweep" --jobs 1 2>/dev/null
req GET "/api/runs/$third/series?format=csv"
check "...writes the study's run's series byte for byte" \
  cmp <(printf '%s' "$BODY") "$TMP_ROOT/sweep/runs/003-duration=0.003/series.csv"
req POST /api/studies -d "$SPEC"
expect "a name in use is 409 naming name" 409 '"field":"name"'

# Bad input: refused whole, naming the field, and nothing stored.
req GET /api/studies
STUDIES_BEFORE=$BODY
req GET /api/runs
RUNS_BEFORE=$(json b.total)
nothing_new() {
  req GET /api/studies
  [[ $BODY == "$STUDIES_BEFORE" ]] || { echo "studies now: $BODY"; return 1; }
  req GET /api/runs
  [[ $(json b.total) == "$RUNS_BEFORE" ]] || { echo "runs now: $(json b.total)"; return 1; }
}
refused() {  # refused DESCRIPTION STATUS FIELD SPEC: sets REFUSAL and RETRY_AFTER
  req POST /api/studies -d "$4"
  REFUSAL=$BODY
  RETRY_AFTER=$(header Retry-After)
  local pattern
  pattern=$(sed 's/[][().]/\\&/g' <<<"\"field\":\"$3\"")
  expect "$1: $2 naming $3" "$2" "$pattern"
  check "...and nothing is stored" nothing_new
}
refused "an unknown path in vary" 400 vary.stages.0.durtion \
  "{ \"name\": \"bad\", \"base\": $TINY_SCENE, \"vary\": { \"stages.0.durtion\": [0.001] } }"
refused "a stage that is not there" 400 vary.stages.3.duration \
  "{ \"name\": \"bad\", \"base\": $TINY_SCENE, \"vary\": { \"stages.3.duration\": [0.001] } }"
refused "a negative friction in the second run" 400 vary.material.friction \
  "{ \"name\": \"bad\", \"base\": $TINY_SCENE, \"vary\": { \"material.friction\": [0.5, -0.1] } }"
check "...the message says which run and why" grep -q 'run 2 (material.friction = -0.1): material.friction: must be >= 0' <<<"$REFUSAL"
refused "a second run longer than --max-run-seconds" 400 vary.stages.0.duration \
  "{ \"name\": \"bad\", \"base\": $LONG_SCENE, \"vary\": { \"stages.0.duration\": [1, 1000000] } }"
check "...the message says which run and why" grep -q 'run 2 (stages.0.duration = 1000000): the run would take about' <<<"$REFUSAL"
refused "more runs than the server holds at once (1 running + 3 queued)" 400 vary \
  "{ \"name\": \"bad\", \"base\": $TINY_SCENE, \"vary\": { \"stages.0.duration\": [0.001, 0.002, 0.003, 0.004, 0.005] } }"
check "...the message names the limits" grep -q 'this server holds at most 4 at once' <<<"$REFUSAL"
refused "more particles than --max-particles" 503 'runs[0].particles' \
  "{ \"name\": \"bad\", \"base\": {\"preset\": \"circular-quick\"}, \"vary\": { \"seed\": [1, 2] } }"
refused "no name" 400 name "{ \"base\": $TINY_SCENE, \"vary\": { \"seed\": [1] } }"
refused "a name that is no path segment" 400 name "{ \"name\": \"a/b\", \"base\": $TINY_SCENE, \"vary\": { \"seed\": [1] } }"
refused "prepare (grainlab sweep's, not the server's)" 400 prepare \
  "{ \"name\": \"bad\", \"base\": $TINY_SCENE, \"prepare\": {}, \"vary\": { \"seed\": [1] } }"
refused "an unknown key" 400 vry "{ \"name\": \"bad\", \"base\": $TINY_SCENE, \"vry\": { \"seed\": [1] } }"
refused "malformed JSON" 400 '(json)' '{"name": "bad",'

# A queue with room for one run: a study of two must wait (429, as a run would get).
busy=()
for _ in 1 2 3; do
  req POST /api/runs -d "$LONG_SCENE"
  busy+=("$(json b.id)")
done
wait_status "${busy[0]}" running 30
RUNS_BEFORE=$((RUNS_BEFORE + 3))
refused "two runs when the queue has room for one" 429 vary \
  "{ \"name\": \"later\", \"base\": $TINY_SCENE, \"vary\": { \"stages.0.duration\": [0.001, 0.002] } }"
check "...with Retry-After" test "$RETRY_AFTER" = 5
for id in "${busy[@]}"; do req POST "/api/runs/$id/cancel"; done
check "the busy runs are cancelled" wait_status "${busy[0]}" cancelled 30

# Cancel: the running run is asked to stop (202), the queued ones end at once.
req POST /api/studies -d "{ \"name\": \"slow\", \"base\": $LONG_SCENE, \"vary\": { \"stages.0.duration\": [1000, 1001, 1002] } }"
expect "a study of three long runs" 201
slow=($(json 'b.run_parameters.map(r => r.id).join(" ")'))
check "its first run starts" wait_status "${slow[0]}" running 30
req POST /api/studies/slow/cancel
expect "POST /api/studies/slow/cancel asks the running run to stop: 202" 202 '"name":"slow"'
for id in "${slow[@]}"; do check "run $id ends cancelled" wait_status "$id" cancelled 30; done
req GET /api/studies/slow
expect "the study is cancelled" 200 '"status":"cancelled"'
check "...marked so, progress 1" test "$(json 'b.cancelled + " " + b.progress')" = "true 1"
req POST /api/studies/slow/cancel
expect "cancelling it again is 409" 409 '"field":"study"'
req POST /api/studies/nosuch/cancel
expect "an unknown study is 404" 404 '"field":"study"'
req GET /api/studies/slow/cancel
expect "GET on cancel is 405" 405
req POST /api/runs -d "$LONG_SCENE"
blocker=$(json b.id)
wait_status "$blocker" running 30
req POST /api/studies -d "{ \"name\": \"queued\", \"base\": $TINY_SCENE, \"vary\": { \"stages.0.duration\": [0.001, 0.002] } }"
expect "a study queued behind a run" 201 '"by_status":\{"queued":2\}'
req POST /api/studies/queued/cancel
expect "a study whose runs are all queued is cancelled at once: 200" 200 '"by_status":\{"cancelled":2\}'
req POST "/api/runs/$blocker/cancel"
stop_server
finish

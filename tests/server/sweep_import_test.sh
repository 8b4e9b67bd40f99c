#!/usr/bin/env bash
# A sweep folder into the database: `grainlab import DIR` (beside a running server, without
# disturbing its runs) and POST /api/sweeps/import. The imported series is the run's own
# series.csv byte for byte; importing twice adds nothing.
source "$(dirname "$0")/lib.sh"
cli=$GRAINLAB_CLI

sweep() {  # sweep NAME DURATIONS: a two-run sweep of the tiny scene into $TMP_ROOT/NAME
  cat > "$TMP_ROOT/$1.json" <<JSON
{ "name": "$1", "base": $TINY_SCENE, "vary": { "stages.0.duration": $2 } }
JSON
  "$cli" sweep "$TMP_ROOT/$1.json" --out "$TMP_ROOT/$1" --jobs 2 2>/dev/null
}
check "a sweep to import" sweep first "[0.001, 0.002]"
check "a second sweep" sweep second "[0.003, 0.004]"
check "a third sweep" sweep third "[0.005, 0.006]"

db=$TMP_ROOT/runs.db
out=$("$cli" import "$TMP_ROOT/first" --db "$db")
check "grainlab import adds both runs" grep -q '^imported 2 runs' <<<"$out"
out=$("$cli" import "$TMP_ROOT/first" --db "$db")
check "importing again adds none" grep -q '^imported 0 runs.*2 were there already' <<<"$out"
"$cli" import "$TMP_ROOT/nowhere" --db "$db" 2>"$TMP_ROOT/err"; status=$?
check "a folder that is no sweep is refused with status 2" test "$status" -eq 2
check "...saying why" grep -q 'not a sweep folder' "$TMP_ROOT/err"

start_server "$TMP_ROOT/server.log" "$db" --import-root "$TMP_ROOT"
req GET /api/runs
expect "the server lists the imported runs" 200 '"name":"first/001-duration=0.001"'
id=$(json 'b.runs.find(r => r.name === "first/002-duration=0.002").id')
req GET "/api/runs/$id"
expect "an imported run is completed" 200 '"status":"completed"'
req GET "/api/runs/$id/series?format=csv"
check "its series is the run's series.csv byte for byte" \
  cmp <(printf '%s' "$BODY") "$TMP_ROOT/first/runs/002-duration=0.002/series.csv"

# The CLI beside the live server: the server's running run must not be marked interrupted.
req POST /api/runs -H 'Content-Type: application/json' -d "$LONG_SCENE"
long=$(json b.id)
wait_status "$long" running 30
out=$("$cli" import "$TMP_ROOT/third" --db "$db")
check "grainlab import beside a running server" grep -q '^imported 2 runs' <<<"$out"
req GET "/api/runs/$long"
expect "...leaves the server's running run running" 200 '"status":"running"'
req POST "/api/runs/$long/cancel"

req POST /api/sweeps/import -H 'Content-Type: application/json' -d "{\"dir\": \"$TMP_ROOT/second\"}"
expect "POST /api/sweeps/import" 200 '"imported":2'
req POST /api/sweeps/import -H 'Content-Type: application/json' -d "{\"dir\": \"$TMP_ROOT/second\"}"
expect "...twice adds nothing" 200 '"already_there":2'
req POST /api/sweeps/import -H 'Content-Type: application/json' -d "{\"dir\": \"$TMP_ROOT/nowhere\"}"
expect "a folder that is no sweep is a 400 naming dir" 400 '"field":"dir"'
req POST /api/sweeps/import -H 'Content-Type: application/json' -d '{"dir": 3}'
expect "a dir that is not a string is a 400" 400 '"field":"dir"'
req GET /api/sweeps/import
expect "GET is not allowed" 405
req GET /api/runs
check "six runs imported in all, besides the live one" test "$(json 'b.runs.filter(r => r.name.includes("/0")).length')" -eq 6
# Each sweep is a study: its runs carry its name and are listed by it.
req GET "/api/runs?study=second&limit=1"
expect "GET /api/runs?study=second finds the second sweep's runs" 200 '"study":"second"'
check "...both, one to a page" test "$(json 'b.total + "," + b.runs.length + "," + b.runs[0].name.startsWith("second/")')" = "2,1,true"
req GET /api/studies
expect "GET /api/studies lists the imported sweeps" 200 '"name":"first"'
check "...three, each of 2 completed runs" test "$(json 'b.studies.map(s => s.name + ":" + s.by_status.completed).join(" ")')" = "first:2 second:2 third:2"
stop_server
finish

#!/usr/bin/env bash
# The HTTP API against the real server over loopback with curl: create, list, get, series as
# JSON and CSV (byte for byte the CLI's series.csv), cancel, delete, static files, and every
# refusal with its status code and message. Also starts the real `grainlab serve` once.
source "$(dirname "$0")/lib.sh"

WEB=$TMP_ROOT/web
mkdir -p "$WEB/js" "$TMP_ROOT/outside"
echo '<!doctype html><title>grainlab</title>' >"$WEB/index.html"
echo 'export const x = 1;' >"$WEB/js/app.js"
echo 'body { margin: 0 }' >"$WEB/style.css"
echo '{}' >"$WEB/data.json"
echo 'secret' >"$TMP_ROOT/outside/secret.txt"

start_server "$TMP_ROOT/server.log" "$TMP_ROOT/db/api.db" --web "$WEB" --max-concurrent 1 --max-queued 1 \
  --max-particles 100 --max-body 100000

# ---- health, presets ----
req GET /api/health
expect "health" 200 '"status":"ok"'
check "binds 127.0.0.1 only" grep -q 'listening on http://127.0.0.1:' "$TMP_ROOT/server.log"
check "database created with its parent directory" test -f "$TMP_ROOT/db/api.db"
req GET /api/presets
expect "presets list the paper's assemblies" 200 '"circular-quick"'
req GET /api/presets/elongated-bedding-30
expect "a preset's scene" 200 '"assembly"'

# ---- a run from create to completed ----
req POST /api/runs -H 'Content-Type: application/json' --data "$TINY_SCENE"
expect "create a run" 201 '^\{"id":[0-9]+\}$'
ID=$(json b.id)
check "Location header" test "$(header Location)" = "/api/runs/$ID"
req GET /api/runs
expect "the list has it" 200 "\"id\":$ID"
check "tiny run completes" wait_status "$ID" completed 60
req GET "/api/runs/$ID"
expect "run detail" 200 '"progress":1(\.0)?,'
check "detail has the estimate it was queued with" test "$(json 'typeof b.estimated_seconds')" = number
check "detail has name, times, wall time, scene" test "$(json '[b.name, typeof b.created_at, typeof b.finished_at, typeof b.wall_seconds, b.scene.name].join()')" = "tiny,string,string,number,tiny"
req HEAD "/api/runs/$ID"
check "HEAD gives the headers (Content-Length $(header Content-Length)) without the body" \
  test "$STATUS" = 200 -a "$(header Content-Length)" -gt 0 -a "${BODY/\"id\"/}" = "$BODY"

req GET "/api/runs/$ID/series"
expect "series as JSON" 200 '"columns":\["step","time","stage"'
ROWS=$(json b.rows.length)
check "series has rows ($ROWS)" test "$ROWS" -gt 2
req GET "/api/runs/$ID/series?format=csv"
expect "series as CSV" 200 '^step,time,stage,axial_strain'
check "CSV content type" test "$(header Content-Type)" = "text/csv; charset=utf-8"
printf '%s' "$BODY" >"$TMP_ROOT/rest.csv"
CSV_ROWS=$(($(wc -l <"$TMP_ROOT/rest.csv") - 1))
check "CSV has a line per JSON row ($CSV_ROWS)" test "$CSV_ROWS" = "$ROWS"
if [[ -x ${GRAINLAB_CLI:-} ]]; then
  echo "$TINY_SCENE" >"$TMP_ROOT/tiny.json"
  check "grainlab run of the same scene finishes" timeout 60 "$GRAINLAB_CLI" run "$TMP_ROOT/tiny.json" --out "$TMP_ROOT/cli-out" 2>/dev/null
  check "REST CSV is byte for byte the CLI's series.csv" cmp "$TMP_ROOT/rest.csv" "$TMP_ROOT/cli-out/series.csv"
fi
req GET "/api/runs/$ID/frames"
expect "frame index" 200 '"frames":\[\{"bytes":[0-9]+,"index":0'
FRAME_STATUS=$(curl -s -o "$TMP_ROOT/frame.bin" -D "$HEADERS" -w '%{http_code}' "$(BASE)/api/runs/$ID/frames?index=0")
check "a frame is binary GLF1" test "$FRAME_STATUS-$(header Content-Type)-$(head -c 4 "$TMP_ROOT/frame.bin")" = "200-application/octet-stream-GLF1"
check "the frame at or before a step" test "$(curl -s -o /dev/null -w '%{http_code}' "$(BASE)/api/runs/$ID/frames?step=1000000")" = 200
req GET "/api/runs/$ID/shapes"
expect "shapes" 200 '"type":"shapes","walls"|"count":1'
req GET "/api/runs/$ID/histograms?latest=1"
expect "histograms" 200 '^\{"id":'

# ---- cancel and delete ----
req POST /api/runs --data "$LONG_SCENE"
LONG=$(json b.id)
check "long run starts" wait_status "$LONG" running 30
req POST /api/runs --data "$TINY_SCENE"
QUEUED=$(json b.id)
req GET "/api/runs/$QUEUED"
expect "second run waits in the queue (one at a time)" 200 '"status":"queued"'
req POST /api/runs --data "$TINY_SCENE"
expect "queue full: 429" 429 'queue is full'
check "429 says when to retry" test "$(header Retry-After)" = 5
req POST "/api/runs/$QUEUED/cancel"
expect "cancel a queued run" 200 '"status":"cancelled"'
req POST "/api/runs/$LONG/cancel"
expect "cancel a running run" 202 '"cancel_requested":true'
check "running run ends cancelled" wait_status "$LONG" cancelled 30
req GET "/api/runs/$LONG/series"
check "a cancelled run keeps its series" test "$(json b.rows.length)" -gt 0
req POST "/api/runs/$LONG/cancel"
expect "cancel an ended run: 409" 409 'already ended'
req DELETE "/api/runs/$LONG"
expect "delete" 204
req GET "/api/runs/$LONG"
expect "deleted run is gone" 404 '"error":"no run '
req GET "/api/runs/$LONG/series"
expect "its series too" 404
req DELETE "/api/runs/$LONG"
expect "delete twice: 404" 404

# ---- bad input, each with its status and a message naming the field ----
req POST /api/runs --data '{"name": "x", '
expect "invalid JSON: 400 (json)" 400 '"field":"\(json\)"'
req POST /api/runs --data '[]'
expect "not an object: 400" 400 '"field":"\(json\)"'
req POST /api/runs --data '{"name":"x","particles":[{"shape":"disc","position":[0,0]}]}'
expect "missing radius: 400 names particles[0].radius" 400 '"error":"[^"]+","field":"particles\[0\]\.radius"'
req POST /api/runs --data '{"name":"x","material":{"friction":-1},"particles":[{"shape":"disc","radius":0.002,"position":[0,0]}]}'
expect "out-of-range friction: 400 names it" 400 '"field":"material\.friction"'
req POST /api/runs --data '{"name":"x","colour":"red","particles":[{"shape":"disc","radius":0.002,"position":[0,0]}]}'
expect "unknown key: 400" 400 '"field":"colour"'
req POST /api/runs --data '{"preset":"no-such"}'
expect "unknown preset: 400" 400 '"field":"preset"'
# A stiffness of 1e30 N/m steps at ~1e-17 s: a second of it would hold a run slot for ever.
req POST /api/runs --data '{"name":"stiff","material":{"normal_stiffness":1e30,"tangential_stiffness":1e30},"particles":[{"shape":"disc","radius":0.002,"position":[0,0]}],"stages":[{"type":"free","duration":1}]}'
expect "absurd cost: 400 names the field that drives it" 400 '"error":"the run would take about [^"]*years[^"]*","field":"material\.normal_stiffness"'
# The validity envelope (docs/validity.md): past a hard limit refused naming the field (a grain
# 20,000 times smaller than its neighbour); past a soft one run, the warning in the detail (two
# discs starting 20% of a radius inside each other).
req POST /api/runs --data '{"name":"speck","particles":[{"radius":0.002,"position":[0,0]},{"radius":1e-7,"position":[0.01,0]}],"stages":[{"type":"free","duration":0.001}]}'
expect "past the validity envelope: 400 names the field" 400 '"error":"particles\[1\]\.radius: size_ratio [^"]*","field":"particles\[1\]\.radius"'
req POST /api/runs --data '{"name":"deep","particles":[{"radius":0.002,"position":[0,0]},{"radius":0.002,"position":[0.0036,0]}],"stages":[{"type":"free","duration":0.001}]}'
expect "a warned scene runs: 201" 201
WARNED=$(json b.id)
req GET "/api/runs/$WARNED"
expect "its warnings are in the detail while queued or running" 200 '"warnings":\[\{"field":"particles\[[01]\]\.radius","limit":0\.1,"meaning":"[^"]*","quantity":"initial_overlap"'
check "the warned run completes" wait_status "$WARNED" completed 60
req GET "/api/runs/$WARNED"
expect "and once it has ended" 200 '"quantity":"initial_overlap"'
req POST /api/runs --data '{"preset":"circular-quick"}'
expect "past the particle limit: 503" 503 '"error":"this server runs at most 100 particles per run[^"]*","field":"particles"'
head -c 200000 /dev/zero | tr '\0' ' ' >"$TMP_ROOT/big.json"
req POST /api/runs --data-binary "@$TMP_ROOT/big.json"
expect "body past the limit: 413" 413 '"field":"body"'
T0=$(date +%s%N)
req POST /api/runs -H 'Expect: 100-continue' --data-binary "@$TMP_ROOT/big.json"
expect "413 before the body is sent (Expect: 100-continue)" 413 '"field":"body"'
req POST /api/runs -H 'Expect: 100-continue' --data "$TINY_SCENE"
ELAPSED_MS=$((($(date +%s%N) - T0) / 1000000))
expect "Expect: 100-continue is answered" 201
check "without curl's one-second wait (${ELAPSED_MS} ms for both)" test "$ELAPSED_MS" -lt 900
req GET /api/runs
check "no bad request stored a run" test "$(json 'b.runs.filter(r => r.name === "x" || r.preset === "no-such").length')" = 0

req GET /api/nothing
expect "unknown route: 404" 404 'no such endpoint'
req GET /api/runs/424242
expect "unknown id: 404" 404 '"error":"no run 424242"'
req GET /api/runs/abc/series
expect "malformed id: 404" 404
req PUT /api/runs
expect "wrong method: 405" 405 'PUT is not allowed'
check "405 has Allow" test "$(header Allow)" = "GET, HEAD, POST"
req DELETE /api/health
expect "405 on health" 405
req GET "/api/runs/$ID/cancel"
expect "GET on cancel: 405" 405
check "Allow: POST" test "$(header Allow)" = "POST"
req GET "/api/runs/$ID/series?format=xml"
expect "bad format: 400" 400 '"field":"format"'
req GET "/api/runs/$ID/frames?index=x"
expect "bad frame index: 400" 400 '"field":"index"'
req GET "/api/runs/$ID/frames?index=99999"
expect "no such frame: 404" 404
req GET "/api/runs/$ID/stream"
expect "stream without upgrade: 426" 426 'WebSocket'
RAW=$(exec 3<>"/dev/tcp/127.0.0.1/$PORT"; printf 'NOT HTTP AT ALL\r\n\r\n' >&3; timeout 5 cat <&3)
check "malformed HTTP: 400" grep -q '^HTTP/1.1 400' <<<"$RAW"

# ---- static files ----
req GET /
expect "index" 200 'grainlab'
check "html type" test "$(header Content-Type)" = "text/html; charset=utf-8"
req GET /js/app.js
check "js type" test "$STATUS $(header Content-Type)" = "200 text/javascript; charset=utf-8"
req GET /style.css
check "css type" test "$STATUS $(header Content-Type)" = "200 text/css; charset=utf-8"
req GET /data.json
check "json type" test "$STATUS $(header Content-Type)" = "200 application/json"
req GET /missing.js
expect "missing file: 404" 404
for evil in "/../outside/secret.txt" "/js/../../outside/secret.txt" "/%2e%2e/outside/secret.txt" \
  "/%2E%2E%2Foutside%2Fsecret.txt" "/js/%2e%2e/%2e%2e/outside/secret.txt" "/..%5Coutside%5Csecret.txt"; do
  req GET "$evil"
  if [[ $STATUS == 400 && $BODY != *secret* ]]; then pass "refused $evil"; else fail "$evil gave $STATUS: $BODY"; fi
done
req POST /index.html
expect "POST on a file: 405" 405

check "server still up after all that" bash -c "curl -sf $(BASE)/api/health >/dev/null"
stop_server TERM
check "SIGTERM stops it cleanly (exit 0)" test $? -eq 0
check "and it says so" grep -q 'stopped' "$TMP_ROOT/server.log"

# ---- the real program: grainlab serve ----
if [[ -x ${GRAINLAB_CLI:-} ]]; then
  GRAINLAB_SERVER_REAL=$GRAINLAB_SERVER
  GRAINLAB_SERVER=$TMP_ROOT/cli-serve.sh
  printf '#!/bin/sh\nexec "%s" serve "$@"\n' "$GRAINLAB_CLI" >"$GRAINLAB_SERVER"
  chmod +x "$GRAINLAB_SERVER"
  start_server "$TMP_ROOT/cli.log" "$TMP_ROOT/cli/grainlab.db" --web "$WEB"
  req GET /api/health
  expect "grainlab serve answers" 200 '"status":"ok"'
  stop_server INT
  check "grainlab serve stops on SIGINT (exit 0)" test $? -eq 0
  GRAINLAB_SERVER=$GRAINLAB_SERVER_REAL
fi

finish

#!/usr/bin/env bash
# Who may start and delete runs (docs/security.md): each attack as curl sends it to the real
# server, and the requests that must still work. Every request goes to 127.0.0.1, also when
# the server listens on 0.0.0.0 (which is how a server reachable from other machines is
# told apart from a loopback one).
source "$(dirname "$0")/lib.sh"
EVIL=http://evil.example
WS_UPGRADE=(-H 'Connection: Upgrade' -H 'Upgrade: websocket' -H 'Sec-WebSocket-Version: 13'
            -H 'Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==')
run_count() { req GET /api/runs; json b.runs.length; }
# upgrade PATH [curl args...]: the status of a WebSocket upgrade (the frames that follow are dropped).
upgrade() {
  local path=$1; shift
  STATUS=$(curl -s --max-time 2 -o /dev/null -w '%{http_code}' "${WS_UPGRADE[@]}" "$@" "$(BASE)$path")
  BODY=
}

# ---- loopback, no token: what any web page the user has open could send ----
start_server "$TMP_ROOT/loopback.log" "$TMP_ROOT/loopback.db"
req POST /api/runs -H "Origin: $EVIL" -H 'Content-Type: text/plain' -d "$TINY_SCENE"
check "a text/plain POST from a foreign Origin is refused with 403 or 415 (got $STATUS)" test "$STATUS" = 403 -o "$STATUS" = 415
req POST /api/runs -H 'Content-Type: application/x-www-form-urlencoded' -d "$TINY_SCENE"
expect "a form-encoded POST (an HTML form) is refused with 415" 415
req POST /api/runs -H 'Content-Type: text/plain' -d "$TINY_SCENE"
expect "a text/plain POST without Origin is refused with 415" 415
check "...and none of them started a run" test "$(run_count)" = 0

req GET /api/runs -H 'Host: evil.example:8080'
check "a foreign Host (DNS rebinding) is refused with 403 or 421 (got $STATUS)" test "$STATUS" = 421 -o "$STATUS" = 403
req POST /api/runs -H 'Host: evil.example' -H "Origin: $EVIL" -H 'Content-Type: application/json' -d "$TINY_SCENE"
check "a POST under a rebound name is refused (got $STATUS)" test "$STATUS" = 421 -o "$STATUS" = 403
req GET /api/health -H 'Host: localhost'
expect "GET /api/health with Host: localhost (the container's probe)" 200 '"status":"ok"'

req POST /api/runs -H "Origin: $(BASE)" -H 'Content-Type: application/json' -d "$LONG_SCENE"
expect "the dashboard's own POST (its Origin, JSON)" 201
id=$(json b.id)
req DELETE "/api/runs/$id" -H "Origin: $EVIL"
expect "a DELETE from a foreign Origin is refused with 403" 403
req DELETE "/api/runs/$id" -H 'Host: evil.example' -H "Origin: $EVIL"
check "a DELETE under a rebound name is refused (got $STATUS)" test "$STATUS" = 421 -o "$STATUS" = 403
req GET "/api/runs/$id"
expect "...and the run is still there" 200

# Cross-site WebSocket hijacking: a page elsewhere opening the live stream (of a run of its
# own, so this check does not depend on the DELETE above).
req POST /api/runs -d "$LONG_SCENE"
id=$(json b.id)
upgrade "/api/runs/$id/stream" -H "Origin: $EVIL"
expect "a WebSocket upgrade from a foreign Origin is refused with 403" 403
upgrade "/api/runs/$id/stream" -H "Origin: $(BASE)"
expect "...from the server's own page it is accepted" 101
req POST "/api/runs/$id/cancel" -H "Origin: $(BASE)"
expect "the dashboard's own cancel (no body)" 202 '"cancel_requested":true'
stop_server

# ---- listening on every address: a token is required, made at start-up when none is given ----
start_server "$TMP_ROOT/generated.log" "$TMP_ROOT/generated.db" --host 0.0.0.0 --web "$GRAINLAB_WEB"
req GET /api/runs
expect "no token on a non-loopback bind is refused with 401" 401
check "...saying nothing more" test "$BODY" = '{"error":"a token is required"}'
check "exactly one login URL line on stderr" test "$(grep -c 'login URL' "$TMP_ROOT/generated.log")" = 1
url=$(grep -o 'grainlab serve: login URL: http://127.0.0.1:[0-9]*/?token=[0-9a-f]*$' "$TMP_ROOT/generated.log")
check "...of the agreed form, naming 127.0.0.1 and the port" test -n "$url"
made=${url##*token=}
check "...with a 64-digit random token" test "${#made}" = 64
req GET /api/runs -H "Authorization: Bearer $made"
expect "the generated token lets a client in" 200
req GET /api/health
expect "GET /api/health needs no token" 200
req GET /
expect "the dashboard's page needs no token (it shows the login form)" 200
stop_server

# ---- tokens from the environment: a full one and a read-only one ----
FULL=full-token-for-the-security-test-0001
READ=read-only-token-for-the-security-test
GRAINLAB_TOKEN=$FULL GRAINLAB_READ_ONLY_TOKEN=$READ start_server "$TMP_ROOT/tokens.log" "$TMP_ROOT/tokens.db" --host 0.0.0.0
req POST /api/runs -H "Authorization: Bearer $FULL" -d "$LONG_SCENE"
expect "the full token starts a run" 201
id=$(json b.id)
req GET /api/runs -H "Authorization: Bearer $READ"
expect "the read-only token may GET" 200 "\"id\":$id"
upgrade "/api/runs/$id/stream" -H "Authorization: Bearer $READ"
expect "...and watch the live stream" 101
req POST /api/runs -H "Authorization: Bearer $READ" -d "$TINY_SCENE"
expect "the read-only token may not POST" 403
req POST "/api/runs/$id/cancel" -H "Authorization: Bearer $READ"
expect "...nor cancel" 403
req DELETE "/api/runs/$id" -H "Authorization: Bearer $READ"
expect "...nor DELETE" 403
req GET "/api/runs/$id" -H "Authorization: Bearer $FULL"
expect "...and the run is untouched" 200 '"status":"(queued|running)"'

# The dashboard's login: the token for a cookie, which then stands for it.
req POST /api/session -H "Authorization: Bearer $FULL"
expect "POST /api/session with the token" 204
cookie=$(header Set-Cookie)
check "...sets an HttpOnly, SameSite=Strict cookie for this port" \
  grep -q "^grainlab_token_$PORT=$FULL; Path=/; HttpOnly; SameSite=Strict$" <<<"$cookie"
req DELETE "/api/runs/$id" -H "Cookie: ${cookie%%;*}"
expect "the cookie lets the dashboard delete" 204

# Guessing: 10 wrong tokens in 60 s, then 429 for the rest of the window, right token or not.
for k in $(seq 10); do req GET /api/runs -H "Authorization: Bearer wrong-guess-number-$k"; done
expect "the 10th wrong token is still a 401" 401
req GET /api/runs -H "Authorization: Bearer $FULL"
expect "the 11th request from that address gets 429" 429
check "...with Retry-After" test -n "$(header Retry-After)"
req GET /api/health
expect "...while health still answers" 200
stop_server
check "no token is written to the log but the login URL" \
  test "$(grep -c -e "$FULL" -e "$READ" "$TMP_ROOT/tokens.log")" = 1
check "no token is written to the database" bash -c "! grep -a -q -r -e '$FULL' -e '$READ' '$TMP_ROOT'/tokens.db*"

# ---- importing a sweep: the server's folders cannot be probed ----
start_server "$TMP_ROOT/noimport.log" "$TMP_ROOT/noimport.db"
req POST /api/sweeps/import -d '{"dir": "/etc"}'
etc="$STATUS $BODY"
req POST /api/sweeps/import -d '{"dir": "/no/such/folder/anywhere"}'
check "without --import-root, an existing and a missing folder get the same answer ($etc)" test "$etc" = "$STATUS $BODY"
check "...a refusal (403 or 404)" test "$STATUS" = 403 -o "$STATUS" = 404
stop_server

mkdir -p "$TMP_ROOT/root/inside"
ln -s /etc "$TMP_ROOT/root/escape"
start_server "$TMP_ROOT/import.log" "$TMP_ROOT/import.db" --import-root "$TMP_ROOT/root"
answers=()
for dir in /etc /no/such/folder ../../.. escape "$TMP_ROOT"; do
  req POST /api/sweeps/import -d "{\"dir\": \"$dir\"}"
  answers+=("$STATUS $BODY")
done
check "outside the root: 403 (${answers[0]})" test "${answers[0]%% *}" = 403
same=1
for a in "${answers[@]}"; do [[ $a == "${answers[0]}" ]] || same=0; done
check "...the same answer for every path outside, existing, missing, via .. or a link" test "$same" = 1
req POST /api/sweeps/import -d '{"dir": "inside"}'
expect "inside the root a folder is read (and is no sweep)" 400 'not a sweep folder'
stop_server
finish

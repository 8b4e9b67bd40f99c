# Shared by the server's bash tests: start a server on a free loopback port with its own
# database, make requests with curl, count checks. Source it; set GRAINLAB_SERVER first.
set -uo pipefail

PASSED=0
FAILED=0
SERVER_PID=
PORT=
TMP_ROOT=${GRAINLAB_TEST_TMP:-/tmp}/$(basename "$0" .sh)-$$
mkdir -p "$TMP_ROOT"

pass() { PASSED=$((PASSED + 1)); echo "ok   - $*"; }
fail() { FAILED=$((FAILED + 1)); echo "FAIL - $*"; }
check() {  # check DESCRIPTION COMMAND...: passes if the command succeeds
  local what=$1; shift
  if "$@"; then pass "$what"; else fail "$what"; fi
}

# start_server LOG DB [options...]: starts the server and waits (at most 20 s) for its port.
start_server() {
  local log=$1 db=$2; shift 2
  "$GRAINLAB_SERVER" --host 127.0.0.1 --port 0 --db "$db" "$@" >"$log" 2>&1 &
  SERVER_PID=$!
  for _ in $(seq 200); do
    PORT=$(grep -o 'listening on http://[0-9.]*:[0-9]*' "$log" 2>/dev/null | grep -o '[0-9]*$')
    [[ -n $PORT ]] && return 0
    kill -0 "$SERVER_PID" 2>/dev/null || break
    sleep 0.1
  done
  echo "server did not start:"; cat "$log"; exit 1
}

# stop_server [SIGNAL]: signals the server and waits for it; returns its exit status.
stop_server() {
  local signal=${1:-TERM} status=0
  [[ -n $SERVER_PID ]] || return 0
  kill -s "$signal" "$SERVER_PID" 2>/dev/null
  wait "$SERVER_PID" || status=$?
  SERVER_PID=
  return $status
}

cleanup() {
  [[ -n $SERVER_PID ]] && kill -9 "$SERVER_PID" 2>/dev/null
  rm -rf "$TMP_ROOT"
}
trap cleanup EXIT

BASE() { echo "http://127.0.0.1:$PORT"; }

# req METHOD PATH [curl args...]: sets STATUS, BODY and HEADERS (file).
HEADERS=$TMP_ROOT/headers
req() {
  local method=$1 path=$2; shift 2
  # HEAD through -I: with -X HEAD curl would wait for the body Content-Length announces.
  local how=(-X "$method")
  [[ $method == HEAD ]] && how=(-I)
  # The API takes bodies only as JSON (415 otherwise); curl --data says form-urlencoded.
  local arg body=0 typed=0
  for arg in "$@"; do
    [[ $arg == -d || $arg == --data* ]] && body=1
    [[ ${arg,,} == content-type:* ]] && typed=1
  done
  ((body && !typed)) && how+=(-H 'Content-Type: application/json')
  BODY=$(curl -s --max-time 30 --path-as-is "${how[@]}" -D "$HEADERS" -o /dev/stdout -w '\n%{http_code}' "$@" "$(BASE)$path")
  STATUS=${BODY##*$'\n'}
  BODY=${BODY%$'\n'*}
}

# expect DESCRIPTION STATUS [JQ-ish grep pattern]: checks the last response.
expect() {
  local what=$1 status=$2 pattern=${3:-}
  if [[ $STATUS != "$status" ]]; then
    fail "$what: status $STATUS, expected $status; body: ${BODY:0:300}"
  elif [[ -n $pattern ]] && ! grep -qE -- "$pattern" <<<"$BODY"; then
    fail "$what: body does not match /$pattern/: ${BODY:0:300}"
  else
    pass "$what"
  fi
}

header() { grep -i "^$1:" "$HEADERS" | head -1 | cut -d' ' -f2- | tr -d '\r'; }

# json EXPR: evaluates a JavaScript expression over the last body as `b` (node is there for
# the WebSocket tests anyway).
json() { node -e "const b = JSON.parse(require('fs').readFileSync(0, 'utf8')); console.log($1)" <<<"$BODY"; }

# wait_status ID STATUS [SECONDS]: polls GET /api/runs/ID.
wait_status() {
  local id=$1 want=$2 limit=${3:-60}
  for _ in $(seq $((limit * 10))); do
    req GET "/api/runs/$id"
    [[ $(json b.status) == "$want" ]] && return 0
    sleep 0.1
  done
  echo "run $id is $(json b.status), not $want"; return 1
}

finish() {
  echo "$PASSED passed, $FAILED failed"
  [[ $FAILED -eq 0 ]]
}

# A scene of one disc: quick to parse and run.
TINY_SCENE='{"name":"tiny","particles":[{"shape":"disc","radius":0.002,"position":[0,0]}],"stages":[{"type":"free","duration":0.002}],"output":{"sample_interval":0.0002}}'
# Three discs falling onto a wall for a long time: a run that is still going when we look.
LONG_SCENE='{"name":"long","particles":[{"shape":"disc","radius":0.002,"position":[0,0.003]},{"shape":"disc","radius":0.002,"position":[0.0041,0.003]},{"shape":"disc","radius":0.002,"position":[0.002,0.008]}],"walls":[{"point":[0,0],"normal":[0,1]}],"gravity":[0,-9.81],"stages":[{"type":"free","duration":1000}],"output":{"sample_interval":0.05}}'

#!/usr/bin/env bash
# Server benchmark: requests per second for GET /api/runs (and /api/health, a run's series)
# with wrk, and how much 50 WebSocket watchers (one never reading) slow a run.
#
#   bench/server/bench.sh [BUILD_DIR]       (default: build)
#
# Needs wrk and node (scripts/setup installs both) and a build with the test server
# (BUILD_DIR/tests/server/grainlab_test_server). Loopback only; stops by itself.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
SERVER=$BUILD/tests/server/grainlab_test_server
DURATION=${GRAINLAB_BENCH_SECONDS:-10}
[[ -x $SERVER ]] || { echo "no $SERVER: build the target grainlab_test_server first" >&2; exit 1; }
command -v wrk >/dev/null || { echo "wrk is missing (apt-get install wrk)" >&2; exit 1; }

TMP=$(mktemp -d)
PID=
trap '[[ -n $PID ]] && kill "$PID" 2>/dev/null; rm -rf "$TMP"' EXIT

"$SERVER" --port 0 --db "$TMP/bench.db" --web web --max-concurrent 2 >"$TMP/server.log" 2>&1 &
PID=$!
for _ in $(seq 100); do
  PORT=$(grep -o 'listening on http://127.0.0.1:[0-9]*' "$TMP/server.log" | grep -o '[0-9]*$' || true)
  [[ -n $PORT ]] && break
  sleep 0.1
done
BASE=http://127.0.0.1:$PORT

# Something to list: 20 finished runs of a small scene.
SCENE='{"name":"bench","particles":[{"shape":"disc","radius":0.002,"position":[0,0]}],"stages":[{"type":"free","duration":0.002}],"output":{"sample_interval":0.0002}}'
for _ in $(seq 20); do curl -sf -X POST -H "Content-Type: application/json" "$BASE/api/runs" --data "$SCENE" >/dev/null; done
for _ in $(seq 200); do
  curl -s "$BASE/api/health" | grep -q '"queued":0,"running":0' && break
  sleep 0.1
done

rate() {  # rate PATH: requests/s from wrk
  wrk -t2 -c32 -d"${DURATION}s" --latency "$BASE$1" >"$TMP/wrk.txt"
  local rps p50 p99
  rps=$(awk '/Requests\/sec/ {print $2}' "$TMP/wrk.txt")
  p50=$(awk '$1 == "50%" {print $2}' "$TMP/wrk.txt")
  p99=$(awk '$1 == "99%" {print $2}' "$TMP/wrk.txt")
  printf '%-28s %10s req/s   p50 %8s   p99 %8s\n' "GET $1" "$rps" "$p50" "$p99"
  grep -q 'Non-2xx' "$TMP/wrk.txt" && { echo "  (non-2xx answers!)"; grep 'Non-2xx' "$TMP/wrk.txt"; } || true
}
echo "== wrk: 2 threads, 32 connections, ${DURATION} s each, 20 runs stored =="
rate /api/runs
rate /api/health
rate /api/runs/1
rate /api/runs/1/series
kill "$PID"; wait "$PID" || true; PID=

echo "== run slowdown with 50 WebSocket watchers (one never reading) =="
GRAINLAB_SERVER=$SERVER GRAINLAB_WEB=$PWD/web GRAINLAB_TEST_TMP=$TMP \
  GRAINLAB_SLOW_REPEATS=${GRAINLAB_BENCH_REPEATS:-5} node tests/server/slow_clients_test.mjs | grep '^#'

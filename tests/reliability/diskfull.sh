#!/usr/bin/env bash
# Disk full: small tmpfs mounts (root only) under
#  (a) `grainlab run --vtk`, whose outputs fill the disk: a clear error naming the file and
#      "No space left on device", a nonzero exit, and no torn file (summary.json, if there is
#      one, is valid JSON with status failed; series.csv holds whole rows; no *.tmp left);
#  (b) a run whose checkpoint cannot be written (the disk filled under it, then SIGTERM): it
#      says the checkpoint failed, the checkpoint before it stays readable, and `grainlab
#      resume` on a copy with space completes with the same series.csv as a run never stopped;
#  (c) `grainlab serve` with its database on a tmpfs with 640 KiB left once it has started: the
#      run that fills it ends failed with the database's reason, durably (after a restart too),
#      and the database stays intact.
# Prints `ok`/`FAIL` checks and `figure {json}` lines (tests/reliability/common.mjs). Exit 77
# (skipped) when not root; as root, a mount that is refused fails unless
# GRAINLAB_RELIABILITY_NO_TMPFS=1 (a container without CAP_SYS_ADMIN).
set -uo pipefail
CLI=${GRAINLAB_CLI:-build/grainlab}
CLI=$(realpath "$CLI")
mkdir -p "${GRAINLAB_TEST_TMP:-/tmp}"
ROOT=$(mktemp -d "${GRAINLAB_TEST_TMP:-/tmp}/diskfull.XXXXXX")
PASSED=0
FAILED=0
MOUNTS=()
SERVER_PID=

pass() { PASSED=$((PASSED + 1)); echo "ok   - $*"; }
fail() { FAILED=$((FAILED + 1)); echo "FAIL - $*"; }
check() { local what=$1; shift; if "$@"; then pass "$what"; else fail "$what"; fi; }
# figure SECTION NAME VALUE [UNIT] [TARGET] [OK: true|false|null]
figure() {
  node -e 'const [s, n, v, u, t, ok] = process.argv.slice(1);
           const num = v !== "" && !isNaN(Number(v)) ? Number(v) : v;
           console.log("figure " + JSON.stringify({ section: s, name: n, value: num, unit: u ?? "", target: t ?? "", ok: ok === undefined || ok === "null" ? null : ok === "true" }))' \
    "$1" "$2" "$3" "${4:-}" "${5:-}" "${6:-null}"
}
json() { node -e "const b = JSON.parse(require('fs').readFileSync(0, 'utf8')); const r = ($1); console.log(typeof r === 'string' ? r : JSON.stringify(r))"; }
cleanup() {
  [[ -n $SERVER_PID ]] && kill -9 "$SERVER_PID" 2>/dev/null
  for m in "${MOUNTS[@]}"; do umount "$m" 2>/dev/null; done
  rm -rf "$ROOT"
}
trap cleanup EXIT
finish() { echo "$PASSED passed, $FAILED failed"; exit $((FAILED > 0)); }

S='disk full'
if [[ $(id -u) != 0 ]]; then
  echo "# not run: mounting a tmpfs needs root"
  figure "$S" 'not run' 'mounting a tmpfs needs root'
  exit 77
fi
# mount_tmpfs DIR SIZE
mount_tmpfs() {
  mkdir -p "$1"
  local why
  if ! why=$(mount -t tmpfs -o "size=$2" tmpfs "$1" 2>&1); then
    echo "# not run: mount -t tmpfs refused: $why"
    figure "$S" 'not run' "mount -t tmpfs refused: $why"
    if [[ ${GRAINLAB_RELIABILITY_NO_TMPFS:-0} == 1 ]]; then exit 77; fi
    fail "root, but a tmpfs cannot be mounted (set GRAINLAB_RELIABILITY_NO_TMPFS=1 to skip)"
    finish
  fi
  MOUNTS+=("$1")
}
# fill DIR BYTES_LEFT: takes the tmpfs's free space down to about BYTES_LEFT.
fill() {
  local avail
  avail=$(df --output=avail -B1 "$1" | tail -1)
  fallocate -l $((avail - $2)) "$1/ballast"
}
# Every line of a CSV has the header's number of cells (no torn last row).
whole_rows() { awk -F, 'NR == 1 { n = NF } NF != n { bad = 1 } END { exit bad }' "$1"; }

# The long circular-quick of the load test: about 10 s, checkpoints every 0.3 s.
"$CLI" preset circular-quick | node -e '
  const s = JSON.parse(require("fs").readFileSync(0, "utf8"));
  s.name = "diskfull"; s.stages.find((t) => t.type === "biaxial").strain_rate = 0.1;
  s.output.checkpoint_every_s = 0.3;
  console.log(JSON.stringify(s));' >"$ROOT/long.json"
# (b)'s run: the periodic checkpoint must be what meets the full disk, so the run's other
# large writes are off (the roses' rows and the stages' ends; (a) fills the disk with outputs).
node -e '
  const s = JSON.parse(require("fs").readFileSync(0, "utf8"));
  s.output.histograms = false; s.output.stage_checkpoints = false;
  console.log(JSON.stringify(s));' <"$ROOT/long.json" >"$ROOT/long-checkpoints.json"

# ---- (a) outputs fill the disk
A=$ROOT/a
mount_tmpfs "$A" 2m
"$CLI" run --preset circular-quick --vtk --out "$A/run" >"$ROOT/a.out" 2>"$ROOT/a.err"
code=$?
error=$(grep '^error:' "$ROOT/a.err" | tail -1)
echo "# $error"
figure "$S" '(a) grainlab run --vtk on a 2 MiB tmpfs: exit status' "$code" '' 'nonzero' "$([[ $code != 0 ]] && echo true || echo false)"
figure "$S" '(a) its last words' "${error//$ROOT/TMP}"
check "(a) the run exits nonzero ($code)" test "$code" -ne 0
check "(a) its error names a file on the full disk and 'No space left on device'" \
  grep -q "^error: .*cannot write $A/run/[^ ]*: No space left on device" "$ROOT/a.err"
if [[ -f $A/run/summary.json ]]; then
  status=$(json 'b.status' <"$A/run/summary.json" 2>/dev/null)
  check "(a) summary.json is valid JSON with status failed ($status)" test "$status" = failed
  check "(a) and its error says why" grep -q 'No space left on device' "$A/run/summary.json"
  check "(a) and has no NaN" bash -c "! grep -qi 'nan' '$A/run/summary.json'"
  figure "$S" '(a) summary.json' "status $status, error names the file" '' 'valid, failed' "$([[ $status == failed ]] && echo true || echo false)"
else
  pass "(a) no summary.json (the run left none)"
  figure "$S" '(a) summary.json' 'none written' '' 'valid, failed, or none' true
fi
check "(a) series.csv holds whole rows only" whole_rows "$A/run/series.csv"
leftover=$(find "$A/run" -name '*.tmp' | wc -l)
check "(a) no temporary file left behind ($leftover)" test "$leftover" -eq 0
figure "$S" '(a) series.csv rows, all whole' "$(($(wc -l <"$A/run/series.csv") - 1))"

# ---- (b) a checkpoint that cannot be written
B=$ROOT/b
mount_tmpfs "$B" 2m
# The same run, never stopped, on a disk with space: what the resumed one must end as.
"$CLI" run "$ROOT/long-checkpoints.json" --out "$ROOT/reference" >/dev/null 2>"$ROOT/reference.err" &
REFERENCE_PID=$!
"$CLI" run "$ROOT/long-checkpoints.json" --out "$B/run" >"$ROOT/b.out" 2>"$ROOT/b.err" &
RUN_PID=$!
for _ in $(seq 300); do [[ -f $B/run/checkpoint.bin.previous ]] && break; sleep 0.1; done
check "(b) the run has written two checkpoints" test -f "$B/run/checkpoint.bin.previous"
fill "$B" 16384
sleep 2  # several checkpoints are attempted (every 0.3 s) and refused
kill -TERM "$RUN_PID"
wait "$RUN_PID"
code=$?
grep -v '^\[' "$ROOT/b.err" | sed 's/^/# /'
check "(b) the run stops with a nonzero exit ($code)" test "$code" -ne 0
check "(b) it says its checkpoint failed: No space left on device" \
  grep -q "checkpoint failed: cannot write checkpoint $B/run/checkpoint.bin.tmp: No space left on device" "$ROOT/b.err"
check "(b) and that its last checkpoint is kept for grainlab resume" grep -q 'grainlab resume' "$ROOT/b.err"
check "(b) no temporary checkpoint left behind" test ! -e "$B/run/checkpoint.bin.tmp"
said=$(grep -o 'checkpoint failed: [^;]*' "$ROOT/b.err" | head -1)
figure "$S" '(b) run whose checkpoint cannot be written: exit status, then' "$code: ${said//$ROOT/TMP}"
cp -a "$B/run" "$ROOT/b-copy"
"$CLI" resume "$ROOT/b-copy" >/dev/null 2>"$ROOT/b-resume.err"
rcode=$?
rstatus=$(json 'b.status' <"$ROOT/b-copy/summary.json" 2>/dev/null)
check "(b) grainlab resume on a copy with space completes (exit $rcode, $rstatus)" test "$rcode" -eq 0 -a "$rstatus" = completed
wait "$REFERENCE_PID"
same=no
cmp -s "$ROOT/b-copy/series.csv" "$ROOT/reference/series.csv" && same=yes
check "(b) its series.csv is byte for byte the uninterrupted run's" test "$same" = yes
figure "$S" '(b) resumed from the kept checkpoint on a copy: exit, status' "$rcode, $rstatus" '' '0, completed' "$([[ $rcode == 0 && $rstatus == completed ]] && echo true || echo false)"
figure "$S" '(b) resumed series.csv identical to the run never stopped' "$same" '' 'yes' "$([[ $same == yes ]] && echo true || echo false)"

# ---- (c) the server's database fills the disk
C=$ROOT/c
mount_tmpfs "$C" 4m
start_server() {
  "$CLI" serve --host 127.0.0.1 --port 0 --db "$C/data/grainlab.db" >"$1" 2>&1 &
  SERVER_PID=$!
  PORT=
  for _ in $(seq 200); do
    PORT=$(grep -o 'listening on http://127.0.0.1:[0-9]*' "$1" 2>/dev/null | grep -o '[0-9]*$')
    [[ -n $PORT ]] && return 0
    sleep 0.1
  done
  fail "(c) the server did not start: $(cat "$1")"
  finish
}
stop_server() { kill -TERM "$SERVER_PID"; wait "$SERVER_PID"; local c=$?; SERVER_PID=; return $c; }
start_server "$ROOT/c1.log"
fill "$C" $((640 << 10))  # what the run may fill: 640 KiB (and the server's reserve)
id=$(curl -s -XPOST -H "Content-Type: application/json" "http://127.0.0.1:$PORT/api/runs" --data @"$ROOT/long.json" | json 'b.id')
t0=$(date +%s.%N)
run=
for _ in $(seq 1200); do
  run=$(curl -s "http://127.0.0.1:$PORT/api/runs/$id")
  status=$(json 'b.status' <<<"$run")
  [[ $status =~ ^(completed|failed|cancelled|interrupted)$ ]] && break
  sleep 0.1
done
seconds=$(node -e "console.log(($(date +%s.%N) - $t0).toFixed(1))")
reason=$(json 'b.error' <<<"$run")
echo "# run $id: $status after $seconds s: $reason"
sed 's/^/# server: /' "$ROOT/c1.log"
check "(c) the run that fills the disk ends failed ($status)" test "$status" = failed
check "(c) with the database's reason" grep -q 'database or disk is full' <<<"$reason"
figure "$S" '(c) server, database on a tmpfs with 640 KiB free: the run ends' "$status after $seconds s" '' 'failed' "$([[ $status == failed ]] && echo true || echo false)"
figure "$S" '(c) its reason' "$reason"
stop_server
check "(c) the server stops cleanly" test $? -eq 0
integrity=$(sqlite3 "$C/data/grainlab.db" 'PRAGMA integrity_check' 2>&1)
stored=$(sqlite3 "$C/data/grainlab.db" "SELECT status FROM runs WHERE id = $id" 2>&1)
check "(c) the database is intact (integrity_check: $integrity)" test "$integrity" = ok
check "(c) and holds the run as failed ($stored)" test "$stored" = failed
figure "$S" '(c) sqlite3 PRAGMA integrity_check' "$integrity" '' 'ok' "$([[ $integrity == ok ]] && echo true || echo false)"
figure "$S" '(c) the run in the database after the server stopped' "$stored" '' 'failed' "$([[ $stored == failed ]] && echo true || echo false)"
# On the disk still full, a restart is refused with the reason (its first write, marking
# runs left running as interrupted, needs space); with space freed it starts and still
# tells the run failed.
"$CLI" serve --host 127.0.0.1 --port 0 --db "$C/data/grainlab.db" >"$ROOT/c2.log" 2>&1 &
restart=$!
for _ in $(seq 50); do kill -0 "$restart" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$restart" 2>/dev/null; then
  kill -9 "$restart"
  said='it started'
else
  said=$(head -1 "$ROOT/c2.log")
fi
echo "# restart on the full disk: $said"
figure "$S" '(c) a restart with the disk still full' "${said:0:200}"
rm "$C/ballast"
start_server "$ROOT/c3.log"
after=$(curl -s "http://127.0.0.1:$PORT/api/runs/$id" | json 'b.status')
check "(c) after space is freed and a restart, the API still says failed ($after)" test "$after" = failed
figure "$S" '(c) after space is freed, a restart shows the run' "$after" '' 'failed' "$([[ $after == failed ]] && echo true || echo false)"
stop_server
finish

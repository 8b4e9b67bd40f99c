#!/usr/bin/env bash
# Bad input: each libFuzzer target (tests/server/fuzz) for SECONDS, from its seed corpus:
# inputs tried, and crashes found (target 0; libFuzzer stops a target at its first, which is
# kept as ARTIFACTS/<target>-crash-*). Usage: fuzz.sh FUZZ_BUILD_DIR SECONDS ARTIFACTS
# Prints `ok`/`FAIL` checks and `figure {json}` lines (tests/reliability/common.mjs).
set -uo pipefail
BIN=$1
SECONDS_EACH=$2
ARTIFACTS=$3
SOURCE=$(cd "$(dirname "$0")/../server/fuzz" && pwd)
mkdir -p "${GRAINLAB_TEST_TMP:-/tmp}"
WORK=$(mktemp -d "${GRAINLAB_TEST_TMP:-/tmp}/fuzz.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
mkdir -p "$ARTIFACTS"
FAILED=0

figure() {
  node -e 'const [s, n, v, u, t, ok] = process.argv.slice(1);
           const num = v !== "" && !isNaN(Number(v)) ? Number(v) : v;
           console.log("figure " + JSON.stringify({ section: s, name: n, value: num, unit: u ?? "", target: t ?? "", ok: ok === undefined || ok === "null" ? null : ok === "true" }))' \
    "$1" "$2" "$3" "${4:-}" "${5:-}" "${6:-null}"
}

declare -A WHAT=(
  [scene]='scene JSON (POST /api/runs, grainlab run)'
  [http]='HTTP requests to the server'
  [sweep]='sweep spec (grainlab sweep)'
  [checkpoint]='checkpoint files (grainlab resume)'
)
for target in scene http sweep checkpoint; do
  binary=$BIN/fuzz_$target
  if [[ ! -x $binary ]]; then
    echo "FAIL - fuzz_$target is not built in $BIN"
    FAILED=$((FAILED + 1))
    continue
  fi
  corpus=$WORK/$target
  mkdir -p "$corpus"
  # Checkpoint seeds are written afresh, in this build's format, beside the stored ones.
  if [[ $target == checkpoint ]]; then
    GRAINLAB_FUZZ_MAKE_SEEDS=$corpus ASAN_OPTIONS=detect_leaks=0 "$binary" >/dev/null 2>&1
  fi
  before=$(find "$ARTIFACTS" -name "$target-*" | wc -l)
  ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 "$binary" -max_total_time="$SECONDS_EACH" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$ARTIFACTS/$target-" \
    "$corpus" "$SOURCE/corpus/$target" >"$WORK/$target.log" 2>&1
  code=$?
  runs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$WORK/$target.log" | tail -1 | grep -o '[0-9]*$')
  crashes=$(($(find "$ARTIFACTS" -name "$target-*" | wc -l) - before))
  ((code != 0 && crashes == 0)) && crashes=1
  echo "# fuzz_$target: exit $code, ${runs:-?} inputs in $SECONDS_EACH s, $crashes crashes"
  ((code != 0)) && grep -E 'ERROR|SUMMARY|runtime error|threw|Test unit written' "$WORK/$target.log" | head -5 | sed 's/^/#   /'
  figure fuzz "fuzz_$target: ${WHAT[$target]}: inputs tried in ${SECONDS_EACH} s" "${runs:-0}"
  figure fuzz "fuzz_$target: crashes found" "$crashes" '' '0' "$([[ $crashes == 0 ]] && echo true || echo false)"
  if ((crashes == 0)); then echo "ok   - fuzz_$target: no crash in ${runs:-0} inputs"; else echo "FAIL - fuzz_$target crashed (see $ARTIFACTS)"; FAILED=$((FAILED + 1)); fi
done
exit $((FAILED > 0))

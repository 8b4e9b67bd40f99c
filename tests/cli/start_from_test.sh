#!/usr/bin/env bash
# `grainlab run --from DIR[:STAGE]`: a run of circular-quick keeps its stages' ends; the same
# preset run from its end of consolidation writes its series from there on byte for byte; a bad
# --from is refused with one line naming start_from's field, exit 2, and nothing written.
set -euo pipefail
grainlab=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$grainlab" preset circular-quick | python3 -c '
import json, sys
s = json.load(sys.stdin)
s["stages"][-1]["target_axial_strain"] = 0.02
json.dump(s, open(sys.argv[1], "w"))' "$tmp/scene.json"
"$grainlab" run "$tmp/scene.json" --out "$tmp/a" 2> "$tmp/a.err" || { cat "$tmp/a.err"; fail "run a"; }
[[ -s $tmp/a/stages/consolidation.checkpoint ]] || fail "no stage checkpoint of consolidation"
python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); assert s["stage_checkpoints"]["written"] == 3, s' \
  "$tmp/a/summary.json" || fail "summary.json does not count the stage checkpoints"

"$grainlab" run "$tmp/scene.json" --from "$tmp/a:consolidation" --out "$tmp/b" 2> "$tmp/b.err" \
  || { cat "$tmp/b.err"; fail "run --from"; }
python3 - "$tmp/a/series.csv" "$tmp/b/series.csv" <<'PY' || fail "the branch's series differs from a's"
import sys
a = open(sys.argv[1], "rb").read().split(b"\n")
b = open(sys.argv[2], "rb").read()
last = max(k for k, line in enumerate(a) if b",consolidation," in line)
assert b == a[0] + b"\n" + b"\n".join(a[last:]), "not byte for byte"
PY
# Without a stage, the preparation's end: the stage before the first shearing stage.
"$grainlab" run "$tmp/scene.json" --from "$tmp/a" --out "$tmp/c" 2> /dev/null || fail "run --from DIR"
cmp -s "$tmp/b/series.csv" "$tmp/c/series.csv" || fail "--from DIR is not --from DIR:consolidation"

refused() {  # field, then the arguments of grainlab run
  local field=$1; shift
  local status=0
  "$grainlab" run "$@" --out "$tmp/refused" 2> "$tmp/err.txt" > /dev/null || status=$?
  [[ $status == 2 ]] || fail "exit $status, not 2, for $*: $(cat "$tmp/err.txt")"
  [[ $(wc -l < "$tmp/err.txt") == 1 ]] || fail "not one line: $(cat "$tmp/err.txt")"
  grep -q "^error: $field: " "$tmp/err.txt" || fail "does not name $field: $(cat "$tmp/err.txt")"
  [[ ! -e $tmp/refused ]] || fail "wrote $tmp/refused"
}
refused start_from.run "$tmp/scene.json" --from "$tmp/nowhere:consolidation"
refused start_from.run "$tmp/scene.json" --from "$tmp/a:settling"
cp "$tmp/a/stages/consolidation.checkpoint" "$tmp/bad.checkpoint"
printf 'X' | dd of="$tmp/bad.checkpoint" bs=1 seek=200 conv=notrunc 2> /dev/null
python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); s["start_from"]={"checkpoint": sys.argv[2]}; json.dump(s, open(sys.argv[3], "w"))' \
  "$tmp/scene.json" "$tmp/bad.checkpoint" "$tmp/corrupt.json"
refused start_from.checkpoint "$tmp/corrupt.json"
python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); s["solver"]["engine"]="box2d"; json.dump(s, open(sys.argv[2], "w"))' \
  "$tmp/scene.json" "$tmp/box2d.json"
refused start_from.run "$tmp/box2d.json" --from "$tmp/a:consolidation"
python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); s["assembly"]["specimen_diameter"]=0.05; json.dump(s, open(sys.argv[2], "w"))' \
  "$tmp/scene.json" "$tmp/smaller.json"
refused start_from.run "$tmp/smaller.json" --from "$tmp/a:consolidation"
echo "start_from: all checks passed"

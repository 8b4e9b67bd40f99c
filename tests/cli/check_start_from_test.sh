#!/usr/bin/env bash
# `grainlab check` of a scene with start_from reads it as `grainlab run` does: the specimen is
# loaded and only the stages run on it are counted in the cost, and a start_from that is
# missing, corrupt or does not fit the scene is refused with the very line grainlab run gives
# (one line naming start_from's field, exit 2). One short run of circular-quick prepares the
# specimen.
set -euo pipefail
grainlab=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# scene NAME PYTHON: the prepared run's scene changed by a Python statement on `s`.
scene() {
  python3 -c "import json, sys; s = json.load(open(sys.argv[1])); $2; json.dump(s, open(sys.argv[2], 'w'))" \
    "$tmp/scene.json" "$tmp/$1.json"
}
"$grainlab" preset circular-quick | python3 -c '
import json, sys
s = json.load(sys.stdin)
s["stages"][-1]["target_axial_strain"] = 0.02
json.dump(s, open(sys.argv[1], "w"))' "$tmp/scene.json"
"$grainlab" run "$tmp/scene.json" --out "$tmp/a" 2> "$tmp/a.err" || { cat "$tmp/a.err"; fail "run a"; }

# ---- the cost counts the run's own stages ----
"$grainlab" check "$tmp/scene.json" > "$tmp/whole.txt" || fail "check of the whole scene: $(cat "$tmp/whole.txt")"
scene branch "s['start_from'] = {'run': '$tmp/a', 'stage': 'consolidation'}"
"$grainlab" check "$tmp/branch.json" > "$tmp/branch.txt" 2> "$tmp/branch.err" \
  || fail "check of the branch: $(cat "$tmp/branch.err")"
cat "$tmp/whole.txt" "$tmp/branch.txt"
grep -q "stages that end on a criterion add more" "$tmp/whole.txt" \
  || fail "the whole scene's cost should count its compaction and consolidation as bounded stages"
grep -q "1 of them run on the prepared specimen (the end of stage 'consolidation')" "$tmp/branch.txt" \
  || fail "check does not say the branch runs one stage on the specimen"
! grep -q "stages that end on a criterion" "$tmp/branch.txt" \
  || fail "the branch's cost still counts the compaction and consolidation the specimen stands in for"
# The shearing is the certain part of both: the same lower bound in steps.
bound() { grep -o 'lower bound [0-9.e+]* steps' "$1"; }
[[ $(bound "$tmp/whole.txt") == "$(bound "$tmp/branch.txt")" ]] \
  || fail "the shearing's lower bound differs: $(bound "$tmp/whole.txt") against $(bound "$tmp/branch.txt")"

# ---- a bad start_from: the line grainlab run gives, exit 2 ----
refused() {  # FIELD SCENE
  local field=$1 json=$2 status=0
  "$grainlab" check "$json" > /dev/null 2> "$tmp/check.err" || status=$?
  [[ $status == 2 ]] || fail "check exit $status, not 2, for $(basename "$json"): $(cat "$tmp/check.err")"
  [[ $(wc -l < "$tmp/check.err") == 1 ]] || fail "check: not one line: $(cat "$tmp/check.err")"
  grep -q "^error: $field: " "$tmp/check.err" || fail "check does not name $field: $(cat "$tmp/check.err")"
  status=0
  "$grainlab" run "$json" --out "$tmp/refused" 2> "$tmp/run.err" > /dev/null || status=$?
  [[ $status == 2 ]] || fail "run exit $status for $(basename "$json")"
  cmp -s "$tmp/check.err" "$tmp/run.err" || fail "check says $(cat "$tmp/check.err"), run says $(cat "$tmp/run.err")"
  echo "refused as grainlab run refuses it: $(cat "$tmp/check.err")"
}
scene nowhere "s['start_from'] = {'run': '$tmp/nowhere', 'stage': 'consolidation'}"
refused start_from.run "$tmp/nowhere.json"
scene settling "s['start_from'] = {'run': '$tmp/a', 'stage': 'settling'}"
refused start_from.run "$tmp/settling.json"
cp "$tmp/a/stages/consolidation.checkpoint" "$tmp/bad.checkpoint"
printf 'X' | dd of="$tmp/bad.checkpoint" bs=1 seek=200 conv=notrunc 2> /dev/null
scene corrupt "s['start_from'] = {'checkpoint': '$tmp/bad.checkpoint'}"
refused start_from.checkpoint "$tmp/corrupt.json"
scene smaller "s['assembly']['specimen_diameter'] = 0.05; s['start_from'] = {'run': '$tmp/a'}"
refused start_from.run "$tmp/smaller.json"
scene box2d "s['solver']['engine'] = 'box2d'; s['start_from'] = {'run': '$tmp/a'}"
refused start_from.run "$tmp/box2d.json"
scene last "s['start_from'] = {'run': '$tmp/a', 'stage': 'shearing'}"
refused start_from.stage "$tmp/last.json"
# A stored run of grainlab serve: only that server can resolve it.
scene stored "s['start_from'] = {'run_id': 7, 'stage': 'consolidation'}"
refused start_from.run_id "$tmp/stored.json"
echo "check start_from: all checks passed"

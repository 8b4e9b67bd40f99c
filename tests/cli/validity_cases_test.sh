#!/usr/bin/env bash
# Six scenes that used to "complete" with results that mean nothing, or fail with an internal
# reason, are refused naming their field (exit 2, nothing written) or warned on the CLI's first
# lines; and a biaxial stage sheared faster than the lateral servo can follow is warned before
# its first step and records, during the run, the step where sigma11 left its target band.
set -euo pipefail
grainlab=$1
tmp=$(mktemp -d)
trap 'kill "${runner:-}" 2>/dev/null || true; rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# scene NAME PRESET PYTHON-EDIT: the preset with one field changed, as $tmp/NAME.json.
scene() {
  "$grainlab" preset "$2" | python3 -c "import json,sys; s=json.load(sys.stdin); $3; json.dump(s, open('$tmp/$1.json','w'))"
}

# refused NAME FIELD: check and run both exit 2 naming FIELD first; run writes no summary.json.
refused() {
  local code=0
  "$grainlab" check "$tmp/$1.json" > "$tmp/$1.check.out" 2> "$tmp/$1.check.err" || code=$?
  [[ $code == 2 ]] || fail "$1: check exited $code, not 2: $(cat "$tmp/$1.check.err")"
  grep -q "^error: $2: " "$tmp/$1.check.err" || fail "$1: check does not name $2: $(cat "$tmp/$1.check.err")"
  code=0
  "$grainlab" run "$tmp/$1.json" --out "$tmp/$1.out" > /dev/null 2> "$tmp/$1.run.err" || code=$?
  [[ $code == 2 ]] || fail "$1: run exited $code, not 2: $(tail -3 "$tmp/$1.run.err")"
  grep -q "^error: $2: " "$tmp/$1.run.err" || fail "$1: run does not name $2: $(cat "$tmp/$1.run.err")"
  [[ ! -e $tmp/$1.out/summary.json ]] || fail "$1: a refused run wrote summary.json"
  echo "ok: $1 refused: $(head -c 160 "$tmp/$1.check.err")"
}

scene rate-1e6 circular-quick "s['stages'][2]['strain_rate'] = 1e6"
refused rate-1e6 'stages\[2\]\.strain_rate'
scene diameter-1mm circular-quick "s['assembly']['specimen_diameter'] = 0.001"
refused diameter-1mm 'assembly\.specimen_diameter'
scene rotation-1e12 rotation-circular-quick "s['stages'][2]['total_rotation_deg'] = 1e12"
refused rotation-1e12 'stages\[2\]\.total_rotation_deg'
scene mean-stress-1e30 rotation-circular-quick "s['stages'][2]['mean_stress'] = 1e30"
refused mean-stress-1e30 'stages\[2\]\.mean_stress'
scene pressure-1e12 circular-quick "s['stages'][1]['pressure'] = 1e12"
refused pressure-1e12 'stages\[1\]\.pressure'

# density 1e-3: accepted, warned first thing by check and by run (the run is stopped once the
# warning is out: it would take hours).
scene density-1e-3 circular-quick "s['material']['density'] = 1e-3"
"$grainlab" check "$tmp/density-1e-3.json" > "$tmp/density.check.out" || fail "density: check refused it"
head -1 "$tmp/density.check.out" | grep -q '^warning: material\.density: estimated_seconds ' \
  || fail "density: check's first line is not the warning: $(cat "$tmp/density.check.out")"
"$grainlab" run "$tmp/density-1e-3.json" --out "$tmp/density.out" 2> "$tmp/density.run.err" > /dev/null &
runner=$!
for _ in $(seq 100); do
  grep -q '^warning:' "$tmp/density.run.err" 2>/dev/null && break
  sleep 0.2
done
kill -INT "$runner"; wait "$runner" || true
head -2 "$tmp/density.run.err" | grep -q '^warning: material\.density: estimated_seconds ' \
  || fail "density: run's first lines carry no warning: $(head -3 "$tmp/density.run.err")"
echo "ok: density warned: $(head -c 160 "$tmp/density.check.out")"

# Sheared at 4 /s the lateral servo cannot hold sigma11 at 300 kPa: warned before the first
# step, and the run records the step where sigma11 left its 10% band.
scene rate-4 circular-quick "s['stages'][2]['strain_rate'] = 4"
"$grainlab" run "$tmp/rate-4.json" --out "$tmp/rate-4.out" 2> "$tmp/rate-4.err" > /dev/null \
  || fail "rate 4: run failed: $(tail -3 "$tmp/rate-4.err")"
grep -q '^warning: stages\[2\]\.strain_rate: lateral_servo_inertial_number ' "$tmp/rate-4.err" \
  || fail "rate 4: no lateral servo warning before the run: $(head -5 "$tmp/rate-4.err")"
python3 - "$tmp/rate-4.out" <<'PY' || fail "rate 4: summary.json's warnings"
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
assert s["status"] == "completed", s
measured = [w for w in s["warnings"] if w["quantity"] == "lateral_stress_error" and "step" in w]
assert measured, s["warnings"]
w = measured[0]
assert w["field"] == "stages[2].strain_rate" and w["value"] > w["limit"] == 0.1, w
# The step is inside the shearing stage, where it says.
import csv
rows = {int(r["step"]): r for r in csv.DictReader(open(sys.argv[1] + "/series.csv"))}
row = rows[w["step"]]
assert row["stage"] == "shearing", row["stage"]
assert abs(abs(float(row["sigma11"]) - 3e5) / 3e5 - w["value"]) < 1e-9, (row["sigma11"], w)
print(f"ok: rate 4: sigma11 off by {w['value']:.2f} at step {w['step']}")
PY
echo "validity cases: all as expected"

#!/usr/bin/env bash
# The command line of contracts.md: presets, preset JSON, a run's outputs, and a bad scene
# that exits non-zero with one line naming the field and writes nothing.
set -euo pipefail
grainlab=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$grainlab" presets | grep -qx circular || fail "presets lacks circular"
for p in circular elongated-random elongated-bedding-0 elongated-bedding-30 elongated-bedding-60 elongated-bedding-90; do
  "$grainlab" presets | grep -qx "$p" || fail "presets lacks $p"
  "$grainlab" presets | grep -qx "$p-quick" || fail "presets lacks $p-quick"
done
"$grainlab" preset circular-quick > "$tmp/scene.json"
python3 -c "import json,sys; json.load(open('$tmp/scene.json'))" || fail "preset is not JSON"

# A short run of a scene file.
cat > "$tmp/pair.json" <<'JSON'
{"name": "pair", "particles": [
  {"shape": "disc", "radius": 0.002, "position": [0, 0], "velocity": [0.1, 0]},
  {"shape": "polygon", "vertices": [[-0.002,-0.002],[0.002,-0.002],[0.002,0.002],[-0.002,0.002]],
   "position": [0.0045, 0]}],
 "stages": [{"type": "free", "duration": 0.002}]}
JSON
"$grainlab" run "$tmp/pair.json" --out "$tmp/out" 2> "$tmp/progress.txt" || fail "run failed"
grep -q '%' "$tmp/progress.txt" || fail "no progress on stderr"
for f in series.csv particles_final.csv contacts_final.csv summary.json; do
  [[ -s "$tmp/out/$f" ]] || fail "missing $f"
done
head -1 "$tmp/out/series.csv" | grep -q '^step,time,stage,axial_strain,lateral_strain,volumetric_strain,sigma11,sigma22,sigma12,sigma21,p,q,phi_mob_deg,void_ratio,coordination,contacts,a_c,theta_c_deg,a_n,theta_n_deg,a_t,theta_t_deg,a_w,a_ln,theta_ln_deg,a_lt,theta_lt_deg,theta_sigma_macro_deg,theta_sigma_micro_deg,theta_sigma_eq10_deg,theta_sigma_eq11_deg,omega_macro_deg,omega_micro_deg,kinetic_energy' \
  || fail "series.csv header differs from contracts.md"
[[ $(head -1 "$tmp/out/particles_final.csv") == "id,shape,x,y,angle,vx,vy,spin,radius,boundary" ]] || fail "particles header"
[[ $(head -1 "$tmp/out/contacts_final.csv") == "i,j,px,py,nx,ny,fn,ft,lix,liy,ljx,ljy" ]] || fail "contacts header"
grep -q '"status": "completed"' "$tmp/out/summary.json" || fail "summary status"
! grep -qi 'nan' "$tmp/out/series.csv" || fail "NaN in series.csv"

# A bad scene: non-zero exit, one line naming the field, nothing written.
echo '{"particles": [{"shape": "disc", "radius": -1}]}' > "$tmp/bad.json"
if "$grainlab" run "$tmp/bad.json" --out "$tmp/bad-out" 2> "$tmp/err.txt"; then fail "bad scene accepted"; fi
[[ $(wc -l < "$tmp/err.txt") -eq 1 ]] || fail "error is not one line: $(cat "$tmp/err.txt")"
grep -q 'particles\[0\].radius' "$tmp/err.txt" || fail "error does not name the field: $(cat "$tmp/err.txt")"
[[ ! -e "$tmp/bad-out" ]] || fail "a bad scene wrote to its output directory"
if "$grainlab" run --preset nope --out "$tmp/nope" 2> "$tmp/err2.txt"; then fail "unknown preset accepted"; fi
grep -q '^error: preset' "$tmp/err2.txt" || fail "unknown preset message"
# An absurd cost (a stiffness of 1e30 N/m: a timestep of ~1e-17 s) is refused before the first
# step: exit 2, the field named with the figures, nothing written. --force would run it.
"$grainlab" preset circular-quick | python3 -c '
import json, sys
s = json.load(sys.stdin)
s["material"]["normal_stiffness"] = s["material"]["tangential_stiffness"] = 1e30
print(json.dumps(s))' > "$tmp/stiff.json"
status=0
"$grainlab" run "$tmp/stiff.json" --out "$tmp/stiff-out" 2> "$tmp/err3.txt" || status=$?
[[ $status -eq 2 ]] || fail "an absurd cost exited $status, not 2: $(cat "$tmp/err3.txt")"
grep -q '^error: material.normal_stiffness: .*years' "$tmp/err3.txt" || fail "refusal message: $(cat "$tmp/err3.txt")"
[[ ! -e "$tmp/stiff-out" ]] || fail "a refused run wrote to its output directory"
# The first progress line of a normal run is its estimate.
grep -q '^estimate: timestep' "$tmp/progress.txt" || fail "no estimate line: $(head -2 "$tmp/progress.txt")"
echo "cli contract: all checks passed"

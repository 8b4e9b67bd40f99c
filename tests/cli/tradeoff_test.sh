#!/usr/bin/env bash
# `grainlab tradeoff --quick`: a reduced sweep on circular-quick writes tradeoff.csv with the
# documented columns, a number in every measured cell and never "nan", zero error for the
# reference, a Pareto front, a well-formed pareto.svg, and the scene of every run.
set -euo pipefail
grainlab=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$grainlab" tradeoff --out "$tmp/out" --quick > "$tmp/stdout.txt" 2> "$tmp/stderr.txt" \
  || { cat "$tmp/stderr.txt" >&2; fail "tradeoff --quick exited non-zero"; }
[[ -s $tmp/out/tradeoff.csv ]] || fail "no tradeoff.csv"
[[ -s $tmp/out/pareto.svg ]] || fail "no pareto.svg"

python3 - "$tmp/out" <<'PY' || fail "tradeoff.csv or pareto.svg check"
import csv, math, os, sys, xml.etree.ElementTree as ET
out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/tradeoff.csv")))
expected = ("preset,axis,value,timestep_safety,inertial_number,strain_rate_per_s,vertices,sample_strain,engine,"
            "status,wall_s,cpu_s,steps,particles,measured_inertial_number,shearing_kinetic_energy,"
            "peak_phi_mob_deg,phi_mob_20_deg,"
            "omega_2_deg,omega_5_deg,omega_10_deg,omega_20_deg,theta_sigma_gap_deg,void_ratio,"
            "err_peak_phi_mob_deg,err_phi_mob_20_deg,err_omega_2_deg,err_omega_5_deg,err_omega_10_deg,"
            "err_omega_20_deg,err_theta_sigma_gap_deg,err_void_ratio,mean_angle_error_deg,max_angle_error_deg,pareto,scene,"
            "note").split(",")
header = open(f"{out}/tradeoff.csv").readline().strip().split(",")
assert header == expected, f"columns differ: {header}"
for r in rows:
    for c, v in r.items():
        assert v.strip().lower() not in ("nan", "-nan", "inf", "-inf"), (c, v)
axes = {r["axis"] for r in rows}
for axis in ("reference", "timestep_safety", "inertial_number", "sample_strain") + (
        () if any(r["status"] == "skipped" for r in rows) else ("engine", "box2d")):
    assert axis in axes, f"no {axis} rows"
measured = [c for c in expected if c.startswith("err_") or c in (
    "wall_s", "cpu_s", "steps", "peak_phi_mob_deg", "phi_mob_20_deg", "void_ratio", "mean_angle_error_deg",
    "max_angle_error_deg")]
for r in rows:
    if r["status"] == "skipped":
        assert r["axis"] == "engine" and r["note"], r
        continue
    if r["axis"] == "box2d":
        # box2d's own knob reaches the scene that ran: 20 velocity iterations, not its 8.
        import json
        solver = json.load(open(f"{out}/{r['scene']}"))["solver"]
        assert r["engine"] == "box2d" and r["value"] == "velocity_iterations 20", r
        assert solver["engine"] == "box2d" and solver["velocity_iterations"] == 20, solver
    assert r["status"] == "completed", r
    for c in measured:
        assert math.isfinite(float(r[c])), (c, r)
    assert os.path.isfile(f"{out}/{r['scene']}"), r["scene"]
ref = [r for r in rows if r["axis"] == "reference"]
assert len(ref) == 1 and float(ref[0]["mean_angle_error_deg"]) == 0 and ref[0]["pareto"] == "1"
assert sum(r["pareto"] == "1" for r in rows) >= 2, "a front of one point"
# The faster shearing (larger I) costs less CPU time than the reference's.
assert float(ref[0]["cpu_s"]) > min(float(r["cpu_s"]) for r in rows if r["axis"] == "inertial_number")
svg = ET.parse(f"{out}/pareto.svg").getroot()
assert svg.tag.endswith("svg")
assert len(svg.findall(".//{http://www.w3.org/2000/svg}circle")) >= 5
PY
# --axes keeps only the named axes (and the reference); an unknown axis is refused by name.
"$grainlab" tradeoff --out "$tmp/axes" --quick --axes inertial_number > /dev/null 2> "$tmp/axes.txt" \
  || { cat "$tmp/axes.txt" >&2; fail "tradeoff --axes inertial_number exited non-zero"; }
python3 - "$tmp/axes/tradeoff.csv" <<'PY' || fail "--axes inertial_number ran other axes"
import csv, sys
axes = sorted({r["axis"] for r in csv.DictReader(open(sys.argv[1]))})
assert axes == ["inertial_number", "reference"], axes
PY
set +e
"$grainlab" tradeoff --out "$tmp/bad" --quick --axes inertia 2> "$tmp/bad.txt"
status=$?
set -e
[[ $status -eq 2 ]] || fail "an unknown axis exited $status, not 2"
grep -q -- '--axes: unknown axis "inertia"' "$tmp/bad.txt" || fail "no error naming the axis: $(cat "$tmp/bad.txt")"
[[ ! -e $tmp/bad ]] || fail "a refused tradeoff wrote $tmp/bad"
echo "tradeoff: all checks passed"

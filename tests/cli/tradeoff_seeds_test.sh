#!/usr/bin/env bash
# `grainlab tradeoff --quick --seeds 3`: the paired ensemble on circular-quick writes tradeoff.csv
# with one row per setting and quantity and the columns of the ensemble design (seeds, bias and
# its 95% interval, sd, cpu_s, runs_for_tolerance), intervals that hold their bias, verdicts
# that follow from the intervals, the shearing settings paired on the reference's specimens,
# and a pareto.svg with interval bars.
set -euo pipefail
grainlab=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$grainlab" tradeoff --out "$tmp/out" --quick --seeds 3 > "$tmp/stdout.txt" 2> "$tmp/stderr.txt" \
  || { cat "$tmp/stderr.txt" >&2; fail "tradeoff --quick --seeds 3 exited non-zero"; }
for f in tradeoff.csv runs.csv pareto.svg; do [[ -s $tmp/out/$f ]] || fail "no $f"; done
ls "$tmp/out/specimens/circular-quick/seed-3/stages/consolidation.checkpoint" > /dev/null \
  || fail "the reference kept no specimen for seed 3"

python3 - "$tmp/out" <<'PY' || fail "tradeoff.csv check"
import csv, math, sys, xml.etree.ElementTree as ET
out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/tradeoff.csv")))
header = open(f"{out}/tradeoff.csv").readline().strip().split(",")
for c in ("seeds", "bias", "bias_ci_low", "bias_ci_high", "sd", "cpu_s", "runs_for_tolerance", "verdict", "quantity",
          "tolerance", "paired"):
    assert c in header, f"no column {c}: {header}"
quantities = {r["quantity"] for r in rows}
for q in ("peak_phi_mob_deg", "phi_mob_20_deg", "void_ratio_5", "void_ratio_20", "a_c_5", "theta_sigma_1_deg",
          "theta_sigma_10_deg", "omega_1_deg", "omega_10_deg", "theta_sigma_gap_deg"):
    assert q in quantities, f"no rows for {q}"
judged = [r for r in rows if r["axis"] != "reference"]
assert judged, "no settings judged"
paired_axes = {r["axis"] for r in judged if r["paired"] == "1"}
assert {"timestep_safety", "inertial_number", "sample_strain"} <= paired_axes, paired_axes
assert all(r["paired"] == "0" for r in judged if r["engine"] == "box2d"), "box2d cannot shear a dem specimen"
seen_bias = 0
for r in judged:
    assert r["seeds"] == "3", r
    if r["bias"] == "":
        continue
    b, lo, hi, sd, tol = (float(r[c]) for c in ("bias", "bias_ci_low", "bias_ci_high", "sd", "tolerance"))
    assert lo <= b <= hi, r
    seen_bias += 1
    assert float(r["cpu_s"]) > 0, r
    v = r["verdict"]
    if lo > 0 or hi < 0:
        assert v.startswith("biased by "), r
    elif -tol <= lo and hi <= tol:
        assert v == "no bias found at 3 seeds", r
    else:
        assert v == "undecided at 3 seeds", r
    # ⌈(t·sd/tol)²⌉ with t = 4.303 (2 degrees of freedom) for a paired row
    if r["paired"] == "1":
        want = max(2, math.ceil((4.303 * sd / tol) ** 2))
        assert int(float(r["runs_for_tolerance"])) == want, (r, want)
        assert abs((hi - lo) / 2 - 4.303 * sd / math.sqrt(3)) <= 1e-6 * max(1, abs(hi - lo)), r
assert seen_bias >= 0.8 * len(judged), f"only {seen_bias} of {len(judged)} rows measured a bias"
# A paired setting that changes nothing of the specimen: its void ratio after consolidation is
# not among the quantities, but its void ratio at 5% is measured on the same specimen.
runs = list(csv.DictReader(open(f"{out}/runs.csv")))
assert len({(r["axis"], r["value"]) for r in runs}) >= 6 and all(r["status"] == "completed" for r in runs), runs[:2]
svg = ET.parse(f"{out}/pareto.svg").getroot()
ns = "{http://www.w3.org/2000/svg}"
assert len(svg.findall(f".//{ns}circle")) >= 5
bars = [l for l in svg.findall(f".//{ns}line") if l.get("stroke-width") == "1.5"]
assert len(bars) >= 4, "no interval bars"
PY
echo "tradeoff --seeds: all checks passed"

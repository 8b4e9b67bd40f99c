#!/usr/bin/env bash
# `grainlab shapes` in little: two seeds of the quick hexagons, 2-disc clumps and plain discs on
# the random assembly. shapes.csv has its columns and a row per representation and quantity;
# every interval holds its mean; the bias of the peak φ_mob and its Welch interval are
# recomputed from runs.csv; the cost ratio is the CPU time over the hexagons'. A second call
# runs nothing and writes the same table (the study resumes from DIR/runs).
set -euo pipefail
grainlab=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

args=(shapes --out "$tmp/out" --seeds 2 --jobs 2 --assemblies random --representations clumps-2,discs)
"$grainlab" "${args[@]}" > "$tmp/stdout.txt" 2> "$tmp/stderr.txt" || { cat "$tmp/stderr.txt" >&2; fail "shapes exited non-zero"; }
for f in shapes.csv runs.csv calibration.csv shapes.svg; do [[ -s $tmp/out/$f ]] || fail "no $f"; done
cp "$tmp/out/shapes.csv" "$tmp/first.csv"

python3 - "$tmp/out" <<'PY' || fail "shapes.csv check"
import csv, math, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/shapes.csv")))
header = open(f"{out}/shapes.csv").readline().strip().split(",")
for c in ("size", "assembly", "representation", "preset", "quantity", "tolerance", "seeds", "mean", "mean_ci_low",
          "mean_ci_high", "reference_mean", "bias", "bias_ci_low", "bias_ci_high", "welch_t", "sd", "verdict", "cpu_s",
          "cost_ratio", "failed_runs"):
    assert c in header, f"no column {c}: {header}"
quantities = ("peak_phi_mob_deg", "phi_mob_20_deg", "void_ratio_5", "void_ratio_20", "a_c_5", "theta_sigma_1_deg",
              "theta_sigma_10_deg", "omega_1_deg", "omega_10_deg", "theta_sigma_gap_deg", "void_ratio_consolidated")
for rep in ("hexagons", "clumps-2", "discs"):
    mine = {r["quantity"]: r for r in rows if r["representation"] == rep}
    for q in quantities:
        assert q in mine, f"no {rep} row for {q}"
assert {r["preset"] for r in rows} == {"elongated-random-quick", "clump-random-quick", "circular-quick"}, rows
checked = 0
for r in rows:
    assert r["size"] == "quick" and r["assembly"] == "random" and r["failed_runs"] == "0", r
    assert r["seeds"] == "2" and r["reference_seeds"] == "2", r
    m, lo, hi = (float(r[c]) for c in ("mean", "mean_ci_low", "mean_ci_high"))
    assert lo <= m <= hi and lo < hi, r
    assert float(r["cpu_s_ci_low"]) <= float(r["cpu_s"]) <= float(r["cpu_s_ci_high"]), r
    if r["representation"] == "hexagons":
        assert r["verdict"] == "reference" and r["bias"] == "", r
        assert float(r["cost_ratio"]) == 1.0, r
        continue
    b, blo, bhi = (float(r[c]) for c in ("bias", "bias_ci_low", "bias_ci_high"))
    assert blo <= b <= bhi, r
    tol = float(r["tolerance"])
    if blo > 0 or bhi < 0:
        assert r["verdict"].startswith("biased by "), r
    elif -tol <= blo and bhi <= tol:
        assert r["verdict"] == "no bias found at 2 seeds", r
    else:
        assert r["verdict"] == "undecided at 2 seeds", r
    checked += 1
assert checked == 2 * len({r["quantity"] for r in rows}) == 2 * 15, checked

# Welch from the runs themselves, for the peak φ_mob: bias = mean − mean, half-width t·√(sa²/na + sb²/nb),
# t the 97.5% quantile at the Welch–Satterthwaite degrees of freedom rounded down (1 or 2 here).
runs = list(csv.DictReader(open(f"{out}/runs.csv")))
assert len(runs) == 6, len(runs)
def values(rep, q):
    return [float(r[q]) for r in runs if r["representation"] == rep]
def var(v):
    m = sum(v) / len(v)
    return sum((x - m) ** 2 for x in v) / (len(v) - 1)
t975 = {1: 12.706204736, 2: 4.30265273}
ref = values("hexagons", "peak_phi_mob_deg")
cpu = {rep: sum(values(rep, "cpu_s")) / 2 for rep in ("hexagons", "clumps-2", "discs")}
for rep in ("clumps-2", "discs"):
    v = values(rep, "peak_phi_mob_deg")
    row = next(r for r in rows if r["representation"] == rep and r["quantity"] == "peak_phi_mob_deg")
    va, vb = var(v) / 2, var(ref) / 2
    dof = (va + vb) ** 2 / (va ** 2 + vb ** 2)
    t = t975[max(1, math.floor(dof))]
    bias = sum(v) / 2 - sum(ref) / 2
    assert abs(float(row["bias"]) - bias) < 1e-6, (row, bias)
    assert abs(float(row["welch_t"]) - t) < 1e-3, (row, t)
    t = float(row["welch_t"])  # the study's table of t, to 3 decimals
    assert abs(float(row["bias_ci_high"]) - (bias + t * math.sqrt(va + vb))) < 1e-6, row
    assert abs(float(row["cost_ratio"]) - cpu[rep] / cpu["hexagons"]) < 1e-6 * cpu[rep], row
    assert float(row["cpu_s"]) > 0, row
# The discs' runs are the same for any assembly: one ensemble on the circular specimen.
assert {r["specimen"] for r in runs if r["representation"] == "discs"} == {"circular"}, runs
PY

"$grainlab" "${args[@]}" > "$tmp/stdout2.txt" 2> "$tmp/stderr2.txt" || { cat "$tmp/stderr2.txt" >&2; fail "the resumed call exited non-zero"; }
grep -q "6 runs, 6 already done, running 0" "$tmp/stderr2.txt" || { cat "$tmp/stderr2.txt" >&2; fail "the resumed call ran again"; }
cmp "$tmp/first.csv" "$tmp/out/shapes.csv" || fail "the resumed call wrote another shapes.csv"

# A bad option is refused by name before anything runs.
if "$grainlab" shapes --out "$tmp/bad" --representations clumps-9 2> "$tmp/bad.txt"; then fail "clumps-9 accepted"; fi
grep -q -- "--representations" "$tmp/bad.txt" || fail "the refusal does not name --representations: $(cat "$tmp/bad.txt")"
[[ ! -e $tmp/bad ]] || fail "a refused call wrote $tmp/bad"
echo "shapes tiny study: ok"

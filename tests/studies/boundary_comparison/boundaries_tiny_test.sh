#!/usr/bin/env bash
# `grainlab boundaries` in little: two seeds of the ring, the cell and the matched cell on the
# circular assembly, sheared to an axial strain of 0.03. boundaries.csv has its columns and a
# row per boundary and quantity; every interval holds its mean; the cell − ring difference of
# the peak φ_mob and its Welch interval are recomputed from runs.csv; the peak, its strain and
# a_c there, and the curves' means are recomputed from each run's own series.csv. A second call
# runs nothing and writes the same tables (the study resumes from DIR/runs).
set -euo pipefail
grainlab=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

args=(boundaries --out "$tmp/out" --seeds 2 --jobs 2 --assemblies circular --axial-strain 0.03)
"$grainlab" "${args[@]}" > "$tmp/stdout.txt" 2> "$tmp/stderr.txt" || { cat "$tmp/stderr.txt" >&2; fail "boundaries exited non-zero"; }
for f in boundaries.csv runs.csv curves.csv curves.svg; do [[ -s $tmp/out/$f ]] || fail "no $f"; done
cp "$tmp/out/boundaries.csv" "$tmp/first.csv"
cp "$tmp/out/curves.csv" "$tmp/first-curves.csv"

python3 - "$tmp/out" <<'PY' || fail "table check"
import csv, math, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/boundaries.csv")))
header = open(f"{out}/boundaries.csv").readline().strip().split(",")
for c in ("size", "assembly", "boundary", "preset", "quantity", "seeds", "mean", "mean_ci_low", "mean_ci_high", "sd",
          "ring_mean", "difference", "difference_ci_low", "difference_ci_high", "welch_t", "resolved", "failed_runs"):
    assert c in header, f"no column {c}: {header}"
presets = {"ring": "circular-quick", "cell": "periodic-biaxial-circular-quick",
           "cell-matched": "periodic-biaxial-circular-quick"}
for b, p in presets.items():
    mine = {r["quantity"]: r for r in rows if r["boundary"] == b}
    for q in ("peak_phi_mob_deg", "axial_strain_at_peak", "a_c_at_peak", "omega_1_deg", "omega_2_deg",
              "void_ratio_consolidated"):
        assert q in mine, f"no {b} row for {q}"
    assert {r["preset"] for r in mine.values()} == {p}, mine
checked = 0
for r in rows:
    assert r["size"] == "quick" and r["assembly"] == "circular" and r["failed_runs"] == "0", r
    if r["seeds"] == "0":  # measured past the shortened shearing (e.g. φ_mob at 20 %): nothing
        assert r["mean"] == "" and r["quantity"] in ("phi_mob_20_deg", "void_ratio_5", "void_ratio_20", "a_c_5", "theta_sigma_5_deg",
            "theta_sigma_10_deg", "omega_5_deg", "omega_10_deg"), r
        continue
    assert r["seeds"] == "2", r
    m, lo, hi = (float(r[c]) for c in ("mean", "mean_ci_low", "mean_ci_high"))
    eps = 1e-9 * max(1.0, abs(m))  # two seeds may agree to the last digits (both peak at one sample)
    assert lo - eps <= m <= hi + eps, r
    if r["boundary"] == "ring":
        assert r["resolved"] == "reference" and r["difference"] == "", r
        continue
    d, dlo, dhi = (float(r[c]) for c in ("difference", "difference_ci_low", "difference_ci_high"))
    assert dlo - eps <= d <= dhi + eps, r
    assert r["resolved"] == ("yes" if dlo > 0 or dhi < 0 else "not resolved at 2 seeds"), r
    checked += 1
assert checked >= 2 * 8, checked

# Welch from the runs themselves: difference = mean − mean, half-width t·√(sa²/na + sb²/nb), t the
# 97.5% quantile at the Welch–Satterthwaite degrees of freedom rounded down (1 or 2 here).
runs = list(csv.DictReader(open(f"{out}/runs.csv")))
assert len(runs) == 6, len(runs)
def values(b, q):
    return [float(r[q]) for r in runs if r["boundary"] == b]
def var(v):
    m = sum(v) / len(v)
    return sum((x - m) ** 2 for x in v) / (len(v) - 1)
t975 = {1: 12.706204736, 2: 4.30265273}
for q in ("peak_phi_mob_deg", "void_ratio_consolidated", "a_c_at_peak"):
    ring = values("ring", q)
    for b in ("cell", "cell-matched"):
        v = values(b, q)
        row = next(r for r in rows if r["boundary"] == b and r["quantity"] == q)
        va, vb = var(v) / 2, var(ring) / 2
        dof = (va + vb) ** 2 / (va ** 2 + vb ** 2)
        t = t975[max(1, math.floor(dof))]
        diff = sum(v) / 2 - sum(ring) / 2
        # The tables print 10 significant digits, so each run's value here is off by up to
        # 5e-10 of itself: a mean or the difference by up to 1e-9 of the largest value (big),
        # the interval's half-width t √(va + vb) by up to t times that, besides the printed
        # result's own 5e-10.
        big = max(abs(x) for x in v + ring)
        assert abs(float(row["difference"]) - diff) < 1e-9 * big + 5e-10 * abs(diff), (row, diff)
        assert abs(float(row["welch_t"]) - t) < 1e-3, (row, t)
        t = float(row["welch_t"])
        high = diff + t * math.sqrt(va + vb)
        assert abs(float(row["difference_ci_high"]) - high) < 1e-9 * big * (1 + t) + 5e-10 * abs(high), (row, high)
        assert abs(float(row["mean"]) - sum(v) / 2) < 1e-9 * big, row

# Each run's peak, its strain and a_c there, from its own series.csv; the curves' means likewise.
def shearing(run):
    d = f"{out}/runs/{run['boundary']}-{run['preset']}/seed-{run['seed']}/series.csv"
    return [s for s in csv.DictReader(open(d)) if s["stage"] == "shearing" and s["phi_mob_deg"] != ""]
def at(samples, col, e):
    for a, b in zip(samples, samples[1:]):
        x0, x1 = float(a["axial_strain"]), float(b["axial_strain"])
        if min(x0, x1) <= e <= max(x0, x1):
            t = 0 if x1 == x0 else (e - x0) / (x1 - x0)
            return float(a[col]) + t * (float(b[col]) - float(a[col]))
    raise AssertionError(f"{e} not bracketed")
curves = list(csv.DictReader(open(f"{out}/curves.csv")))
for run in runs:
    s = shearing(run)
    peak = max(s, key=lambda x: float(x["phi_mob_deg"]))
    assert abs(float(run["peak_phi_mob_deg"]) - float(peak["phi_mob_deg"])) < 1e-6, (run, peak)
    assert abs(float(run["axial_strain_at_peak"]) - float(peak["axial_strain"])) < 1e-9, run
    assert abs(float(run["a_c_at_peak"]) - float(peak["a_c"])) < 1e-9, run
for b in presets:
    mine = [r for r in runs if r["boundary"] == b]
    for q in ("phi_mob_deg", "a_c"):
        for e in (0.01, 0.02):
            want = sum(at(shearing(r), q, e) for r in mine) / len(mine)
            row = next(c for c in curves if c["boundary"] == b and c["quantity"] == q and abs(float(c["axial_strain"]) - e) < 1e-12)
            assert abs(float(row["mean"]) - want) < 1e-8 * max(1, abs(want)), (row, want)
            assert float(row["ci_low"]) <= float(row["mean"]) <= float(row["ci_high"]), row
PY

"$grainlab" "${args[@]}" > "$tmp/stdout2.txt" 2> "$tmp/stderr2.txt" || { cat "$tmp/stderr2.txt" >&2; fail "the resumed call exited non-zero"; }
grep -q "6 runs, 6 already completed (kept), 0 to run" "$tmp/stderr2.txt" || { cat "$tmp/stderr2.txt" >&2; fail "the resumed call ran again"; }
cmp "$tmp/first.csv" "$tmp/out/boundaries.csv" || fail "the resumed call wrote another boundaries.csv"
cmp "$tmp/first-curves.csv" "$tmp/out/curves.csv" || fail "the resumed call wrote another curves.csv"

# A bad option is refused by name before anything runs.
if "$grainlab" boundaries --out "$tmp/bad" --boundaries wall 2> "$tmp/bad.txt"; then fail "wall accepted"; fi
grep -q -- "--boundaries" "$tmp/bad.txt" || fail "the refusal does not name --boundaries: $(cat "$tmp/bad.txt")"
if "$grainlab" boundaries --out "$tmp/bad" --assemblies random 2> "$tmp/bad.txt"; then fail "random accepted"; fi
grep -q -- "--assemblies" "$tmp/bad.txt" || fail "the refusal does not name --assemblies: $(cat "$tmp/bad.txt")"
[[ ! -e $tmp/bad ]] || fail "a refused call wrote $tmp/bad"
echo "boundaries tiny study: ok"

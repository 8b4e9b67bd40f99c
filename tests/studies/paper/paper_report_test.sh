#!/usr/bin/env bash
# `grainlab paper --quick --seeds 2`: the report's structure, not the paper's agreement.
# report.html exists and loads nothing from the network, has the eight findings rows each with
# a verdict; findings.csv has seeds, ci_low, ci_high; every figure's CSV exists with a header,
# rows, mean and interval columns and no nan/inf cell; each seed's run has its own folder; and
# --report-only rebuilds the same findings from the folders. Twelve quick runs: the CI's
# longest test (about 2× the single-seed one it replaces).
# Verdicts are free to go either way where the physics decides, but two follow from the code
# alone, run by run: the contact stress is symmetric (every particle in moment equilibrium at
# the quasi-static rates of the presets: σ12 − σ21 below 1% of p), and for discs the branch
# vector is (r − δ/2)·n with δ = f_n/k_n, so a_lt vanishes to rounding and a_ln is only the
# overlaps' trace: l0·a_ln = f0·a_n/(2 k_n), at right angles to the forces' direction. Each run
# must show them, and the merged findings must not deny them (two seeds' t-interval, 12.7
# standard errors wide, may leave them "not resolved").
set -euo pipefail
grainlab=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# Bad --seeds: a clear error naming the option, and nothing run.
if "$grainlab" paper --quick --seeds 0 --out "$tmp/bad" 2> "$tmp/bad.txt"; then fail "--seeds 0 was accepted"; fi
grep -q -- '--seeds takes a positive whole number' "$tmp/bad.txt" || fail "--seeds 0: no clear error ($(cat "$tmp/bad.txt"))"
[[ ! -e "$tmp/bad" ]] || fail "--seeds 0 wrote into its output directory"

"$grainlab" paper --quick --seeds 2 --out "$tmp/out" 2> "$tmp/progress.txt" || { tail -20 "$tmp/progress.txt" >&2; fail "paper exited non-zero"; }
grep -q 'completed in' "$tmp/progress.txt" || fail "no progress on stderr"
[[ -s "$tmp/out/report.html" ]] || fail "no report.html"

cp "$tmp/out/findings.csv" "$tmp/findings-run.csv"
"$grainlab" paper --quick --out "$tmp/out" --report-only 2> "$tmp/rebuild.txt" || { cat "$tmp/rebuild.txt" >&2; fail "--report-only exited non-zero"; }
cmp -s "$tmp/out/findings.csv" "$tmp/findings-run.csv" || fail "--report-only gives other findings than the run"

# The ensemble runs through the sweeps' batch executor: run again, it resumes, and under
# mpirun the runs spread over ranks. With one run's folder gone, `mpirun -np 2` reruns exactly
# that run (circular-quick, seconds), keeps the others, and rank 0 writes the same findings.
if command -v mpirun >/dev/null; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
  cp "$tmp/out/runs/circular-quick/seed-2/series.csv" "$tmp/series-seed2.csv"
  rm -rf "$tmp/out/runs/circular-quick/seed-2"
  mpirun -np 2 --oversubscribe "$grainlab" paper --quick --seeds 2 --out "$tmp/out" 2> "$tmp/mpi.txt" \
    || { tail -20 "$tmp/mpi.txt" >&2; fail "paper under mpirun exited non-zero"; }
  grep -q '11 already completed (kept), 1 to run' "$tmp/mpi.txt" || fail "the resume did not rerun exactly one run: $(head -3 "$tmp/mpi.txt")"
  cmp -s "$tmp/series-seed2.csv" "$tmp/out/runs/circular-quick/seed-2/series.csv" || fail "the rerun under MPI differs"
  cmp -s "$tmp/out/findings.csv" "$tmp/findings-run.csv" || fail "the resumed ensemble gives other findings"
else
  fail "mpirun is missing: ./scripts/setup installs openmpi-bin"
fi

python3 - "$tmp/out" <<'PY'
import csv, json, math, os, re, sys
out = sys.argv[1]
html = open(os.path.join(out, "report.html"), encoding="utf-8").read()
def fail(msg):
    print("FAIL:", msg, file=sys.stderr)
    sys.exit(1)

# Self-contained: no src/href (nor CSS url()) pointing off the machine, no scripts to fetch.
external = re.findall(r'(?:src|href)\s*=\s*["\']?\s*(?:https?:)?//', html, re.I)
if external:
    fail(f"external references in report.html: {external[:3]}")
if re.search(r'url\(\s*["\']?\s*(?:https?:)?//', html, re.I):
    fail("external url() in report.html")
if "<svg" not in html:
    fail("report.html has no inline SVG")

verdicts = {"holds", "does not hold", "inconclusive", "not resolved at 2 seeds"}
decided = {1: {"holds", "not resolved at 2 seeds"}}  # stress symmetry, never "does not hold"
for n in range(1, 9):
    m = re.search(r'<tr class="finding" id="finding-%d">(.*?)</tr>' % n, html, re.S)
    if not m:
        fail(f"finding {n} has no row")
    v = re.search(r'<td class="verdict[^"]*">([^<]*)</td>', m.group(1))
    if not v or v.group(1) not in verdicts:
        fail(f"finding {n} has no verdict")
    if n in decided and v.group(1) not in decided[n]:
        fail(f"finding {n}: {v.group(1)!r}, but the code alone allows only {sorted(decided[n])}")

figures = ["fig%02d" % k for k in range(6, 16)] + ["roses"]
for name in figures + ["runs", "findings"]:
    path = os.path.join(out, name + ".csv")
    if not os.path.isfile(path):
        fail(f"{name}.csv is missing")
    rows = list(csv.reader(open(path, encoding="utf-8")))
    if len(rows) < 2:
        fail(f"{name}.csv has no data rows")
    width = len(rows[0])
    for i, row in enumerate(rows[1:], 2):
        if len(row) != width:
            fail(f"{name}.csv line {i} has {len(row)} cells for {width} columns")
        for cell in row:
            if cell.strip().lower() in ("nan", "-nan", "inf", "-inf", "+inf", "infinity", "-infinity"):
                fail(f"{name}.csv line {i} has a {cell} cell")
    if name in figures and f'href="{name}.csv"' not in html:
        fail(f"report.html does not link {name}.csv")

for name in figures[:-1]:
    header = next(csv.reader(open(os.path.join(out, name + ".csv"), encoding="utf-8")))
    for col in ("seeds",):
        if col not in header:
            fail(f"{name}.csv has no {col} column")
    if not any(h.endswith("_mean") for h in header) or not any(h.endswith("_ci_low") for h in header):
        fail(f"{name}.csv has no _mean/_ci_low columns")

findings = list(csv.DictReader(open(os.path.join(out, "findings.csv"), encoding="utf-8")))
for col in ("seeds", "ci_low", "ci_high", "verdict", "value"):
    if col not in findings[0]:
        fail(f"findings.csv has no {col} column")
if sorted({int(r["number"]) for r in findings}) != list(range(1, 9)):
    fail("findings.csv does not cover findings 1-8")
judged = [r for r in findings if r["seeds"] == "2" and r["ci_low"] and r["ci_high"]]
if not judged:
    fail("no check in findings.csv was judged on two seeds with an interval")
for r in judged:
    if not float(r["ci_low"]) <= float(r["value"]) <= float(r["ci_high"]):
        fail(f"finding {r['number']} {r['subject']}: mean {r['value']} outside its interval")
# The checks the code alone decides: symmetry for each of the six assemblies, and the discs'
# branch-vector anisotropy.
symmetry = [r for r in findings if r["number"] == "1"]
branch = [r for r in findings if r["number"] == "2" and "a_ln, a_lt" in r["subject"]]
for r in symmetry + branch:
    if r["check_verdict"] == "does not hold" or not float(r["value"]) < float(r["holds_to"]):
        fail(f"finding {r['number']} {r['subject']}: {r['check_verdict']} ({r['measured']}), which the code alone decides")
if len(symmetry) != 6 or len(branch) != 1:
    fail(f"{len(symmetry)} symmetry checks (6 assemblies) and {len(branch)} disc branch checks (1)")
for preset in ["circular", "elongated-random"] + ["elongated-bedding-%d" % a for a in (0, 30, 60, 90)]:
    for seed in (1, 2):
        path = os.path.join(out, "runs", preset + "-quick", f"seed-{seed}", "series.csv")
        rows = [r for r in csv.DictReader(open(path, encoding="utf-8")) if r["stage"] == "shearing"]
        asym = max(abs(float(r["sigma12"]) - float(r["sigma21"])) / float(r["p"]) for r in rows if float(r["p"]) > 0)
        if not asym < 0.01:
            fail(f"{preset}-quick seed {seed}: max |σ12 − σ21|/p = {asym} over the shearing, not below 1%")
        if preset == "circular":
            lt = max(abs(float(r["a_lt"])) for r in rows)
            if not lt < 1e-9:
                fail(f"circular-quick seed {seed}: a_lt up to {lt} (a disc's l_t is zero: rounding only)")
            # l0·a_ln = f0·a_n/(2 k_n), but for the dashpot's share of the normal forces, which
            # no overlap carries: over every shearing sample of 16 runs of circular-quick it held
            # within 6 %. A branch vector of r (no overlap) or of 2r − δ breaks it by 100 %.
            scene = json.load(open(os.path.join(os.path.dirname(path), "scene.json"), encoding="utf-8"))
            kn = float(scene["material"]["normal_stiffness"])
            for r in rows:
                expected = float(r["f0"]) * float(r["a_n"]) / (2 * kn * float(r["l0"]))
                turn = (float(r["theta_ln_deg"]) - float(r["theta_n_deg"])) % 180
                if not (abs(float(r["a_ln"]) - expected) <= 0.1 * expected and abs(turn - 90) < 5):
                    fail(f"circular-quick seed {seed} at axial strain {r['axial_strain']}: a_ln {r['a_ln']} at "
                         f"{r['theta_ln_deg']}°, but the overlaps give {expected} at 90° to θ_n = {r['theta_n_deg']}°")

runs = list(csv.DictReader(open(os.path.join(out, "runs.csv"), encoding="utf-8")))
if len(runs) != 12:
    fail(f"runs.csv has {len(runs)} runs, not 6 assemblies × 2 seeds")
for preset in ["circular", "elongated-random"] + ["elongated-bedding-%d" % a for a in (0, 30, 60, 90)]:
    for seed in (1, 2):
        run = os.path.join(out, "runs", preset + "-quick", f"seed-{seed}")
        for f in ("scene.json", "series.csv", "summary.json", "particles_final.csv", "contacts_final.csv", "roses.json"):
            if not os.path.isfile(os.path.join(run, f)):
                fail(f"runs/{preset}-quick/seed-{seed}/{f} is missing")
print("paper report structure: ok")
PY

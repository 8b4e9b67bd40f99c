#!/usr/bin/env bash
# `grainlab paper --quick`: the report's structure, not the paper's agreement. report.html
# exists and loads nothing from the network, has the seven findings rows each with a verdict,
# and every figure's CSV exists with a header and rows and no nan/inf cell.
set -euo pipefail
grainlab=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$grainlab" paper --quick --out "$tmp/out" 2> "$tmp/progress.txt" || { tail -20 "$tmp/progress.txt" >&2; fail "paper exited non-zero"; }
grep -q 'completed in' "$tmp/progress.txt" || fail "no progress on stderr"
[[ -s "$tmp/out/report.html" ]] || fail "no report.html"

python3 - "$tmp/out" <<'PY'
import csv, math, os, re, sys
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

verdicts = {"holds", "does not hold", "inconclusive"}
for n in range(1, 8):
    m = re.search(r'<tr class="finding" id="finding-%d">(.*?)</tr>' % n, html, re.S)
    if not m:
        fail(f"finding {n} has no row")
    v = re.search(r'<td class="verdict[^"]*">([^<]*)</td>', m.group(1))
    if not v or v.group(1) not in verdicts:
        fail(f"finding {n} has no verdict")

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

for preset in ["circular", "elongated-random"] + ["elongated-bedding-%d" % a for a in (0, 30, 60, 90)]:
    run = os.path.join(out, "runs", preset + "-quick")
    for f in ("series.csv", "summary.json", "particles_final.csv", "contacts_final.csv"):
        if not os.path.isfile(os.path.join(run, f)):
            fail(f"runs/{preset}-quick/{f} is missing")
print("paper report structure: ok")
PY

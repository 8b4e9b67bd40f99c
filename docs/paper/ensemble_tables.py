# Markdown tables for docs/paper-reproduction.md from a `grainlab paper --seeds N` output directory.
import csv, math, statistics as st, sys
out = sys.argv[1]
runs = list(csv.DictReader(open(f"{out}/runs.csv")))
T = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365}
def ci(v, fmt):
    m = st.mean(v); h = T[len(v) - 1] * st.stdev(v) / math.sqrt(len(v))
    return f"{m:{fmt}} ({m - h:{fmt}} to {m + h:{fmt}})"
bar = chr(92) + "|"
print("| assembly | seeds completed | particles (ring incl.) | contacts at ε22 = 0 | void ratio after consolidation (95 % interval) | paper | peak φ_mob in shearing, ° (95 % interval) | wall time per run |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
order = []
for r in runs:
    if r["assembly"] not in order: order.append(r["assembly"])
for a in order:
    rs = [r for r in runs if r["assembly"] == a]
    ok = [r for r in rs if r["status"] == "completed"]
    parts = sorted({int(r["particles"]) for r in ok})
    c = [float(r["contacts_at_start"]) for r in ok]
    e = ci([float(r["void_ratio_after_consolidation"]) for r in ok], ".3f")
    phi = ci([float(r["peak_phi_mob_shearing_deg"]) for r in ok], ".1f")
    w = [float(r["wall_seconds"]) for r in ok]
    print(f"| {a} | {len(ok)} of {len(rs)} | {parts[0]}-{parts[-1]} | {min(c):.0f}-{max(c):.0f} | {e} | {float(ok[0]['paper_void_ratio']):.3f} | {phi} | {min(w):.0f}-{max(w):.0f} s |")
print()
rows = list(csv.DictReader(open(f"{out}/findings.csv")))
print("| # | claim | measured: mean over the seeds (95 % interval) | verdict |")
print("|---|---|---|---|")
by = {}
for r in rows: by.setdefault(r["number"], []).append(r)
for n, rs in by.items():
    cells = "<br>".join(f"{r['subject']}: {r['measured']} [{r['check_verdict']}]" for r in rs).replace("|", bar)
    claim = rs[0]["claim"].replace("|", bar)
    print(f"| {n} | {claim} | {cells} | **{rs[0]['verdict']}** |")

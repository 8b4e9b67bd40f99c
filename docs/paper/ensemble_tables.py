# Markdown tables for docs/paper-reproduction.md from a `grainlab paper --seeds N` output directory.
import csv, math, statistics as st, sys
out = sys.argv[1]
runs = list(csv.DictReader(open(f"{out}/runs.csv")))
# t_{0.975} by degrees of freedom, as engine/studies/src/paper/ensemble_stats.cpp.
T = dict(enumerate([12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160,
                    2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056,
                    2.052, 2.048, 2.045, 2.042], start=1))
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

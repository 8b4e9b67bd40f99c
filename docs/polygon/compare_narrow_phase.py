#!/usr/bin/env python3
"""Before/after statistics of a narrow-phase change over seed ensembles.

Usage: compare_narrow_phase.py BEFORE_ROOT AFTER_ROOT
Each root holds one `grainlab sweep` output per preset (runs/<id>/series.csv, summary.json),
as scripts in docs/polygon-contacts.md make them. For each preset it prints, before and after,
the mean and 95% t-interval over seeds of: peak φ_mob, the void ratio after consolidation and
at 20% axial strain, a_c and the non-coaxiality ω (omega_macro_deg) at 5% and 20% axial strain;
and Welch's t for the difference.
"""
import csv, json, math, os, sys
from statistics import mean, stdev

# Two-sided 95% Student t quantiles by degrees of freedom.
T95 = {1: 12.71, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306, 9: 2.262,
       10: 2.228, 12: 2.179, 14: 2.145, 16: 2.120, 20: 2.086, 30: 2.042}

def t95(df):
    keys = sorted(k for k in T95 if k <= df)
    return T95[keys[-1]] if keys else T95[1]

def at_strain(rows, column, target):
    """Linear interpolation of a series column at an axial strain (shearing stage only)."""
    shear = [r for r in rows if r["stage"] == "shearing" and r[column] != ""]
    for a, b in zip(shear, shear[1:]):
        ea, eb = float(a["axial_strain"]), float(b["axial_strain"])
        if ea <= target <= eb and eb > ea:
            w = (target - ea) / (eb - ea)
            return float(a[column]) * (1 - w) + float(b[column]) * w
    return None

def metrics(run_dir):
    summary = json.load(open(os.path.join(run_dir, "summary.json")))
    rows = list(csv.DictReader(open(os.path.join(run_dir, "series.csv"))))
    return {
        "peak phi_mob (deg)": summary.get("peak_phi_mob_deg"),
        "e after consolidation": summary.get("void_ratio_after_consolidation"),
        "e at 20%": at_strain(rows, "void_ratio", 0.20),
        "a_c at 5%": at_strain(rows, "a_c", 0.05),
        "a_c at 20%": at_strain(rows, "a_c", 0.20),
        "omega at 5% (deg)": at_strain(rows, "omega_macro_deg", 0.05),
        "omega at 20% (deg)": at_strain(rows, "omega_macro_deg", 0.20),
    }

def ensemble(root, preset):
    runs = os.path.join(root, preset, "runs")
    out = {}
    for run in sorted(os.listdir(runs)):
        for k, v in metrics(os.path.join(runs, run)).items():
            if v is not None:
                out.setdefault(k, []).append(v)
    return out

def interval(v):
    m = mean(v)
    h = t95(len(v) - 1) * stdev(v) / math.sqrt(len(v))
    return m, h

def main(before_root, after_root):
    presets = sorted(p for p in os.listdir(after_root) if os.path.isdir(os.path.join(after_root, p, "runs")))
    print("| preset | quantity | before: mean ± 95% (n) | after: mean ± 95% (n) | Welch t |")
    print("|---|---|---|---|---:|")
    for preset in presets:
        b, a = ensemble(before_root, preset), ensemble(after_root, preset)
        for key in b:
            vb, va = b[key], a.get(key, [])
            if len(vb) < 2 or len(va) < 2:
                continue
            mb, hb = interval(vb)
            ma, ha = interval(va)
            se = math.sqrt(stdev(vb) ** 2 / len(vb) + stdev(va) ** 2 / len(va))
            t = (ma - mb) / se if se > 0 else 0.0
            print(f"| {preset} | {key} | {mb:.4g} ± {hb:.2g} ({len(vb)}) | {ma:.4g} ± {ha:.2g} ({len(va)}) | {t:+.2f} |")

if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])

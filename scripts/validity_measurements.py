#!/usr/bin/env python3
"""The measurements behind docs/validity.md's limits, on circular-quick (seed 1):

  rate      the biaxial stage's strain_rate: the measured inertial number, how far sigma11
            strays from its 300 kPa target, the void ratio at the end;
  pressure  the consolidation pressure (compaction and consolidation only): the measured mean
            overlap over the radius and the void ratio after consolidation;
  diameter  assembly.specimen_diameter: particles across and the peak mobilised friction.

Each run is `grainlab run` of the preset with one field changed and `--force` (a scene
outside the envelope is refused; the measurement needs it run). Prints one Markdown table
per measurement.

usage: scripts/validity_measurements.py GRAINLAB OUTDIR [rate|pressure|diameter ...]
"""
import csv
import json
import math
import os
import statistics
import subprocess
import sys

GRAINLAB, OUT = sys.argv[1], sys.argv[2]
WHICH = sys.argv[3:] or ["rate", "pressure", "diameter"]


def preset():
    return json.loads(subprocess.check_output([GRAINLAB, "preset", "circular-quick"]))


def run(name, scene):
    """Runs `scene` (refusals lifted by running the stage's own preset values where needed)
    and returns (summary, series rows, contacts rows)."""
    out = os.path.join(OUT, name)
    os.makedirs(OUT, exist_ok=True)
    path = os.path.join(OUT, name + ".json")
    with open(path, "w") as f:
        json.dump(scene, f)
    p = subprocess.run([GRAINLAB, "run", path, "--out", out, "--force"], capture_output=True, text=True)
    if not os.path.exists(os.path.join(out, "summary.json")):
        return {"status": "refused", "error": p.stderr.strip()}, [], []
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    series = list(csv.DictReader(open(os.path.join(out, "series.csv"))))
    contacts = list(csv.DictReader(open(os.path.join(out, "contacts_final.csv"))))
    return summary, series, contacts


def num(row, key):
    v = row.get(key, "")
    return float(v) if v not in ("", None) else math.nan


def mean_overlap(contacts, stiffness):
    """Mean normal overlap over the mean radius, particle-particle contacts: the linear law's
    fn/k_n over |l_i| + fn/(2 k_n) (the branch vector reaches the contact point, half the
    overlap inside the radius)."""
    overlaps, radii = [], []
    for c in contacts:
        if int(c["j"]) < 0:
            continue
        d = float(c["fn"]) / stiffness
        overlaps.append(d)
        radii.append(math.hypot(float(c["lix"]), float(c["liy"])) + d / 2)
    return statistics.mean(overlaps) / statistics.mean(radii) if overlaps else math.nan


def warned(summary):
    return "; ".join(f"{w['quantity']}" + (f"@{w['step']}" if "step" in w else "") for w in summary.get("warnings", []))


def rates():
    print("| strain_rate (1/s) | I requested | I measured (median, shearing) | max abs(sigma11 - 300 kPa)/300 kPa | "
          "sigma11 at 5.5% (kPa) | void ratio at the end | warnings |")
    print("|---|---|---|---|---|---|---|")
    for rate in (1, 2.66, 4, 16):
        scene = preset()
        scene["stages"][2]["strain_rate"] = rate
        summary, series, _ = run(f"rate-{rate}", scene)
        shear = [r for r in series if r["stage"] == "shearing"][1:]
        inertial = statistics.median(num(r, "inertial_number") for r in shear)
        error = max(abs(num(r, "sigma11") - 3e5) / 3e5 for r in shear)
        at55 = min(shear, key=lambda r: abs(num(r, "axial_strain") - 0.055))
        requested = rate * 0.004 * math.sqrt(2650 / 3e5)
        print(f"| {rate} | {requested:.2g} | {inertial:.2g} | {error:.2f} | {num(at55, 'sigma11') / 1e3:.0f} | "
              f"{num(shear[-1], 'void_ratio'):.3f} | {warned(summary)} |")


def pressures():
    print("| consolidation pressure (Pa) | 2p/k_n | mean overlap / radius, measured | void ratio after consolidation | "
          "warnings |")
    print("|---|---|---|---|---|")
    for pressure in (3e5, 3e6, 3e7, 1e8):
        scene = preset()
        scene["stages"] = scene["stages"][:2]
        scene["stages"][1]["pressure"] = pressure
        summary, _, contacts = run(f"pressure-{pressure:g}", scene)
        k = scene["material"]["normal_stiffness"]
        if summary.get("status") != "completed":
            print(f"| {pressure:g} | {2 * pressure / k:.3g} | – | – | {summary.get('status')}: "
                  f"{summary.get('error', '')[:120]} |")
            continue
        print(f"| {pressure:g} | {2 * pressure / k:.3g} | {mean_overlap(contacts, k):.3g} | "
              f"{summary.get('void_ratio_after_consolidation', math.nan):.3f} | {warned(summary)} |")


def diameters():
    print("| specimen_diameter (m) | particles across | particles | peak phi_mob (deg) | warnings |")
    print("|---|---|---|---|---|")
    for diameter in (0.012, 0.02, 0.04, 0.06):
        scene = preset()
        scene["assembly"]["specimen_diameter"] = diameter
        summary, _, _ = run(f"diameter-{diameter}", scene)
        print(f"| {diameter} | {diameter / 0.004:.1f} | {summary.get('particles', '–')} | "
              f"{summary.get('peak_phi_mob_deg', math.nan):.1f} | "
              f"{summary.get('status') if summary.get('status') != 'completed' else warned(summary)} |")


for which in WHICH:
    {"rate": rates, "pressure": pressures, "diameter": diameters}[which]()
    print()

#!/usr/bin/env python3
"""The reference ensembles behind the bands of tests/run/biaxial_test.cpp and
box2d_biaxial_test.cpp: a quick preset run for seeds FIRST..LAST (not seed 1, the preset's
own seed, which the tests run), and for each quantity the 95 % prediction interval of one
more run, mean ± t_0.975(n−1) · s · √(1 + 1/n). Not run by ctest (minutes of CPU); rerun it
when the physics changes on purpose and update the tests' figures with the commit.

usage: biaxial_reference_ensemble.py GRAINLAB PRESET ENGINE [FIRST=2] [LAST=12] [WORKDIR]
"""
import csv
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

T975 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306, 9: 2.262,
        10: 2.228, 11: 2.201, 12: 2.179, 13: 2.160, 14: 2.145, 15: 2.131}


def quantities(run):
    summary = json.load(open(os.path.join(run, "summary.json")))
    shearing = [r for r in csv.DictReader(open(os.path.join(run, "series.csv"))) if r["stage"] == "shearing"]
    phi = sorted(float(r["phi_mob_deg"]) for r in shearing if float(r["axial_strain"]) > 0.02)
    within = lambda share: sum(abs(float(r["sigma11"]) - 3e5) < share * 3e5 for r in shearing) / len(shearing)
    return {
        "void ratio after consolidation": summary["void_ratio_after_consolidation"],
        "median phi_mob past 2% strain (deg)": phi[len(phi) // 2],
        "peak phi_mob (deg)": summary["peak_phi_mob_deg"],
        "share of shearing samples with sigma11 within 2%": within(0.02),
        "share within 10%": within(0.1),
    }


def main():
    grainlab, preset, engine = sys.argv[1:4]
    first = int(sys.argv[4]) if len(sys.argv) > 4 else 2
    last = int(sys.argv[5]) if len(sys.argv) > 5 else 12
    work = sys.argv[6] if len(sys.argv) > 6 else tempfile.mkdtemp()
    scene = json.loads(subprocess.run([grainlab, "preset", preset], check=True, capture_output=True, text=True).stdout)
    values = []
    for seed in range(first, last + 1):
        scene["seed"] = seed
        scene["solver"]["engine"] = engine
        path = os.path.join(work, f"{preset}-{engine}-{seed}.json")
        json.dump(scene, open(path, "w"))
        run = os.path.join(work, f"{preset}-{engine}-{seed}")
        subprocess.run([grainlab, "run", path, "--out", run], check=True, capture_output=True)
        values.append(quantities(run))
    n = len(values)
    print(f"{preset}, {engine}, seeds {first}-{last} (n = {n}):")
    for name in values[0]:
        xs = [v[name] for v in values]
        mean, sd = statistics.mean(xs), statistics.stdev(xs)
        half = T975[n - 1] * sd * math.sqrt(1 + 1 / n)
        print(f"  {name}: mean {mean:.4f}, sd {sd:.4f}, 95 % prediction interval [{mean - half:.4f}, {mean + half:.4f}]")


if __name__ == "__main__":
    main()

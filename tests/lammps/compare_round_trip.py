#!/usr/bin/env python3
"""Checks of tests/lammps/round_trip.sh on its work folder (see there)."""
import cmath
import csv
import json
import math
import sys

work = sys.argv[1]
failures = []


def check(ok, message):
    print(("ok   - " if ok else "FAIL - ") + message)
    if not ok:
        failures.append(message)


def thermo(log):
    """LAMMPS's thermo rows: step -> (pxx, pyy, pxy)."""
    rows, inside = {}, False
    for line in open(log):
        words = line.split()
        if words[:3] == ["Step", "Time", "c_stress[1]"]:
            inside = True
            continue
        if inside:
            if not words or not words[0].isdigit():
                inside = False
                continue
            rows[int(words[0])] = tuple(float(w) for w in words[2:5])
    return rows


def series(folder):
    return list(csv.DictReader(open(f"{work}/{folder}/series.csv")))


def stress_matches(name, folder, imported):
    lammps = thermo(f"{work}/{folder}/log.lammps")
    rows = series(imported)
    check(len(rows) == len(lammps) and len(rows) >= 10,
          f"{name}: {len(rows)} imported frames, {len(lammps)} LAMMPS thermo rows")
    worst = 0.0
    for row in rows:
        step = int(row["step"])
        pxx, pyy, pxy = lammps[step]
        size = math.sqrt(pxx * pxx + pyy * pyy + 2 * pxy * pxy)
        ours = (float(row["sigma11"]), float(row["sigma22"]), float(row["sigma21"]))
        worst = max(worst, max(abs(a - b) for a, b in zip(ours, (pxx, pyy, pxy))) / size)
    check(worst <= 1e-6, f"{name}: contact stress = LAMMPS's pair virial stress at every frame "
                         f"(largest difference {worst:.2e} of |sigma|)")
    return rows


walls = stress_matches("walls", "walls", "walls-imported")
periodic = stress_matches("periodic", "periodic", "periodic-imported")

# The first frame against grainlab's own analysis of the same packing.
reference = {k: float(v) for k, v in (line.split() for line in open(f"{work}/reference.txt"))}
first = walls[0]
check(int(first["contacts"]) == int(reference["contacts"]) and reference["contacts"] > 300,
      f"first frame: {first['contacts']} contacts, grainlab's analysis {int(reference['contacts'])}")
for a, theta in (("a_c", "theta_c_deg"), ("a_n", "theta_n_deg"), ("a_ln", "theta_ln_deg")):
    ours = cmath.rect(float(first[a]), 2 * math.radians(float(first[theta])))
    theirs = cmath.rect(reference[a], 2 * math.radians(reference[theta]))
    check(abs(ours - theirs) <= 1e-12 and reference[a] > 1e-6,
          f"first frame: A = {a} e^(2i {theta}) within 1e-12 ({abs(ours - theirs):.1e}; {a} = {reference[a]:.6g})")
for a in ("a_t", "a_w", "a_lt"):  # at rest: no tangential force; discs: no tangential branch
    check(abs(float(first[a]) - reference[a]) <= 1e-12, f"first frame: {a} within 1e-12 ({first[a]} vs {reference[a]})")
for q in ("f0", "l0"):
    check(abs(float(first[q]) / reference[q] - 1) <= 1e-12, f"first frame: {q} within 1e-12 relative")
size = math.hypot(reference["sigma11"], reference["sigma22"])
worst = max(abs(float(first[k]) - reference[k]) for k in ("sigma11", "sigma22", "sigma12", "sigma21")) / size
check(worst <= 1e-12, f"first frame: stress = grainlab's contactStress within 1e-12 ({worst:.1e})")

# fix deform y erate -0.5: ly = ly0 (1 - 0.5 t), so the axial strain is 0.5 t; and the cell's
# strain rate L = [[0, 1], [0, -0.5]] has D = -sym(L) with its major direction at
# 1/2 arg((D11 - D22) + 2i D12).
dt = json.load(open(f"{work}/periodic/export.json"))["timestep_s"]
worst = max(abs(float(r["axial_strain"]) - 0.5 * int(r["step"]) * dt) for r in periodic)
check(worst <= 1e-12, f"periodic: axial strain = fix deform's 0.5 t (largest difference {worst:.1e})")
d11, d22, d12 = 0.0, 0.5, -0.5
expected = math.degrees(0.5 * math.atan2(2 * d12, d11 - d22)) % 180
angles = [float(r["theta_strain_rate_deg"]) for r in periodic[1:]]
check(all(abs((a - expected + 90) % 180 - 90) < 0.05 for a in angles),
      f"periodic: strain-rate direction {expected:.3f} deg at every frame after the first (got {angles[0]:.3f} ...)")
check(all(r["omega_strain_rate_deg"] != "" for r in periodic[1:]), "periodic: omega against the cell's strain rate at every frame after the first")
check(float(periodic[-1]["a_c"]) > 0 and periodic[-1]["theta_sigma_micro_deg"] != "", "periodic: fabric and Eq. 7 measured")

sys.exit(1 if failures else 0)

#!/usr/bin/env python3
"""grainlab.read_lammps on two small dumps written here (no LAMMPS needed): the contact stress
of one known contact in closed form, the same tables as `grainlab import lammps` writes, and a
truncated last frame as a warning. Arguments: the build directory (its python/ and grainlab)."""
import os
import subprocess
import sys
import tempfile
import warnings

build = sys.argv[1]
sys.path.insert(0, os.path.join(build, "python"))
import grainlab  # noqa: E402

BOX = "ITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n-0.5 0.5\n"


def atoms(step):
    # Columns in an unusual order: the reader goes by name.
    return (f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n2\n{BOX}ITEM: ATOMS radius id x y vx vy omegaz type\n"
            "0.55 1 1 1 0 0 0 1\n0.55 2 2 1 0 0 0 1\n")


def contacts(step):
    # On atom 1: normal force −3 x̂, tangential −1 ŷ; so on atom 2 from 1: +3 x̂ + 1 ŷ, branch +1 x̂.
    return (f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ENTRIES\n1\n{BOX}"
            "ITEM: ENTRIES c_ends[1] c_ends[2] c_pairs[1] c_pairs[2] c_pairs[3] c_pairs[4] c_pairs[5]\n"
            "1 2 1 -3 0 0 -1\n")


failures = []


def check(ok, message):
    print(("ok   - " if ok else "FAIL - ") + message)
    if not ok:
        failures.append(message)


with tempfile.TemporaryDirectory() as work:
    a, c = os.path.join(work, "a.dump"), os.path.join(work, "c.dump")
    open(a, "w").write(atoms(0) + atoms(10) + atoms(20)[:-10])  # the last frame cut short
    open(c, "w").write(contacts(0) + contacts(10) + contacts(20))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        run = grainlab.read_lammps(a, c, timestep=1e-6)
    check(len(run.series) == 2, f"two whole frames read ({len(run.series)})")
    check(any("truncated" in str(w.message) for w in caught), "the truncated last frame is a warning")
    s = run.series
    # σ = (1/A) Σ f ⊗ l, force index first, over the 10 × 10 cell: σ11 = 3·1/100, σ21 = 1·1/100.
    check(abs(s["sigma11"][0] - 0.03) < 1e-15 and abs(s["sigma21"][0] - 0.01) < 1e-15 and s["sigma12"][0] == 0
          and s["sigma22"][0] == 0, f"contact stress in closed form: {s['sigma11'][0]}, {s['sigma21'][0]}")
    check(abs(s["time"][1] - 10e-6) < 1e-20, "time = step × timestep")
    check(run.contacts()["fn"][0] == 3 and run.contacts()["ft"][0] == 1, "the last frame's contact: fn 3, ft 1")
    # The same tables as the command line's import.
    out = os.path.join(work, "cli")
    subprocess.run([os.path.join(build, "grainlab"), "import", "lammps", a, c, "--out", out, "--timestep", "1e-6"],
                   check=True, capture_output=True)
    same = open(os.path.join(out, "series.csv")).read().splitlines()[1:]
    check(len(same) == 2 and all(float(x.split(",")[6]) == s["sigma11"][k] for k, x in enumerate(same)),
          "the same series as grainlab import lammps")
    try:
        grainlab.read_lammps(a)
        check(False, "a particles dump alone is refused")
    except RuntimeError as e:
        check("no dump local" in str(e), f"a particles dump alone is refused: {e}")

sys.exit(1 if failures else 0)

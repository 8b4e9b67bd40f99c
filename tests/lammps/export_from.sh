#!/usr/bin/env bash
# grainlab export lammps --from RUN_DIR:STAGE exports the specimen another run kept at the end of
# STAGE, as grainlab run --from starts from it: the data file's positions and velocities are
# that run's final particles (the end of its only stage) to the last digit, the run is the
# stages after it, and an import of its frames keeps the prepared run's clock. Argument: grainlab.
set -euo pipefail
grainlab=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 "$here/packing.py" 4 4 > "$work/relax.json"
# The same scene with a second stage: its first stage is the one the prepared run kept.
python3 -c "
import json, sys
s = json.load(open('$work/relax.json'))
s['stages'].append({'type': 'free', 'name': 'hold', 'duration': 1e-3})
json.dump(s, open('$work/two-stages.json', 'w'))"
"$grainlab" run "$work/relax.json" --out "$work/prepared" 2> /dev/null
"$grainlab" export lammps "$work/two-stages.json" --from "$work/prepared:relax" --out "$work/exported" > /dev/null
python3 - "$work" "$grainlab" <<'PY'
import csv, json, sys
work = sys.argv[1]
final = list(csv.DictReader(open(f"{work}/prepared/particles_final.csv")))
lines = open(f"{work}/exported/specimen.data").read().split("\n")
atoms = lines[lines.index("Atoms # sphere") + 2:][:len(final)]
velocities = lines[lines.index("Velocities") + 2:][:len(final)]
failures = 0
for row, atom, vel in zip(final, atoms, velocities):
    a, v = atom.split(), vel.split()
    if (float(a[4]), float(a[5])) != (float(row["x"]), float(row["y"])) or \
       (float(v[1]), float(v[2]), float(v[6])) != (float(row["vx"]), float(row["vy"]), float(row["spin"])):
        print(f"FAIL - atom {a[0]}: exported {a[4:6]} {v[1:3]} {v[6]}, prepared run ended at {row}")
        failures += 1
meta = json.load(open(f"{work}/exported/export.json"))
expected = round(1e-3 / meta["timestep_s"])
if meta["steps"] != expected:
    print(f"FAIL - {meta['steps']} steps exported, the hold stage is {expected}")
    failures += 1
if meta["start_time_s"] <= 0:
    print("FAIL - the exported specimen's clock did not start where the prepared run ended")
    failures += 1
# A frame at LAMMPS's step 0 of the exported run (written here, as LAMMPS would dump it), imported:
# its time is the prepared run's clock, where the specimen was kept.
box = "ITEM: BOX BOUNDS ff ff pp\n" + "\n".join(" ".join(l.split()[:2]) for l in lines if l.endswith(("xlo xhi", "ylo yhi", "zlo zhi"))) + "\n"
rows = "".join(f"{a.split()[0]} 1 {a.split()[4]} {a.split()[5]} {float(a.split()[2]) / 2}\n" for a in atoms)
open(f"{work}/exported/particles.dump", "w").write(
    f"ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n{len(atoms)}\n{box}ITEM: ATOMS id type x y radius\n{rows}")
open(f"{work}/exported/contacts.dump", "w").write(
    f"ITEM: TIMESTEP\n0\nITEM: NUMBER OF ENTRIES\n0\n{box}"
    "ITEM: ENTRIES c_ends[1] c_ends[2] c_pairs[1] c_pairs[2] c_pairs[3] c_pairs[4] c_pairs[5]\n")
import subprocess
subprocess.run([sys.argv[2], "import", "lammps", f"{work}/exported/particles.dump", f"{work}/exported/contacts.dump",
                "--out", f"{work}/imported"], check=True, capture_output=True)
first = next(csv.DictReader(open(f"{work}/imported/series.csv")))
prepared_end = float(list(csv.DictReader(open(f"{work}/prepared/series.csv")))[-1]["time"])
if float(first["time"]) != meta["start_time_s"] or abs(meta["start_time_s"] - prepared_end) > meta["timestep_s"]:
    print(f"FAIL - imported time {first['time']}, export's start {meta['start_time_s']}, prepared run ended at {prepared_end}")
    failures += 1
print(f"{'FAIL' if failures else 'ok  '} - {len(final)} discs exported from the prepared run's end of relax, "
      f"{meta['steps']} steps of the hold stage")
sys.exit(1 if failures else 0)
PY

#!/usr/bin/env bash
# grainlab export lammps of a scene's own periodic cell (docs/periodic-cell.md, "Against
# LAMMPS"): the data file's triclinic box is the cell, the atoms are the discs wrapped into it
# with grainlab's masses, their velocities the fluctuation plus the streaming field of the
# constant-volume biaxial stage about the box's centre, and fix deform the stage's true strain
# rates for the steps grainlab's stage takes; and a specimen kept at the end of a servo's stage
# (the cell still moving at the servo's rate) is exported, as grainlab run --from starts the next
# stage from a cell at rest. Argument: grainlab.
set -euo pipefail
grainlab=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
# Four discs in a 0.02 x 0.016 m cell, one placed outside it (wrapped in by the scene), moving.
material = {"density": 2650, "normal_stiffness": 1e7, "tangential_stiffness": 5e6, "friction": 0.5,
            "restitution": 0.5, "local_damping": 0}
particles = [{"shape": "disc", "radius": 0.002, "position": p, "velocity": v}
             for p, v in [([0.003, 0.004], [0.01, 0]), ([0.012, 0.004], [0, -0.02]),
                          ([0.007, 0.011], [0, 0]), ([0.033, 0.014], [0.005, 0.005])]]
biaxial = {"type": "biaxial", "name": "shearing", "lateral": "constant_volume", "pressure": 1e5,
           "strain_rate": 2.0, "target_axial_strain": 0.05}
json.dump({"name": "cell", "material": material, "particles": particles,
           "boundary": {"type": "periodic", "size": [0.02, 0.016]}, "stages": [biaxial]},
          open(f"{work}/cell.json", "w"))
PY
"$grainlab" export lammps "$work/cell.json" --out "$work/out" > /dev/null
python3 - "$work" <<'PY'
import json, math, sys
work = sys.argv[1]
lines = open(f"{work}/out/specimen.data").read().split("\n")
scene = json.load(open(f"{work}/cell.json"))
meta = json.load(open(f"{work}/out/export.json"))
script = open(f"{work}/out/in.grainlab").read()
failures = []
def check(ok, what):
    print(f"{'ok  ' if ok else 'FAIL'} - {what}")
    if not ok: failures.append(what)
box = {l.split()[-1]: l.split()[:-2] for l in lines if l.endswith(("xhi", "yhi", "yz"))}
check(box["xhi"] == ["0", "0.02"] and box["yhi"] == ["0", "0.016"] and box["yz"][0] == "0",
      f"the box is the cell 0.02 x 0.016 m, no tilt: {box}")
atoms = lines[lines.index("Atoms # sphere") + 2:][:4]
vels = lines[lines.index("Velocities") + 2:][:4]
L, c = (2.0, -2.0), (0.01, 0.008)
for part, atom, vel in zip(scene["particles"], atoms, vels):
    a, v = [float(x) for x in atom.split()], [float(x) for x in vel.split()]
    x = (part["position"][0] % 0.02, part["position"][1] % 0.016)
    mass = a[3] * 4 / 3 * math.pi * (a[2] / 2) ** 3
    check(abs(a[4] - x[0]) < 1e-15 and abs(a[5] - x[1]) < 1e-15 and 0 <= a[4] < 0.02,
          f"atom {int(a[0])} at ({a[4]:.6g}, {a[5]:.6g}), wrapped into the cell")
    check(abs(mass / (2650 * math.pi * 0.002 ** 2) - 1) < 1e-14, f"atom {int(a[0])}: LAMMPS's mass is ρπr²")
    want = (part["velocity"][0] + L[0] * (x[0] - c[0]), part["velocity"][1] + L[1] * (x[1] - c[1]))
    check(abs(v[1] - want[0]) < 1e-15 and abs(v[2] - want[1]) < 1e-15,
          f"atom {int(a[0])}: velocity ({v[1]:.6g}, {v[2]:.6g}) = fluctuation + L (x − centre)")
check("fix             deform all deform 1 x trate 2 y trate -2 remap v" in script,
      "fix deform: the stage's true strain rates, remap v")
check("nve/sphere disc" in script, "disc inertia ½ m r² (fix nve/sphere disc)")
dt = meta["timestep_s"]
want = math.ceil(math.log(1 - 0.05) / math.log(1 - 2.0 * dt))
check(meta["steps"] == want and (1 - 2.0 * dt) ** meta["steps"] <= 0.95 < (1 - 2.0 * dt) ** (meta["steps"] - 1),
      f"{meta['steps']} steps: grainlab's stage ends there ((1 − r dt)^n ≤ 1 − 0.05 first at n = {want})")
check(meta["boundary"] == "cell" and meta["cell_h"] == [[0.02, 0], [0, 0.016]], "export.json records the cell")
sys.exit(1 if failures else 0)
PY

# A specimen kept at the end of an isotropic stage: the cell moves at the servo's rate when it is
# kept; the biaxial stage after it starts from the cell at rest in grainlab, and so in LAMMPS.
python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
s = json.load(open(f"{work}/cell.json"))
s["stages"] = [{"type": "isotropic", "name": "squeeze", "pressure": 1e5, "strain_rate": 0.5, "max_time": 2e-3}] + s["stages"]
json.dump(s, open(f"{work}/two-stages.json", "w"))
json.dump(dict(s, stages=s["stages"][:1]), open(f"{work}/squeeze.json", "w"))
PY
"$grainlab" run "$work/squeeze.json" --out "$work/squeezed" > /dev/null 2>&1
if ! "$grainlab" export lammps "$work/two-stages.json" --from "$work/squeezed:squeeze" --out "$work/from-servo" > "$work/from-servo.log" 2>&1; then
  echo "FAIL - a specimen kept at the end of a servo's stage is refused: $(cat "$work/from-servo.log")"
  exit 1
fi
grep -q "x trate 2 y trate -2 remap v" "$work/from-servo/in.grainlab" ||
  { echo "FAIL - from the squeezed specimen: no fix deform at the biaxial stage's rates"; exit 1; }
echo "ok   - a specimen kept while the servo moved the cell is exported, at the next stage's rates"

#!/usr/bin/env bash
# The material mapping (docs/lammps.md) on two-disc collisions run by LAMMPS from grainlab's
# export, against the closed form and against grainlab's own engine (compare_collision.py):
#  - head-on, equal discs: LAMMPS's rebound equals grainlab's to rounding, and converges to
#    the closed form e (the mapped damping γ = 2ζ√(k/m*) gives restitution e exactly in
#    continuous time) at first order in the timestep;
#  - oblique, with spin and friction: LAMMPS's velocities and spins after the collision equal
#    grainlab's, within what the two contact models differ by (see compare_collision.py).
# Arguments: grainlab, lmp.
set -euo pipefail
grainlab=$1 lmp=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for case in head-on:0.5:200 head-on:0.5:2000 oblique:1.0:200 oblique:0.5:200; do
  IFS=: read -r shape e steps_per_contact <<< "$case"
  name=$shape-$e-$steps_per_contact
  python3 "$here/compare_collision.py" scene "$shape" "$e" "$steps_per_contact" > "$work/$name.json"
  "$grainlab" run "$work/$name.json" --out "$work/$name-grainlab" 2> "$work/$name-grainlab.log"
  steps=$(python3 -c "import json; print(json.load(open('$work/$name-grainlab/summary.json'))['steps'])")
  "$grainlab" export lammps "$work/$name.json" --out "$work/$name-lammps" --steps "$steps" --dump-every "$steps" \
    > /dev/null
  if ! (cd "$work/$name-lammps" && "$lmp" -in in.grainlab -log log.lammps > run.out 2>&1); then
    tail -20 "$work/$name-lammps/run.out" >&2
    echo "FAIL: LAMMPS failed on $name" >&2
    exit 1
  fi
  "$grainlab" import lammps "$work/$name-lammps/particles.dump" "$work/$name-lammps/contacts.dump" \
    --out "$work/$name-imported" > /dev/null
done
python3 "$here/compare_collision.py" check "$work"

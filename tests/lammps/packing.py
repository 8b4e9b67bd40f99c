#!/usr/bin/env python3
"""A small compressed disc packing in a box of four walls, as a grainlab scene, for the LAMMPS
round trip (tests/lammps/round_trip.sh). A triangular lattice of slightly polydisperse discs
whose neighbours overlap by about 1% of a diameter, jittered so that the contact normals spread,
at rest, no gravity: the first frame's contact forces are all spring forces. Restitution 1 (no
dashpot): LAMMPS's compute pair/local re-evaluates a pair's force at the end of the step, with
the end-of-step velocities where the step used the half-step ones, so only a material without
a velocity-dependent normal force dumps exactly the forces LAMMPS applied (docs/lammps.md).
Usage: packing.py COLUMNS ROWS > scene.json"""
import json
import math
import random
import sys

columns, rows = int(sys.argv[1]), int(sys.argv[2])
a = 0.002  # m: lattice spacing
h = a * math.sqrt(3) / 2
rng = random.Random(7)
particles = []
for row in range(rows):
    shift = 0.5 * a * (row % 2)
    for col in range(columns - (row % 2)):
        r = 0.5 * a * 1.01 * (1 + 0.004 * (rng.random() - 0.5))
        x = (col + 0.5) * a + shift + 0.002 * a * (rng.random() - 0.5)
        y = (row + 0.5) * h + 0.002 * a * (rng.random() - 0.5)
        particles.append({"shape": "disc", "radius": r, "position": [x, y]})
width, height = columns * a, rows * h
scene = {
    "name": "lammps-round-trip",
    "material": {"density": 2650, "normal_stiffness": 1e7, "tangential_stiffness": 5e6, "friction": 0.5,
                 "restitution": 1.0, "local_damping": 0},
    "particles": particles,
    "walls": [{"point": [0, 0], "normal": [0, 1]}, {"point": [0, height], "normal": [0, -1]},
              {"point": [0, 0], "normal": [1, 0]}, {"point": [width, 0], "normal": [-1, 0]}],
    "stages": [{"type": "free", "name": "relax", "duration": 2e-3}],
    "output": {"sample_interval": 1e-4},
}
json.dump(scene, sys.stdout, indent=1)

"""Write a grainlab scene of a small pile of elongated hexagons, the same construction as
`grainlab bench --scene polygon-pile` (engine/src/bench_scenes.cpp) but with Python's random
numbers and fewer columns and rows: hexagons with vertices (a cos t, b sin t), a = 1.25 s,
b = a / 1.5, s = 2 mm x U(0.9, 1.1), random angle, dropped between three walls and left to
settle for 0.3 s.

    python3 pile_scene.py COLUMNS ROWS > pile.json
"""
import json
import math
import random
import sys


def pile(columns, rows, seed=1):
    rng = random.Random(seed)
    r = 0.002
    spacing = 2.25 * r * 1.25
    particles = []
    for row in range(rows):
        for col in range(columns):
            size = r * (0.9 + 0.2 * rng.random())
            a = 1.25 * size
            b = a / 1.5
            particles.append({
                "shape": "polygon",
                "position": [(col + 0.5 * (row % 2)) * spacing, (row + 0.6) * spacing],
                "vertices": [[a * math.cos(k * math.pi / 3), b * math.sin(k * math.pi / 3)]
                             for k in range(6)],
                "angle": math.pi * rng.random(),
            })
    width = (columns + 0.5) * spacing
    return {
        "name": f"polygon-pile-{columns}x{rows}",
        "seed": seed,
        "gravity": [0, -9.81],
        "material": {"normal_stiffness": 3e8, "tangential_stiffness": 1.5e8,
                     "restitution": 0.5, "friction": 0.5},
        "walls": [{"point": [0, 0], "normal": [0, 1]},
                  {"point": [-0.5 * spacing, 0], "normal": [1, 0]},
                  {"point": [width, 0], "normal": [-1, 0]}],
        "particles": particles,
        "stages": [{"type": "free", "name": "settling", "duration": 0.3}],
    }


if __name__ == "__main__":
    json.dump(pile(int(sys.argv[1]), int(sys.argv[2])), sys.stdout, indent=1)
    print()

"""Export a settled grainlab polygon pile as a LAMMPS body/rounded/polygon data file and
input script, and check the geometry LAMMPS will see.

    python3 export_pile.py SCENE.json RUN_DIR/particles_final.csv OUT_DIR [--rounding R]
        [--no-shrink] [--steps N] [--ct C]

SCENE.json gives each particle's outline (body frame) and the walls; particles_final.csv
gives where each particle ended (x, y, angle). The outline is shrunk by the rounding radius
R (default 1e-5 m) so that the rounded body has grainlab's outline; --no-shrink keeps the
outline as the core, so every contact's rounded shells overlap by the whole rounding
diameter (the input error this directory is about). Prints the smallest gap between the
cores of two particles (negative: the cores intersect) in units of the rounding diameter.
"""
import argparse
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bodies import (Body, area_centroid_inertia, core_gap, placed_core, shrink,  # noqa: E402
                    write_data)

INPUT = """# {n} elongated hexagons of a settled grainlab pile, exported by export_pile.py
units si
dimension 2
boundary f f p
atom_style body rounded/polygon 1 6
atom_modify map array
read_data data.pile
# c_n from restitution 0.5 for two bodies of the mean mass: 2 zeta sqrt(k m / 2),
# zeta = -ln e / sqrt(pi^2 + ln^2 e); no cohesion (k_na = 0), cohesion range 1e-7 m
# tangential: only a viscous force -c_t v_t (this version has no Coulomb friction)
pair_style body/rounded/polygon {c_n:.6g} {c_t:.6g} 0.0 1.0 1e-7
pair_coeff * * 3e8 0.0
comm_modify vel yes
neighbor 5e-4 bin
neigh_modify every 1 delay 0 check yes
timestep 1e-6
fix 1 all nve/body
fix 2 all enforce2d
fix 3 all gravity 9.81 vector 0 -1 0
fix 4 all wall/body/polygon 3e8 {c_n:.6g} 0.0 yplane 0.0 NULL
fix 5 all wall/body/polygon 3e8 {c_n:.6g} 0.0 xplane {xlo!r} {xhi!r}
variable speed atom sqrt(vx*vx+vy*vy)
compute vmax all reduce max v_speed
compute ymin all reduce min y
compute ymax all reduce max y
thermo_style custom step ke pe c_vmax c_ymin c_ymax
thermo {thermo}
thermo_modify flush yes
run {steps}
"""


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("particles")
    p.add_argument("out")
    p.add_argument("--rounding", type=float, default=1e-5)
    p.add_argument("--no-shrink", action="store_true")
    p.add_argument("--steps", type=int, default=10000)
    p.add_argument("--ct", type=float, default=0.0, help="c_t, N s/m (default 0)")
    args = p.parse_args()
    scene = json.load(open(args.scene))
    rows = list(csv.DictReader(open(args.particles)))
    bodies = []
    for spec, row in zip(scene["particles"], rows):
        outline = [tuple(v) for v in spec["vertices"]]
        body = Body(outline, args.rounding, float(row["x"]), float(row["y"]), float(row["angle"]))
        if args.no_shrink:  # the core is the outline itself: grow it so shrink() returns it
            body.outline = shrink(outline, -args.rounding)
        bodies.append(body)
    walls = scene["walls"]
    xlo = next(w["point"][0] for w in walls if w["normal"] == [1, 0])
    xhi = next(w["point"][0] for w in walls if w["normal"] == [-1, 0])
    top = max(b.y for b in bodies) + 0.01
    os.makedirs(args.out, exist_ok=True)
    write_data(os.path.join(args.out, "data.pile"), bodies, (xlo - 0.005, xhi + 0.005, -0.005, top),
               f"grainlab pile, {len(bodies)} hexagons, rounding radius {args.rounding!r} m"
               + (", cores not shrunk" if args.no_shrink else ""))
    e = 0.5
    zeta = -math.log(e) / math.sqrt(math.pi ** 2 + math.log(e) ** 2)
    mass = sum(2650 * area_centroid_inertia(spec["vertices"])[0]
               for spec in scene["particles"]) / len(bodies)
    c_n = 2 * zeta * math.sqrt(3e8 * mass / 2)
    with open(os.path.join(args.out, "in.pile"), "w") as f:
        f.write(INPUT.format(n=len(bodies), c_n=c_n, c_t=args.ct, xlo=xlo, xhi=xhi, steps=args.steps,
                             thermo=max(1, args.steps // 10)))
    cores = [placed_core(b) for b in bodies]
    reach = [max(math.hypot(x, y) for x, y in b.outline) for b in bodies]
    worst, intersecting, touching = math.inf, 0, 0
    for i in range(len(bodies)):
        for j in range(i + 1, len(bodies)):
            if math.hypot(bodies[i].x - bodies[j].x, bodies[i].y - bodies[j].y) > reach[i] + reach[j]:
                continue
            g = core_gap(cores[i], cores[j])
            if g is None:
                intersecting += 1
                worst = -math.inf
                continue
            worst = min(worst, g)
            if g < 2 * args.rounding:
                touching += 1
    print(f"{len(bodies)} bodies; pairs whose rounded shells overlap: {touching}; pairs whose "
          f"cores intersect: {intersecting}; smallest core gap / rounding diameter: "
          f"{worst / (2 * args.rounding):.6g}; c_n = {c_n:.6g} N s/m")


if __name__ == "__main__":
    main()

"""Which pairs of polygons make LAMMPS's pair style body/rounded/polygon abort.

Each case is two bodies at rest, written by bodies.py, and a `run 0` (the abort, when it
comes, is in the first force computation). Prints a markdown table; docs/benchmarks.md
quotes it.

    python3 sweep.py              (needs `lmp` on the PATH; about a minute)
    python3 sweep.py --random N   N pairs at random angles whose cores stay apart
"""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import random  # noqa: E402

from bodies import Body, core_gap, hexagon, rectangle, rotate, shrink, write_data  # noqa: E402

INPUT = """units {units}
dimension 2
boundary p p p
atom_style body rounded/polygon 1 6
atom_modify map array
read_data data
pair_style body/rounded/polygon 0.0 0.0 0.0 1.0 {cut_inner}
pair_coeff * * 3e8 0.0
comm_modify vel yes
neighbor {skin} bin
fix 1 all nve/body
fix 2 all enforce2d
thermo_style custom step pe
run 0
"""


def triangle(a):
    """Equilateral triangle, circumradius a, apex up, counterclockwise."""
    return [(a * math.cos(t), a * math.sin(t))
            for t in (math.pi / 2, math.pi / 2 + 2 * math.pi / 3, math.pi / 2 + 4 * math.pi / 3)]


def run(bodies, scale, units):
    with tempfile.TemporaryDirectory() as d:
        write_data(os.path.join(d, "data"), bodies,
                   (-0.02 * scale, 0.02 * scale, -0.02 * scale, 0.02 * scale), "sweep case")
        with open(os.path.join(d, "in"), "w") as f:
            f.write(INPUT.format(units=units, cut_inner=1e-7 * scale, skin=5e-4 * scale))
        p = subprocess.run(["lmp", "-in", "in", "-log", "none", "-nocite"], cwd=d,
                           capture_output=True, text=True)
    out = p.stdout + p.stderr
    if "stack smashing detected" in out:
        return "**aborts**: stack smashing detected"
    if p.returncode != 0:
        return f"fails, exit code {p.returncode}"
    lines = out.splitlines()
    pe = next(lines[k + 1].split()[1] for k, l in enumerate(lines) if l.split()[:2] == ["Step", "PotEng"])
    return f"runs (step-0 energy {float(pe):.3g})"


def cases():
    """(description, overlap / rounding diameter, bodies, scale, units)"""
    size = 0.002  # the pile's nominal particle size (m)
    a, scale = 1.25 * size, 1.0
    for rr in (1e-5, 1e-4, 1e-6):
        for frac in ((0.5, 0.99, 0.999, 1.0, 1.001, 1.5, 3.0) if rr == 1e-5 else (0.99, 1.001)):
            h = hexagon(a, a / 1.5)
            ymax = a / 1.5 * math.sin(math.pi / 3)
            yield (f"hexagons, long faces, corners aligned, r = {rr:g} m", frac,
                   [Body(h, rr, 0, 0), Body(h, rr, 0, 2 * ymax - 2 * rr * frac)], scale, "si")
    rr = 1e-5
    h = hexagon(a, a / 1.5)
    ymax = a / 1.5 * math.sin(math.pi / 3)
    for shift in (1e-9, 1e-5, 0.25 * a):
        for frac in (1.001, 1.5):
            yield (f"hexagons, long faces, one shifted {shift:g} m along the face, r = 1e-05 m",
                   frac, [Body(h, rr, 0, 0), Body(h, rr, shift, 2 * ymax - 2 * rr * frac)],
                   scale, "si")
    for frac in (0.5, 1.001, 1.5, 3.0):
        yield ("hexagon vertex into the other's long face, r = 1e-05 m", frac,
               [Body(h, rr, 0, 0), Body(h, rr, 0, ymax + a - 2 * rr * frac, -math.pi / 2)],
               scale, "si")
    r4 = rectangle(a, a / 1.5)
    for frac in (0.99, 1.001):
        yield ("rectangles (4 vertices), long faces, corners aligned, r = 1e-05 m", frac,
               [Body(r4, rr, 0, 0), Body(r4, rr, 0, 2 * a / 1.5 - 2 * rr * frac)], scale, "si")
    t3 = triangle(a)
    down = [(x, -y) for x, y in reversed(t3)]
    for frac in (0.99, 1.001):
        yield ("triangles (3 vertices), faces, corners aligned, r = 1e-05 m", frac,
               [Body(down, rr, 0, 0), Body(t3, rr, 0, a - 2 * rr * frac)], scale, "si")
    k = 1000.0  # the same hexagons in units where a particle is about 2.5 long
    hk = hexagon(a * k, a * k / 1.5)
    for frac in (0.99, 1.0, 1.001, 1.5):
        yield ("hexagons as the first rows, lengths x 1000, `units lj`", frac,
               [Body(hk, rr * k, 0, 0), Body(hk, rr * k, 0, (2 * ymax - 2 * rr * frac) * k)],
               k, "lj")


def random_pairs(count, seed=1):
    """Hexagons at random angles, the second moved along a random direction until the gap
    between the cores is (1 - f) rounding diameters: the rounded outlines overlap by f of
    the diameter, f < 1, so the cores stay apart."""
    rng = random.Random(seed)
    a = 1.25 * 0.002
    h = hexagon(a, a / 1.5)
    tally = {}
    for _ in range(count):
        rr = rng.choice([1e-6, 1e-5, 1e-4])
        frac = rng.choice([0.01, 0.5, 0.9, 0.999])
        ai, aj = rng.uniform(0, math.pi), rng.uniform(0, math.pi)
        th = rng.uniform(0, 2 * math.pi)
        ci, cj = rotate(shrink(h, rr), ai), rotate(shrink(h, rr), aj)
        gap = 2 * rr * (1 - frac)

        def apart(s):
            g = core_gap([(x + s * math.cos(th), y + s * math.sin(th)) for x, y in ci], cj)
            return g is not None and g >= gap

        lo, hi = 0.0, 4 * a
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            lo, hi = (lo, mid) if apart(mid) else (mid, hi)
        bodies = [Body(h, rr, 0, 0, aj), Body(h, rr, hi * math.cos(th), hi * math.sin(th), ai)]
        outcome = run(bodies, 1.0, "si").split(" (")[0]
        tally[(frac, outcome)] = tally.get((frac, outcome), 0) + 1
    print("| overlap / rounding diameter | LAMMPS | pairs |")
    print("|---:|---|---:|")
    for (frac, outcome), n in sorted(tally.items()):
        print(f"| {frac:g} | {outcome} | {n} |")


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--random":
        random_pairs(int(sys.argv[2]))
        return
    print("| case | overlap / rounding diameter | LAMMPS |")
    print("|---|---:|---|")
    for text, frac, bodies, scale, units in cases():
        print(f"| {text} | {frac:g} | {run(bodies, scale, units)} |", flush=True)


if __name__ == "__main__":
    main()

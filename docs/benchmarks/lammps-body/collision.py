"""Two elongated hexagons (the pile's mean size) meet head on at 0.1 m/s each, and the
rebound is measured: face to face (a hexagon 0.8 times as large lands centred on the long
face of the other, so its two face vertices touch that face and nothing turns), and a
vertex into a long face (centred). Writes data.collision-face, data.collision-vertex and in.collision, runs LAMMPS on
each, and prints the coefficient of restitution it gives next to what a linear spring and
dashpot predicts for the number of contacts the pair style applies the force at.

    python3 collision.py        (writes into this directory; needs `lmp` on the PATH)
"""
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bodies import Body, area_centroid_inertia, hexagon, write_data  # noqa: E402

K_N = 3e8          # N/m, grainlab's normal stiffness for the pile
RESTITUTION = 0.5  # grainlab's restitution for the pile
ROUNDING = 1e-5    # m
SPEED = 0.1        # m/s, each body
GAP = 1e-6         # m between the rounded outlines at the start
CUT_INNER = (1e-11, 1e-7)  # m: the pair style damps until the shells are this far apart

INPUT = """# two hexagons meeting head on; written by collision.py
variable data index data.collision-face
units si
dimension 2
boundary p p p
atom_style body rounded/polygon 1 6
atom_modify map array
read_data ${{data}}
variable cut_inner index {cut_inner!r}
variable mu index 0.0
pair_style body/rounded/polygon {c_n!r} 0.0 ${{mu}} 1.0 ${{cut_inner}}
pair_coeff * * {k_n!r} 0.0
comm_modify vel yes
neighbor 5e-4 bin
neigh_modify every 1 delay 0 check yes
timestep 1e-8
fix 1 all nve/body
fix 2 all enforce2d
variable v1 equal vy[1]
variable v2 equal vy[2]
thermo_style custom step ke pe v_v1 v_v2
thermo_modify format float %.10g
thermo 1000
run 5000
"""


def main():
    size = 0.002
    a = 1.25 * size
    b = a / 1.5
    h = hexagon(a, b)
    mass = 2650 * area_centroid_inertia(h)[0]
    m_eff = mass / 2
    zeta = -math.log(RESTITUTION) / math.sqrt(math.pi ** 2 + math.log(RESTITUTION) ** 2)
    c_n = 2 * zeta * math.sqrt(K_N * m_eff)  # one contact gives RESTITUTION
    ymax = b * math.sin(math.pi / 3)
    small = hexagon(0.8 * a, 0.8 * b)
    cases = {  # name: bodies, effective mass, contacts the force acts at
        "face": ([Body(h, ROUNDING, 0, 0, vy=SPEED),
                  Body(small, ROUNDING, 0, 1.8 * ymax + GAP, vy=-SPEED)],
                 mass * 0.64 * mass / (1.64 * mass), 2),
        "vertex": ([Body(h, ROUNDING, 0, 0, vy=SPEED),
                    Body(h, ROUNDING, 0, ymax + a + GAP, -math.pi / 2, vy=-SPEED)],
                   m_eff, 1),
    }
    with open(os.path.join(HERE, "in.collision"), "w") as f:
        f.write(INPUT.format(c_n=c_n, k_n=K_N, cut_inner=CUT_INNER[0]))
    print(f"mass {mass:.6g} kg/m, c_n {c_n:.6g} N s/m (restitution {RESTITUTION} for one "
          f"contact between two such bodies)")
    # (case, cut_inner, mu): mu = 0.5 shows what the pair style's mu does (a normal
    # force 1 + mu times the spring's, so a spring (1 + mu) k_n)
    runs = [(c, x, 0.0) for x in CUT_INNER for c in cases.items()]
    runs.append((("vertex", cases["vertex"]), CUT_INNER[0], 0.5))
    for (name, (bodies, pair_mass, contacts)), cut, mu in runs:
        data = f"data.collision-{name}"
        write_data(os.path.join(HERE, data), bodies, (-0.01, 0.01, -0.01, 0.01),
                   f"two hexagons, {name} collision, written by collision.py")
        p = subprocess.run(["lmp", "-var", "data", data, "-var", "cut_inner", repr(cut),
                            "-var", "mu", repr(mu), "-in",
                            "in.collision", "-log", "none", "-nocite"], cwd=HERE,
                           capture_output=True, text=True, check=True)
        rows = [l.split() for l in p.stdout.splitlines()]
        start = next(k for k, r in enumerate(rows) if r[:1] == ["Step"])
        table = []
        for r in rows[start + 1:]:
            if not r or not r[0].isdigit():
                break
            table.append(r)
        last = table[-1]
        v1, v2 = float(last[3]), float(last[4])
        e = (v2 - v1) / (2 * SPEED)
        # n contacts, each with k_n and c_n, act like one spring n k_n and one dashpot n c_n
        z = contacts * c_n / (2 * math.sqrt(contacts * (1 + mu) * K_N * pair_mass))
        expected = math.exp(-z * math.pi / math.sqrt(1 - z * z))
        print(f"{name}, cut_inner {cut:g} m, mu {mu:g}: after the collision v1 = {v1:.6g}, v2 = {v2:.6g} m/s, restitution "
              f"{e:.4f}; a spring-dashpot with the force at {contacts} contact(s)"
              f"{' and stiffness (1 + mu) k_n' if mu else ''}: "
              f"{expected:.4f}")


if __name__ == "__main__":
    main()

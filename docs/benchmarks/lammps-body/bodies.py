"""Write LAMMPS body/rounded/polygon data files and input scripts for a few polygons.

Used to find the smallest input that makes LAMMPS's pair style body/rounded/polygon
abort (see docs/benchmarks.md, "LAMMPS body/rounded/polygon"). Plain Python 3, no imports
beyond the standard library.
"""
import math


def hexagon(a, b):
    """The elongated hexagon grainlab's polygon pile uses: vertices (a cos t, b sin t),
    t = 0, 60, ..., 300 degrees, counterclockwise."""
    return [(a * math.cos(k * math.pi / 3), b * math.sin(k * math.pi / 3)) for k in range(6)]


def rectangle(a, b):
    """A 2a x 2b rectangle, counterclockwise."""
    return [(a, -b), (a, b), (-a, b), (-a, -b)]


def shrink(vertices, r):
    """Move every edge of a convex counterclockwise polygon inwards by r, so that the
    polygon rounded by a disc of radius r has the original polygon's outline on its flat
    faces (the body style puts a disc of the rounding radius on every vertex)."""
    n = len(vertices)
    lines = []
    for k in range(n):
        (x0, y0), (x1, y1) = vertices[k], vertices[(k + 1) % n]
        tx, ty = x1 - x0, y1 - y0
        length = math.hypot(tx, ty)
        nx, ny = ty / length, -tx / length  # outward normal of a counterclockwise polygon
        lines.append((nx, ny, nx * x0 + ny * y0 - r))
    out = []
    for k in range(n):
        (n0x, n0y, c0), (n1x, n1y, c1) = lines[k - 1], lines[k]
        det = n0x * n1y - n0y * n1x
        out.append(((c0 * n1y - c1 * n0y) / det, (n0x * c1 - n1x * c0) / det))
    return out


def area_centroid_inertia(vertices):
    """Area, centroid and the second moments about the centroid (Ixx = int y^2, Iyy =
    int x^2, Ixy = int x y) of a simple polygon, per unit density."""
    n = len(vertices)
    a = cx = cy = sxx = syy = sxy = 0.0
    for k in range(n):
        (x0, y0), (x1, y1) = vertices[k], vertices[(k + 1) % n]
        c = x0 * y1 - x1 * y0
        a += c / 2
        cx += (x0 + x1) * c / 6
        cy += (y0 + y1) * c / 6
        sxx += (y0 * y0 + y0 * y1 + y1 * y1) * c / 12
        syy += (x0 * x0 + x0 * x1 + x1 * x1) * c / 12
        sxy += (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) * c / 24
    cx /= a
    cy /= a
    return a, (cx, cy), (sxx - a * cy * cy, syy - a * cx * cx, sxy - a * cx * cy)


def rotate(vertices, angle):
    c, s = math.cos(angle), math.sin(angle)
    return [(c * x - s * y, s * x + c * y) for x, y in vertices]


class Body:
    """One polygon: its outline (counterclockwise, about its own centroid), the rounding
    radius, where it is and how it is turned."""

    def __init__(self, outline, rounding, x, y, angle=0.0, vx=0.0, vy=0.0, density=2650.0):
        self.outline, self.rounding = outline, rounding
        self.x, self.y, self.angle, self.vx, self.vy = x, y, angle, vx, vy
        self.density = density


def write_data(path, bodies, box, comment):
    """A data file for atom_style body rounded/polygon: the vertices are the outline shrunk
    by the rounding radius, in the space frame; the inertia is the space-frame tensor of the
    rounded outline's plate (mass and inertia per unit thickness, as grainlab's 2D)."""
    lines = [comment, "", f"{len(bodies)} atoms", f"{len(bodies)} bodies", "1 atom types",
             f"{box[0]!r} {box[1]!r} xlo xhi", f"{box[2]!r} {box[3]!r} ylo yhi",
             "-0.5 0.5 zlo zhi", "", "Atoms", ""]
    records = []
    for i, b in enumerate(bodies, start=1):
        area, (cx, cy), (ixx, iyy, ixy) = area_centroid_inertia(b.outline)
        assert abs(cx) < 1e-12 and abs(cy) < 1e-12, "outline must be about its centroid"
        mass = b.density * area
        # space-frame plate tensor: I_xx = m<y^2>, I_yy = m<x^2>, I_zz = sum, I_xy = -m<xy>
        c, s = math.cos(b.angle), math.sin(b.angle)
        jxx = c * c * ixx + s * s * iyy + 2 * c * s * ixy  # int y'^2 after turning
        jyy = s * s * ixx + c * c * iyy - 2 * c * s * ixy
        jxy = c * s * (iyy - ixx) + (c * c - s * s) * ixy
        inertia = [b.density * jxx, b.density * jyy, b.density * (jxx + jyy),
                   -b.density * jxy, 0.0, 0.0]
        core = rotate(shrink(b.outline, b.rounding), b.angle)
        lines.append(f"{i} 1 1 {mass!r} {b.x!r} {b.y!r} 0.0")
        rec = [f"{i} 1 {6 + 3 * len(core) + 1}", f"{len(core)}",
               " ".join(repr(v) for v in inertia)]
        rec += [f"{x!r} {y!r} 0.0" for x, y in core]
        rec.append(repr(2 * b.rounding))
        records += rec
    lines += ["", "Velocities", ""]
    lines += [f"{i} {b.vx!r} {b.vy!r} 0.0 0.0 0.0 0.0" for i, b in enumerate(bodies, start=1)]
    lines += ["", "Bodies", ""] + records + [""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


# ---- geometry checks of an exported arrangement -------------------------------------

def _segment_distance(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)
    t = max(0.0, min(1.0, t))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def _inside(p, poly):
    n = len(poly)
    return all((poly[(k + 1) % n][0] - poly[k][0]) * (p[1] - poly[k][1])
               - (poly[(k + 1) % n][1] - poly[k][1]) * (p[0] - poly[k][0]) >= 0
               for k in range(n))


def core_gap(p, q):
    """Distance between two convex counterclockwise polygons; None if they intersect."""
    if any(_inside(v, q) for v in p) or any(_inside(v, p) for v in q):
        return None
    n, m = len(p), len(q)
    return min(min(_segment_distance(v, q[k], q[(k + 1) % m]) for v in p for k in range(m)),
               min(_segment_distance(v, p[k], p[(k + 1) % n]) for v in q for k in range(n)))


def placed_core(body):
    return [(body.x + x, body.y + y) for x, y in rotate(shrink(body.outline, body.rounding),
                                                        body.angle)]

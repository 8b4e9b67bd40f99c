"""grainlab's micromechanical analysis on arrays: the engine's own estimators
(engine/analysis, engine/src/stress.cpp, docs/micromechanics.md), so contact dumps from
another code (LAMMPS, YADE) go through the same checked formulas as grainlab's own runs.

Contacts are a table (numpy structured array, pandas DataFrame or dict of arrays) with the
columns of contacts_final.csv: i, j, px, py, nx, ny, fn, ft (n the unit normal from i to j,
the force on j from i fn·n + ft·t with t = n turned +90°, fn > 0 in compression; j < 0 for a
wall), and lix, liy, ljx, ljy when no particle table is given. Units are the caller's (SI
in grainlab: N/m, m, Pa)."""
import numpy as np

from . import _grainlab
from ._tables import as_columns

_CONTACT_COLUMNS = ("i", "j", "px", "py", "nx", "ny", "fn", "ft")


def _geometry(contacts, particles, inside):
    """The contact columns, the centroids (n, 2) and the inside flags (n) for the engine."""
    c = as_columns(contacts)
    missing = [k for k in _CONTACT_COLUMNS if k not in c]
    if missing:
        raise ValueError(f"contacts: missing columns {', '.join(missing)}")
    columns = {k: np.ascontiguousarray(c[k], dtype=np.int64 if k in ("i", "j") else np.float64)
               for k in _CONTACT_COLUMNS}
    i, j = columns["i"], columns["j"]
    if particles is not None:
        p = as_columns(particles)
        centroids = np.column_stack([np.asarray(p["x"], np.float64), np.asarray(p["y"], np.float64)])
        flags = (np.asarray(p["boundary"]) == 0) if "boundary" in p else np.ones(len(centroids), bool)
    else:
        # The centroids from the branch vectors: x_i = p − l_i (the particles that touch nothing
        # play no part). Every particle counts unless `inside` says otherwise.
        if not all(k in c for k in ("lix", "liy", "ljx", "ljy")):
            raise ValueError("contacts: without a particle table the columns lix, liy, ljx, ljy are needed")
        # Particles after the last one that touches anything have no contact to place them:
        # they still count for `inside`, at a centroid that no contact uses.
        n = int(max(i.max(initial=-1), j.max(initial=-1))) + 1
        if inside is not None:
            n = max(n, len(inside))
        centroids = np.zeros((n, 2))
        point = np.column_stack([columns["px"], columns["py"]])
        centroids[i] = point - np.column_stack([c["lix"], c["liy"]]).astype(np.float64)
        particle = j >= 0
        centroids[j[particle]] = (point - np.column_stack([c["ljx"], c["ljy"]]).astype(np.float64))[particle]
        flags = np.ones(n, bool)
    if inside is not None:
        flags = np.asarray(inside, bool)
    return columns, np.ascontiguousarray(centroids), np.ascontiguousarray(flags, dtype=np.uint8)


def stress(contacts, area, particles=None, inside=None, cell=None):
    """The contact stress σ_ij = (1/A) Σ_ends f_i l_j over the contact ends of the particles
    inside the specimen (force index first, compression positive). ``area``: the measured
    region's area (the series' `area` column in grainlab). ``particles``: a table with x, y and
    optionally boundary (boundary particles are outside); without it the centroids come from
    the branch vectors and every particle is inside. ``inside``: per-particle flags that
    override both. ``cell``: a periodic cell's h (2×2, columns the edges; Run.cell): each
    branch vector then runs from the nearest image of its particle's centroid, so a contact
    across an edge counts with the branch it acts through (``area`` is then det h).
    Returns {"sigma11", "sigma22", "sigma12", "sigma21", "p", "q"}."""
    columns, centroids, flags = _geometry(contacts, particles, inside)
    return _grainlab.contact_stress(columns, centroids, flags, float(area), cell)


def anisotropy(contacts, particles=None, inside=None, cell=None):
    """The anisotropy of contact normals, forces and branch vectors (paper Eqs. 2-4) by the
    second-order estimators of docs/micromechanics.md: a_c, theta_c_deg, a_n, theta_n_deg, a_t,
    theta_t_deg, a_w (moment equilibrium), a_ln, theta_ln_deg, a_lt, theta_lt_deg, f0, l0,
    a_w_direct, lt0_ratio, ends, contacts. Directions in degrees in [0, 180).
    ``particles``, ``inside`` and ``cell`` as for stress()."""
    columns, centroids, flags = _geometry(contacts, particles, inside)
    return _grainlab.fabric(columns, centroids, flags, cell)


def theta_sigma(stress=None, fabric=None, method="eq7"):
    """The major principal stress direction in degrees, [0, 180). From a stress dict (the
    output of stress(), or any dict with sigma11, sigma12, sigma21, sigma22):
    ½ atan2(σ12 + σ21, σ11 − σ22). From an anisotropy dict: ``method`` "eq7" (paper Eq. 7, all
    five terms), "eq10" (unweighted mean of θ_c, θ_n, θ_t), "eq11" (Eq. 7 without the branch
    terms) or "sff" (the exact stress-force-fabric closed form). Give one of the two."""
    if (stress is None) == (fabric is None):
        raise ValueError("theta_sigma: give either stress= or fabric=")
    if stress is not None:
        return _grainlab.theta_sigma_macro(dict(stress))
    return _grainlab.theta_sigma_fabric(dict(fabric), method)


def omega(theta_sigma_deg, theta_strain_rate_deg=90.0):
    """Non-coaxiality ω = θσ − θ_ε̇ wrapped into [−90, 90) degrees (θ_ε̇ = 90° in the biaxial test)."""
    return _grainlab.omega(float(theta_sigma_deg), float(theta_strain_rate_deg))


def phi_mob(stress):
    """Mobilised friction angle in degrees from a stress dict's symmetric part."""
    return _grainlab.phi_mob(dict(stress))

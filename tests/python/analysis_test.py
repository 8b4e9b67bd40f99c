"""grainlab's analysis functions on the CLI's contacts_final.csv reproduce the run's own last
series row (the run samples its final state before it writes the final files). The same
doubles go through the same C++ estimators, so the agreement is to rounding, not to a
physical tolerance; the branch-vector path (no particle table) rebuilds the centroids as
p − l, which moves them by an ulp or so.

Because both sides share those estimators, a wrong formula would pass that comparison:
IndependentReferenceTest recomputes the stress, its principal direction and the anisotropy
coefficients here with numpy, from the contacts table and the formulas of
docs/micromechanics.md (eigenvectors instead of atan2, the fabric tensor for a_c)."""
import math
import os
import unittest

import numpy as np

import grainlab
from support import CLI_RUN, optional_module

STRESS = ("sigma11", "sigma22", "sigma12", "sigma21", "p", "q")
FABRIC = ("a_c", "theta_c_deg", "a_n", "theta_n_deg", "a_t", "theta_t_deg", "a_w", "a_ln",
          "theta_ln_deg", "a_lt", "theta_lt_deg", "f0", "l0")


class AnalysisTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.contacts = grainlab.read_csv(os.path.join(CLI_RUN, "contacts_final.csv"))
        cls.particles = grainlab.read_csv(os.path.join(CLI_RUN, "particles_final.csv"))
        series = grainlab.read_csv(os.path.join(CLI_RUN, "series.csv"))
        cls.last = {name: series[name][-1] for name in series.dtype.names}
        cls.area = cls.last["area"]

    def close(self, got, want, name, rel=1e-12, angle=False):
        if angle:  # axial angles: compare through 2θ so 0° and 179.99...° agree
            d = math.remainder(got - want, 180.0)
            self.assertLess(abs(d), 1e-9, f"{name}: {got} vs {want}")
        else:
            self.assertLessEqual(abs(got - want), rel * max(abs(want), 1e-300), f"{name}: {got} vs {want}")

    def test_stress_matches_last_row(self):
        s = grainlab.stress(self.contacts, self.area, particles=self.particles)
        for name in STRESS:
            self.close(s[name], self.last[name], name)
        self.close(grainlab.phi_mob(s), self.last["phi_mob_deg"], "phi_mob_deg")
        theta = grainlab.theta_sigma(stress=s)
        self.close(theta, self.last["theta_sigma_macro_deg"], "theta_sigma_macro_deg", angle=True)
        self.close(grainlab.omega(theta), self.last["omega_macro_deg"], "omega_macro_deg", angle=True)
        # The test is not vacuous: the specimen is sheared and loaded.
        self.assertGreater(s["p"], 1e3)
        self.assertGreater(s["q"], 0.05 * s["p"])

    def test_anisotropy_matches_last_row(self):
        f = grainlab.anisotropy(self.contacts, particles=self.particles)
        for name in FABRIC:
            self.close(f[name], self.last[name], name, rel=1e-10, angle=name.startswith("theta"))
        self.assertEqual(f["contacts"], self.last["contacts"])
        for method, column in (("eq7", "theta_sigma_micro_deg"), ("eq10", "theta_sigma_eq10_deg"),
                               ("eq11", "theta_sigma_eq11_deg")):
            self.close(grainlab.theta_sigma(fabric=f, method=method), self.last[column], column, angle=True)

    def test_branch_vectors_instead_of_particles(self):
        # A contact dump with branch vectors and no particle table (as from LAMMPS or YADE).
        inside = self.particles["boundary"] == 0
        s = grainlab.stress(self.contacts, self.area, inside=inside)
        for name in STRESS:
            self.close(s[name], self.last[name], name, rel=1e-9)
        f = grainlab.anisotropy(self.contacts, inside=inside)
        # Coefficients are O(0.01-1) (a_lt of discs is zero up to rounding): an absolute bound.
        for name in ("a_c", "a_n", "a_t", "a_ln", "a_lt"):
            self.assertLess(abs(f[name] - self.last[name]), 1e-9, name)
        for name in ("f0", "l0"):
            self.close(f[name], self.last[name], name, rel=1e-9)

    def test_dataframe_input(self):
        pandas = optional_module("pandas", "python3-pandas")
        if pandas is None:
            self.skipTest("left out: configured with -DGRAINLAB_PYTHON_OPTIONAL_MODULES=OFF")
        s = grainlab.stress(pandas.DataFrame(self.contacts), self.area,
                            particles=pandas.DataFrame(self.particles))
        self.close(s["sigma22"], self.last["sigma22"], "sigma22")

    def test_bad_input_is_named(self):
        with self.assertRaisesRegex(ValueError, "missing columns fn"):
            grainlab.stress({k: self.contacts[k] for k in ("i", "j", "px", "py", "nx", "ny", "ft")}, 1.0,
                            particles=self.particles)
        with self.assertRaisesRegex(ValueError, "area must be positive"):
            grainlab.stress(self.contacts, 0.0, particles=self.particles)
        with self.assertRaisesRegex(ValueError, "method"):
            grainlab.theta_sigma(fabric=grainlab.anisotropy(self.contacts, particles=self.particles), method="eq6")

    def test_rotation_turns_theta_sigma(self):
        # Rotating every contact by 30° turns the principal direction by 30°: a check that the
        # functions use the geometry given, not the run's.
        a = math.radians(30)
        R = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
        c = {k: self.contacts[k].copy() for k in self.contacts.dtype.names}
        p = {k: self.particles[k].copy() for k in self.particles.dtype.names}
        for x, y, cols in (("px", "py", c), ("nx", "ny", c), ("x", "y", p)):
            v = np.column_stack([cols[x], cols[y]]) @ R.T
            cols[x], cols[y] = v[:, 0], v[:, 1]
        base = grainlab.theta_sigma(stress=grainlab.stress(self.contacts, self.area, particles=self.particles))
        turned = grainlab.theta_sigma(stress=grainlab.stress(c, self.area, particles=p))
        self.close(turned, base + 30.0, "rotated theta_sigma", angle=True)


def contact_ends(contacts, particles):
    """Every contact end on a specimen particle: (normal, force it exerts, branch vector), as
    docs/micromechanics.md defines them. The table gives n out of particle i, the force i
    exerts on j (fn along n, ft along t = n turned +90°) and both ends' branch vectors; j's end
    has normal −n and exerts −f."""
    inside = {int(k): b == 0 for k, b in zip(particles["id"], particles["boundary"])}
    n = np.column_stack([contacts["nx"], contacts["ny"]])
    t = np.column_stack([-n[:, 1], n[:, 0]])
    f = contacts["fn"][:, None] * n + contacts["ft"][:, None] * t
    on_i = np.array([inside[int(k)] for k in contacts["i"]])
    on_j = np.array([inside[int(k)] for k in contacts["j"]])
    normals = np.vstack([n[on_i], -n[on_j]])
    forces = np.vstack([f[on_i], -f[on_j]])
    branches = np.vstack([np.column_stack([contacts["lix"], contacts["liy"]])[on_i],
                          np.column_stack([contacts["ljx"], contacts["ljy"]])[on_j]])
    return normals, forces, branches, int(np.count_nonzero(on_i | on_j))


def axial_deg(z):
    """½ arg z in degrees, folded into [0, 180)."""
    return math.degrees(0.5 * math.atan2(z.imag, z.real)) % 180.0


class IndependentReferenceTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.contacts = grainlab.read_csv(os.path.join(CLI_RUN, "contacts_final.csv"))
        cls.particles = grainlab.read_csv(os.path.join(CLI_RUN, "particles_final.csv"))
        series = grainlab.read_csv(os.path.join(CLI_RUN, "series.csv"))
        cls.last = {name: series[name][-1] for name in series.dtype.names}
        cls.area = cls.last["area"]
        cls.n, cls.f, cls.l, cls.touching = contact_ends(cls.contacts, cls.particles)

    def test_stress_is_the_sum_of_force_times_branch_over_area(self):
        # Eq. 1: σ_ij = (1/A) Σ_ends f_i l_j, force index first.
        sigma = np.einsum("ei,ej->ij", self.f, self.l) / self.area
        s = grainlab.stress(self.contacts, self.area, particles=self.particles)
        p = 0.5 * (sigma[0, 0] + sigma[1, 1])
        self.assertGreater(p, 1e3)
        # Summed in another order: rounding, a billionth of p.
        for name, value in (("sigma11", sigma[0, 0]), ("sigma22", sigma[1, 1]), ("sigma12", sigma[0, 1]),
                            ("sigma21", sigma[1, 0])):
            self.assertLess(abs(s[name] - value), 1e-9 * p, f"{name}: module {s[name]}, numpy {value}")
            self.assertLess(abs(self.last[name] - value), 1e-9 * p, f"{name}: series {self.last[name]}, numpy {value}")
        # The principal direction and q/p from the eigen-decomposition of the symmetric part.
        values, vectors = np.linalg.eigh(0.5 * (sigma + sigma.T))
        major = vectors[:, 1]  # eigh sorts ascending: the most compressive last
        theta = math.degrees(math.atan2(major[1], major[0])) % 180.0
        d = math.remainder(theta - self.last["theta_sigma_macro_deg"], 180.0)
        self.assertLess(abs(d), 1e-6, f"theta_sigma_macro_deg {self.last['theta_sigma_macro_deg']}, eigenvector {theta}")
        sin_phi = (values[1] - values[0]) / (values[1] + values[0])
        self.assertAlmostEqual(math.sin(math.radians(self.last["phi_mob_deg"])), sin_phi, delta=1e-9)
        self.assertGreater(sin_phi, 0.05)  # sheared: the direction means something

    def test_anisotropy_from_the_documented_estimators(self):
        e = (self.n[:, 0] + 1j * self.n[:, 1]) ** 2  # e^{2iθ} per end
        a_c = 2 * e.mean()
        # a_c from the fabric tensor φ = ⟨n ⊗ n⟩: another route to the same number.
        phi = np.einsum("ei,ej->ij", self.n, self.n) / len(self.n)
        self.assertAlmostEqual(abs(a_c), 2 * math.hypot(phi[0, 0] - phi[1, 1], 2 * phi[0, 1]), delta=1e-12)
        t = np.column_stack([-self.n[:, 1], self.n[:, 0]])

        def g0_g2(g):  # g(θ) = g0 + Re(G2 e^{−2iθ}) from the moments ⟨g⟩ and ⟨g e⟩
            m0, m2 = g.mean(), (g * e).mean()
            g0 = (m0 - (m2 * np.conj(a_c)).real) / (1 - 0.5 * abs(a_c) ** 2)
            return g0, 2 * m2 - g0 * a_c

        f0, gn = g0_g2(np.einsum("ei,ei->e", self.f, self.n))
        _, gt = g0_g2(np.einsum("ei,ei->e", self.f, t))
        l0, gln = g0_g2(np.einsum("ei,ei->e", self.l, self.n))
        _, glt = g0_g2(np.einsum("ei,ei->e", self.l, t))
        terms = {"c": a_c, "n": gn / f0, "t": 1j * gt / f0, "ln": gln / l0, "lt": 1j * glt / l0}
        f = grainlab.anisotropy(self.contacts, particles=self.particles)
        self.assertEqual(f["contacts"], self.touching)
        self.assertEqual(self.last["contacts"], self.touching)
        for name, want in (("f0", f0), ("l0", l0)):
            self.assertLess(abs(f[name] - want), 1e-9 * want, name)
        for k, a in terms.items():
            for got, source in ((f[f"a_{k}"], "module"), (self.last[f"a_{k}"], "series")):
                self.assertLess(abs(got - abs(a)), 1e-9, f"a_{k}: {source} {got}, numpy {abs(a)}")
            if abs(a) > 0.02:  # the direction of a vanishing term is rounding noise
                for got, source in ((f[f"theta_{k}_deg"], "module"), (self.last[f"theta_{k}_deg"], "series")):
                    d = math.remainder(got - axial_deg(a), 180.0)
                    self.assertLess(abs(d), 1e-6, f"theta_{k}_deg: {source} {got}, numpy {axial_deg(a)}")
        # Discs: l = r n, so the branch vectors have no anisotropy of their own beyond the size
        # mix, and no tangential part at all.
        self.assertLess(abs(terms["lt"]), 1e-9)
        self.assertGreater(abs(a_c), 0.05)  # a sheared fabric, far above rounding
        # Eq. 7: half the argument of the sum of the five A_k.
        micro = axial_deg(sum(terms.values()))
        d = math.remainder(grainlab.theta_sigma(fabric=f, method="eq7") - micro, 180.0)
        self.assertLess(abs(d), 1e-6)
        d = math.remainder(self.last["theta_sigma_micro_deg"] - micro, 180.0)
        self.assertLess(abs(d), 1e-6)


if __name__ == "__main__":
    unittest.main()

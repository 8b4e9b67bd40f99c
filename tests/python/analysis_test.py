"""grainlab's analysis functions on the CLI's contacts_final.csv reproduce the run's own last
series row (the run samples its final state before it writes the final files). The same
doubles go through the same C++ estimators, so the agreement is to rounding, not to a
physical tolerance; the branch-vector path (no particle table) rebuilds the centroids as
p − l, which moves them by an ulp or so."""
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


if __name__ == "__main__":
    unittest.main()

"""A bad scene raises grainlab.SceneError naming the field, before anything is written."""
import os
import shutil
import unittest

import grainlab
from support import WORK


class SceneErrorTest(unittest.TestCase):
    def scene(self):
        return grainlab.preset("circular-quick")

    def assertField(self, scene, field):
        with self.assertRaises(grainlab.SceneError) as ctx:
            grainlab.validate(scene)
        self.assertEqual(ctx.exception.field, field)
        self.assertTrue(str(ctx.exception).startswith(field + ": "), str(ctx.exception))
        return ctx.exception

    def test_presets(self):
        names = grainlab.presets()
        for name in ("circular", "elongated-random", "elongated-bedding-0", "elongated-bedding-30",
                     "elongated-bedding-60", "elongated-bedding-90", "circular-quick"):
            self.assertIn(name, names)
        self.assertIsNone(grainlab.validate(self.scene()))
        with self.assertRaises(grainlab.SceneError) as ctx:
            grainlab.preset("no-such-preset")
        self.assertEqual(ctx.exception.field, "preset")

    def test_negative_friction(self):
        s = self.scene()
        s["material"]["friction"] = -1
        e = self.assertField(s, "material.friction")
        self.assertIn(">= 0", e.reason)
        self.assertIsInstance(e, ValueError)

    def test_unknown_key(self):
        s = self.scene()
        s["output"]["colour"] = "red"
        self.assertField(s, "output.colour")

    def test_vtk_fields(self):
        s = self.scene()
        s["output"]["vtk"] = "yes"
        self.assertField(s, "output.vtk")
        s["output"]["vtk"] = True
        s["output"]["vtk_every"] = 0
        self.assertField(s, "output.vtk_every")

    def test_not_json(self):
        self.assertField({"gravity": [0, float("nan")]}, "(json)")
        self.assertField("{not json", "(json)")

    def test_run_writes_nothing(self):
        s = self.scene()
        s["material"]["density"] = -5
        out = os.path.join(WORK, "bad-scene")
        shutil.rmtree(out, ignore_errors=True)
        with self.assertRaises(grainlab.SceneError) as ctx:
            grainlab.run(s, out=out, progress=False)
        self.assertEqual(ctx.exception.field, "material.density")
        self.assertFalse(os.path.exists(out))

    def test_past_the_validity_envelope(self):
        # Sheared at 1e6 /s the inertial number is ~400: refused naming the rate, not run.
        s = self.scene()
        s["stages"][2]["strain_rate"] = 1e6
        with self.assertRaises(grainlab.SceneError) as ctx:
            grainlab.run(s, progress=False)
        self.assertEqual(ctx.exception.field, "stages[2].strain_rate")
        self.assertIn("inertial_number", ctx.exception.reason)

    def test_warnings_travel_with_the_run(self):
        # At 4 /s the lateral servo cannot hold sigma11: run, and warned before and during.
        s = self.scene()
        s["stages"][2]["strain_rate"] = 4
        run = grainlab.run(s, progress=False)
        self.assertEqual(run.status, "completed")
        quantities = {(w["quantity"], w["field"]) for w in run.warnings}
        self.assertIn(("lateral_servo_inertial_number", "stages[2].strain_rate"), quantities)
        measured = [w for w in run.warnings if "step" in w]
        self.assertTrue(measured, run.warnings)


if __name__ == "__main__":
    unittest.main()

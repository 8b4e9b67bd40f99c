"""grainlab.run gives the CLI's run bit for bit: the same preset and seed, the same series.csv
bytes and the same doubles in Run.series; the final particles and contacts too."""
import os
import shutil
import unittest

import numpy as np

import grainlab
from support import CLI_RUN, PRESET, WORK, optional_module


def same(a, b):
    """Bit-identical float columns (NaN where either is unmeasured counts as equal)."""
    return np.array_equal(a, b, equal_nan=True)


class ModuleRunTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = os.path.join(WORK, "module-run")
        shutil.rmtree(cls.out, ignore_errors=True)
        cls.calls = []
        cls.mine = grainlab.run(PRESET, out=cls.out, progress=lambda f, s: cls.calls.append((f, s)))
        cls.cli = grainlab.Run.load(CLI_RUN)

    def test_completed(self):
        self.assertEqual(self.mine.status, "completed")
        self.assertEqual(self.mine.summary["steps"], self.cli.summary["steps"])

    def test_series_csv_bytes_identical(self):
        with open(os.path.join(self.out, "series.csv"), "rb") as a, \
             open(os.path.join(CLI_RUN, "series.csv"), "rb") as b:
            self.assertEqual(a.read(), b.read())

    def test_series_array_identical(self):
        mine, cli = self.mine.series, self.cli.series
        self.assertEqual(mine.dtype.names, cli.dtype.names)
        self.assertEqual(len(mine), len(cli))
        self.assertGreater(len(mine), 10)
        for name in mine.dtype.names:
            if name == "stage":
                self.assertEqual(list(mine[name]), list(cli[name]))
            else:
                self.assertTrue(same(mine[name], cli[name]), name)

    def test_final_state_identical(self):
        for name in self.cli.particles().dtype.names:
            if name != "shape":
                self.assertTrue(same(self.mine.particles()[name], self.cli.particles()[name]), name)
        self.assertEqual(len(self.mine.contacts()), len(self.cli.contacts()))
        for name in self.cli.contacts().dtype.names:
            self.assertTrue(same(self.mine.contacts()[name], self.cli.contacts()[name]), name)
        for name in ("particles_final.csv", "contacts_final.csv"):
            with open(os.path.join(self.out, name), "rb") as a, open(os.path.join(CLI_RUN, name), "rb") as b:
                self.assertEqual(a.read(), b.read(), name)

    def test_progress_reported(self):
        # A stage's own progress may step back (a servo's pressure overshoots): only the range
        # and the end are promised.
        fractions = [f for f, _ in self.calls]
        self.assertGreater(len(fractions), 10)
        self.assertTrue(all(0 <= f <= 1 for f in fractions))
        stages = {s for _, s in self.calls}
        self.assertTrue({"compaction", "consolidation", "shearing"} <= stages, stages)
        self.assertEqual(self.calls[-1], (1.0, "done"))

    def test_dataframe(self):
        pandas = optional_module("pandas", "python3-pandas")
        if pandas is None:
            self.skipTest("left out: configured with -DGRAINLAB_PYTHON_OPTIONAL_MODULES=OFF")
        df = self.mine.series_df()
        self.assertEqual(list(df.columns), list(self.mine.series.dtype.names))
        self.assertTrue(same(df["q"].to_numpy(), self.mine.series["q"]))

    def test_gil_released(self):
        # Another Python thread keeps running while the engine does. Without a progress
        # callable the run would not let it run at all if it held the GIL.
        import threading
        counter = [0]
        done = threading.Event()

        def count():
            while not done.is_set():
                counter[0] += 1
        thread = threading.Thread(target=count)
        thread.start()
        start = counter[0]
        run = grainlab.run(PRESET, progress=False)
        during = counter[0] - start  # read at once: the main thread holds the GIL here
        done.set()
        thread.join()
        self.assertEqual(run.status, "completed")
        # The loop turns ~6 million times a second here and the run lasts 1-4 s (26 million
        # turns measured); with the GIL held it could run only in the few 5 ms switch
        # intervals of run()'s Python part (tens of thousands of turns).
        self.assertGreater(during, 1000000, f"{during} turns during {run.summary['wall_seconds']} s")
        self.assertTrue(same(run.series["q"], self.cli.series["q"]))

    def test_callback_exception_cancels(self):
        # An exception in the callback (as Ctrl-C would) stops the run and surfaces after it.
        class Stop(Exception):
            pass

        def stop(fraction, stage):
            if fraction > 0.05:
                raise Stop()
        out = os.path.join(WORK, "module-cancelled")
        shutil.rmtree(out, ignore_errors=True)
        with self.assertRaises(Stop):
            grainlab.run(PRESET, out=out, progress=stop)
        # The files are whole and say why the run stopped.
        import json
        with open(os.path.join(out, "summary.json")) as f:
            self.assertEqual(json.load(f)["status"], "cancelled")


if __name__ == "__main__":
    unittest.main()

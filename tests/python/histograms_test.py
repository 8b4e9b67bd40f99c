"""histograms.csv (and Run.histograms()) against an independent computation: the rose data of
the last sample recomputed here, in plain Python, from contacts_final.csv and
particles_final.csv of the same run (the run's last sample is its final state)."""
import math
import os
import unittest

import numpy as np

import grainlab
from support import CLI_RUN


def rose_from_contacts(contacts, particles, bins):
    """Per-bin contact-end counts and mean f_n and l_n over the ends of specimen particles
    (boundary == 0), each end with its own outward normal and branch vector."""
    inside = {int(i): b == 0 for i, b in zip(particles["id"], particles["boundary"])}
    count = [0] * bins
    fn = [0.0] * bins
    ln = [0.0] * bins
    for c in contacts:
        i, j = int(c["i"]), int(c["j"])
        theta = math.degrees(math.atan2(c["ny"], c["nx"])) % 180.0
        b = min(int(theta / (180.0 / bins)), bins - 1)
        ends = []
        if inside[i]:
            ends.append(c["lix"] * c["nx"] + c["liy"] * c["ny"])
        if j >= 0 and inside[j]:
            ends.append(-(c["ljx"] * c["nx"] + c["ljy"] * c["ny"]))
        for l_n in ends:
            count[b] += 1
            fn[b] += c["fn"]
            ln[b] += l_n
    return count, [f / n if n else None for f, n in zip(fn, count)], \
        [l / n if n else None for l, n in zip(ln, count)]


class HistogramsCsv(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.result = grainlab.Run.load(CLI_RUN)

    def test_last_sample_matches_the_final_contacts(self):
        run = self.result
        # The comparison needs the last sample to be the final state.
        self.assertEqual(int(run.series["step"][-1]), int(run.summary["steps"]))
        last = len(run.series) - 1
        counts = run.histograms("count", sample=last)
        bins = len(counts)
        self.assertGreaterEqual(bins, 18)
        self.assertEqual(list(counts["bin"]), list(range(bins)))
        count, fn, ln = rose_from_contacts(run.contacts(), run.particles(), bins)
        self.assertGreater(sum(count), 100)
        self.assertEqual([int(v) for v in counts["value"]], count)
        for name, expected in (("fn", fn), ("ln", ln)):
            got = run.histograms(name, sample=last)["value"]
            for b, (g, e) in enumerate(zip(got, expected)):
                if e is None:
                    self.assertTrue(math.isnan(g), f"{name} bin {b}: empty bin should be empty")
                else:
                    # Sums of the same numbers in another order: rounding only.
                    self.assertAlmostEqual(g, e, delta=1e-9 * abs(e), msg=f"{name} bin {b}")
        density = run.histograms("density", sample=last)["value"]
        self.assertAlmostEqual(float(np.sum(density)), bins, delta=1e-9 * bins)

    def test_every_sample_with_contacts_and_the_fits(self):
        table = self.result.histograms()
        samples = np.unique(table["sample"])
        self.assertGreater(len(samples), 10)
        self.assertLess(samples.max(), len(self.result.series))
        stages = set(self.result.series["stage"])
        self.assertTrue(set(table["stage"]) <= stages)
        # The fitted density's mean over the bins is its c0, which is 1 by construction.
        for k in samples[:: max(1, len(samples) // 5)]:
            fit = self.result.histograms("density_fit", sample=int(k))["value"]
            self.assertAlmostEqual(float(np.mean(fit)), 1.0, delta=1e-9)

    def test_without_an_output_directory_it_says_how(self):
        with self.assertRaises(ValueError) as caught:
            grainlab.Run(self.result.series, self.result.summary, None, None).histograms()
        self.assertIn("out=", str(caught.exception))


if __name__ == "__main__":
    unittest.main()

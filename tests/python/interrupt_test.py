"""Ctrl-C during grainlab.run: a real SIGINT sent to a Python process running a preset stops
the run cleanly (its summary.json says cancelled, its series.csv is whole) and surfaces as
KeyboardInterrupt once the engine has stopped."""
import json
import os
import shutil
import signal
import subprocess
import sys
import textwrap
import unittest

from support import PRESET, WORK

CHILD = textwrap.dedent("""
    import sys, grainlab
    started = []
    def progress(fraction, stage):
        if not started:
            started.append(1)
            print("started", flush=True)
    try:
        grainlab.run(sys.argv[1], out=sys.argv[2], progress=progress)
    except KeyboardInterrupt:
        print("interrupted", flush=True)
        sys.exit(0)
    print("finished", flush=True)
    sys.exit(1)
""")


class InterruptTest(unittest.TestCase):
    def test_sigint_cancels_cleanly(self):
        out = os.path.join(WORK, "interrupted")
        shutil.rmtree(out, ignore_errors=True)
        child = subprocess.Popen([sys.executable, "-c", CHILD, PRESET, out], stdout=subprocess.PIPE, text=True)
        self.assertEqual(child.stdout.readline().strip(), "started")
        child.send_signal(signal.SIGINT)
        rest, _ = child.communicate(timeout=120)
        self.assertEqual(rest.strip(), "interrupted")
        self.assertEqual(child.returncode, 0)
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        self.assertEqual(summary["status"], "cancelled")
        with open(os.path.join(out, "series.csv")) as f:
            lines = f.read().splitlines()
        self.assertGreaterEqual(len(lines), 2)  # the header and the first sample at least
        self.assertEqual(len({line.count(",") for line in lines}), 1)  # every row whole


if __name__ == "__main__":
    unittest.main()

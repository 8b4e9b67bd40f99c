"""grainlab.Client against a real server started here (`grainlab serve --port 0` on a
throw-away database): submit a preset, wait for it, fetch its series, which must be the CLI's
own run of the same preset, bit for bit; a bad scene is refused with the field named."""
import os
import shutil
import unittest

import numpy as np

import grainlab
from loopback_server import start_loopback_server
from support import CLI, CLI_RUN, PRESET, WORK


class ClientTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = os.path.join(WORK, "client")
        shutil.rmtree(cls.dir, ignore_errors=True)
        os.makedirs(cls.dir)
        cls.server, cls.log, url = start_loopback_server(
            [CLI, "serve", "--host", "127.0.0.1", "--port", "0", "--db", os.path.join(cls.dir, "test.db")],
            os.path.join(cls.dir, "serve.log"))
        cls.client = grainlab.Client(url)

    @classmethod
    def tearDownClass(cls):
        cls.server.terminate()
        cls.server.wait(timeout=30)
        cls.log.close()

    def test_resume_refuses_a_completed_run_by_reason(self):
        run_id = self.client.submit(PRESET)
        self.assertEqual(self.client.wait(run_id, timeout=600, poll=0.2)["status"], "completed")
        with self.assertRaises(grainlab.ServerError) as caught:
            self.client.resume(run_id)
        self.assertEqual(caught.exception.status, 409)
        self.assertIn("no checkpoint", str(caught.exception))

    def test_health_and_presets(self):
        self.assertEqual(self.client.health()["status"], "ok")
        self.assertEqual(self.client.presets(), grainlab.presets())

    def test_submit_wait_fetch(self):
        run_id = self.client.submit(PRESET)
        self.assertIn(run_id, [r["id"] for r in self.client.runs()])
        # Filtered and paged on the server: the run is found by its name, and not under a status
        # it does not have; a page of one is one run.
        self.assertIn(run_id, [r["id"] for r in self.client.runs(name=PRESET.upper())])
        self.assertNotIn(run_id, [r["id"] for r in self.client.runs(status=["failed", "cancelled"])])
        self.assertEqual(len(self.client.runs(limit=1)), 1)
        one_by_one = grainlab.Client(self.client.url)
        one_by_one.page_size = 1  # the whole list walked a page of one run at a time
        self.assertEqual([r["id"] for r in one_by_one.runs()], [r["id"] for r in self.client.runs()])
        run = self.client.wait(run_id, timeout=600, poll=0.2)
        self.assertEqual(run["status"], "completed")
        series = self.client.series(run_id)
        cli = grainlab.read_csv(os.path.join(CLI_RUN, "series.csv"))
        self.assertEqual(series.dtype.names, cli.dtype.names)
        self.assertEqual(len(series), len(cli))
        for name in cli.dtype.names:
            if name == "stage":
                self.assertEqual(list(series[name]), list(cli[name]))
            else:
                self.assertTrue(np.array_equal(series[name], cli[name], equal_nan=True), name)

    def test_bad_scene(self):
        scene = grainlab.preset(PRESET)
        scene["material"]["friction"] = -1
        with self.assertRaises(grainlab.SceneError) as ctx:
            self.client.submit(scene)
        self.assertEqual(ctx.exception.field, "material.friction")
        with self.assertRaises(grainlab.ServerError) as ctx:
            self.client.get(999999)
        self.assertEqual(ctx.exception.status, 404)


if __name__ == "__main__":
    unittest.main()

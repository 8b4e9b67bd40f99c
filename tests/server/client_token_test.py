"""grainlab.Client with a token (docs/security.md): the real server with a full and a read-only
token, started here on loopback. Without a token the client is refused with 401; with the
read-only one it lists and reads but cannot submit or delete (403); with the full one it
submits, cancels and deletes. The token never shows in the client's repr."""
import os
import tempfile
import unittest

import grainlab
from loopback_server import start_loopback_server

SERVER = os.environ["GRAINLAB_SERVER"]
FULL = "python-client-full-token-0001"
READ = "python-client-read-only-token-1"
LONG = {"name": "long", "particles": [{"shape": "disc", "radius": 0.002, "position": [0, 0.003]}],
        "walls": [{"point": [0, 0], "normal": [0, 1]}], "gravity": [0, -9.81],
        "stages": [{"type": "free", "duration": 1000}], "output": {"sample_interval": 0.05}}


class ClientTokenTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        scratch = os.environ.get("GRAINLAB_TEST_TMP")
        if scratch:
            os.makedirs(scratch, exist_ok=True)
        cls.dir = tempfile.TemporaryDirectory(dir=scratch)
        env = dict(os.environ, GRAINLAB_TOKEN=FULL, GRAINLAB_READ_ONLY_TOKEN=READ)
        cls.server, cls.log, cls.url = start_loopback_server(
            [SERVER, "--host", "127.0.0.1", "--port", "0", "--db", os.path.join(cls.dir.name, "test.db")],
            os.path.join(cls.dir.name, "serve.log"), env)

    @classmethod
    def tearDownClass(cls):
        cls.server.terminate()
        cls.server.wait(timeout=30)
        cls.log.close()
        cls.dir.cleanup()

    def client(self, token):
        # An explicit token, and none from this process's environment for the tokenless one.
        os.environ.pop("GRAINLAB_TOKEN", None)
        return grainlab.Client(self.url, token=token)

    def test_without_a_token_401(self):
        with self.assertRaises(grainlab.client.ServerError) as refused:
            self.client(None).runs()
        self.assertEqual(refused.exception.status, 401)
        self.assertEqual(self.client(None).health()["status"], "ok")  # health needs none

    def test_read_only_token_reads_but_changes_nothing(self):
        full, reader = self.client(FULL), self.client(READ)
        run_id = full.submit(LONG)
        self.assertIn(run_id, [r["id"] for r in reader.runs()])
        self.assertEqual(reader.get(run_id)["id"], run_id)
        for change in (lambda: reader.submit(LONG), lambda: reader.cancel(run_id), lambda: reader.delete(run_id)):
            with self.assertRaises(grainlab.client.ServerError) as refused:
                change()
            self.assertEqual(refused.exception.status, 403)
        self.assertIn(full.get(run_id)["status"], ("queued", "running"))
        full.cancel(run_id)
        full.delete(run_id)
        self.assertNotIn(run_id, [r["id"] for r in full.runs()])

    def test_token_from_the_environment_and_never_in_repr(self):
        os.environ["GRAINLAB_TOKEN"] = FULL
        try:
            client = grainlab.Client(self.url)
            self.assertIsInstance(client.runs(), list)
            self.assertNotIn(FULL, repr(client))
        finally:
            del os.environ["GRAINLAB_TOKEN"]


if __name__ == "__main__":
    unittest.main()

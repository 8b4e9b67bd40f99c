"""grainlab.Client: the server's REST API (docs/http-api.md) with the standard library only."""
import io
import json
import os
import time
import urllib.error
import urllib.request

from ._errors import SceneError
from ._tables import read_csv


class ServerError(RuntimeError):
    """A refusal from the server other than a bad scene: ``status`` (HTTP), ``field``, message."""

    def __init__(self, status, message, field=None):
        super().__init__(f"HTTP {status}: {message}")
        self.status = status
        self.field = field


class Client:
    """A grainlab server at ``url`` (for example "http://127.0.0.1:8080").

    ``token``: the server's token (the ``token=`` of the login URL ``grainlab serve`` prints),
    sent as ``Authorization: Bearer``; by default the environment variable GRAINLAB_TOKEN, if
    set. A server on loopback started without a token needs none (docs/security.md)."""

    def __init__(self, url="http://127.0.0.1:8080", timeout=30.0, token=None):
        self.url = url.rstrip("/")
        self.timeout = timeout
        self._token = token if token is not None else os.environ.get("GRAINLAB_TOKEN") or None

    def __repr__(self):
        # Never the token: a repr ends up in logs and notebooks.
        return f"Client({self.url!r})"

    def _request(self, method, path, body=None):
        data = None if body is None else json.dumps(body, allow_nan=False).encode()
        headers = {"Content-Type": "application/json"} if data else {}
        if self._token:
            headers["Authorization"] = f"Bearer {self._token}"
        request = urllib.request.Request(self.url + path, data=data, method=method, headers=headers)
        try:
            with urllib.request.urlopen(request, timeout=self.timeout) as response:
                return response.read()
        except urllib.error.HTTPError as e:
            text = e.read().decode(errors="replace")
            try:
                detail = json.loads(text)
            except ValueError:
                detail = {"error": text}
            if e.code == 400 and method == "POST" and path == "/api/runs" and detail.get("field"):
                raise SceneError(detail["field"], detail.get("error", "")) from None
            raise ServerError(e.code, detail.get("error", text), detail.get("field")) from None

    def _json(self, method, path, body=None):
        text = self._request(method, path, body)
        return json.loads(text) if text else None

    def health(self):
        return self._json("GET", "/api/health")

    def presets(self):
        return self._json("GET", "/api/presets")["presets"]

    def runs(self):
        """Every run, newest first, without its scene."""
        return self._json("GET", "/api/runs")["runs"]

    def get(self, run_id):
        """One run: status, progress, stage, timings, peak_phi_mob_deg, error, scene."""
        return self._json("GET", f"/api/runs/{int(run_id)}")

    def submit(self, scene):
        """Queues a scene dict or a preset name; returns the run's id. A bad scene raises
        SceneError with the server's field (nothing is stored)."""
        body = {"preset": scene} if isinstance(scene, str) else scene
        return self._json("POST", "/api/runs", body)["id"]

    def wait(self, run_id, timeout=None, poll=0.5):
        """Polls until the run has ended; returns it. Raises TimeoutError after ``timeout`` s."""
        deadline = None if timeout is None else time.monotonic() + timeout
        while True:
            run = self.get(run_id)
            if run["status"] not in ("queued", "running"):
                return run
            if deadline is not None and time.monotonic() > deadline:
                raise TimeoutError(f"run {run_id} still {run['status']} after {timeout} s")
            time.sleep(poll)

    def series(self, run_id):
        """The run's series as a numpy structured array, from the same CSV as the CLI's."""
        text = self._request("GET", f"/api/runs/{int(run_id)}/series?format=csv").decode()
        return read_csv(io.StringIO(text))

    def cancel(self, run_id):
        return self._json("POST", f"/api/runs/{int(run_id)}/cancel")

    def resume(self, run_id):
        """Continues a run the server left resumable (interrupted, or stopped at its wall-time
        limit) from its checkpoint; the run as the server now has it (queued or running)."""
        return self._json("POST", f"/api/runs/{int(run_id)}/resume")

    def delete(self, run_id):
        self._request("DELETE", f"/api/runs/{int(run_id)}")

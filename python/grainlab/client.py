"""grainlab.Client: the server's REST API (docs/http-api.md) with the standard library only."""
import io
import json
import os
import time
import urllib.error
import urllib.parse
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

    page_size = 1000  # runs per request when runs() walks the whole list

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

    def runs(self, status=None, preset=None, study=None, name=None, sort=None, order=None,
             limit=None, offset=0):
        """Runs without their scenes, newest first unless ``sort`` (created_at, name, status,
        preset, wall_seconds, peak_phi_mob_deg) and ``order`` ("asc", "desc") say otherwise,
        filtered on the server: ``status`` (one or a list), ``preset``, ``study``, ``name`` (part
        of the name, any case). With ``limit``, one page of at most that many runs from
        ``offset``; without it every match, asked for ``page_size`` (1,000) at a time so that no
        answer grows with the database (docs/http-api.md, GET /api/runs)."""
        query = {"status": ",".join(status) if isinstance(status, (list, tuple)) else status,
                 "preset": preset, "study": study, "q": name, "sort": sort, "order": order}
        query = {k: v for k, v in query.items() if v is not None}
        if limit is not None:
            return self._runs_page(query, limit, offset)["runs"]
        runs = []
        while True:
            page = self._runs_page(query, self.page_size, offset)
            runs += page["runs"]
            if not page.get("next"):
                return runs
            offset += len(page["runs"])

    def _runs_page(self, query, limit, offset):
        query = dict(query, limit=int(limit), offset=int(offset))
        return self._json("GET", "/api/runs?" + urllib.parse.urlencode(query))

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

"""Starts a grainlab server on 127.0.0.1 with a port the system picks, for the tests that talk
to a real one (the Python client's). Needs nothing from the environment, so tests outside
tests/python can use it too."""
import re
import subprocess
import time


def start_loopback_server(command, log_path, env=None):
    """Runs `command` (a server taking --host 127.0.0.1 --port 0 among its arguments) with its
    output in log_path. Returns (process, log file, url); raises if it does not say where it
    listens within 20 s, after stopping it."""
    log = open(log_path, "w+")
    server = subprocess.Popen(command, stderr=log, stdout=log, env=env)
    for _ in range(200):
        log.seek(0)
        m = re.search(r"listening on http://127\.0\.0\.1:(\d+)", log.read())
        if m:
            return server, log, f"http://127.0.0.1:{m.group(1)}"
        if server.poll() is not None:
            break
        time.sleep(0.1)
    server.terminate()
    server.wait(timeout=30)
    log.close()
    raise RuntimeError(f"the server did not start (its log: {log_path})")

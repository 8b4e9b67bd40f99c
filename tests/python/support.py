"""Shared by the Python tests: where the CLI and the shared fixture run are."""
import os
import subprocess

CLI = os.environ["GRAINLAB_CLI"]
WORK = os.environ["GRAINLAB_TEST_DIR"]
# The fixture: `grainlab run --preset circular-quick --vtk` (cli_run_fixture.py).
PRESET = "circular-quick"
CLI_RUN = os.path.join(WORK, "cli-run")


def run_cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True)

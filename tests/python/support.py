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


def optional_module(name, package):
    """Imports a module these tests need that the grainlab module itself does not. Missing, it
    fails the test naming the Debian package, unless the build was configured to leave these
    tests out (-DGRAINLAB_PYTHON_OPTIONAL_MODULES=OFF): then it returns None and the caller
    skips, and the ctest test test_areas_registered says so."""
    import importlib
    try:
        return importlib.import_module(name)
    except ImportError as error:
        if os.environ.get("GRAINLAB_PYTHON_OPTIONAL_MODULES", "ON").upper() in ("OFF", "0", "FALSE", "NO"):
            return None
        raise RuntimeError(
            f"this test needs the Python module {name} ({error}): apt-get install {package} "
            f"(./scripts/setup installs it), or configure with "
            f"-DGRAINLAB_PYTHON_OPTIONAL_MODULES=OFF to leave these tests out") from None

"""The compiled part of grainlab is built for one interpreter: Debian's /usr/bin/python3 with
python3-numpy (scripts/setup installs both). Another python3 first on PATH (pyenv, conda, a
venv without numpy) fails on import with an error that does not say so; this check does."""
import glob
import os
import sys


def check():
    here = os.path.dirname(os.path.abspath(__file__))
    built = sorted(os.path.basename(p) for p in glob.glob(os.path.join(here, "_grainlab*.so")))
    try:
        import numpy  # noqa: F401  (the extension returns numpy arrays)
        from . import _grainlab  # noqa: F401
    except ImportError as error:
        raise ImportError(
            "grainlab: cannot load its compiled module with this interpreter "
            f"({sys.executable}, Python {sys.version.split()[0]}): {error}. It is built for "
            f"Debian's python3 with python3-numpy ({', '.join(built) or 'no _grainlab found'} "
            "in " + here + "): run it with /usr/bin/python3, or rebuild with "
            "-DPython3_EXECUTABLE=... for another interpreter that has numpy.") from error

"""grainlab from Python: run scenes in-process, read their results as numpy arrays, apply
grainlab's micromechanical analysis to any contact table, and drive a grainlab server.
See docs/python.md."""
from ._interpreter import check as _check_interpreter

_check_interpreter()

from ._errors import SceneError
from ._scene import presets, preset, validate
from ._run import Run, run
from ._tables import read_csv
from ._analysis import stress, anisotropy, theta_sigma, omega, phi_mob
from ._lammps import read_lammps
from .client import Client, ServerError

__all__ = ["SceneError", "presets", "preset", "validate", "Run", "run", "read_csv", "stress",
           "anisotropy", "theta_sigma", "omega", "phi_mob", "read_lammps", "Client", "ServerError"]

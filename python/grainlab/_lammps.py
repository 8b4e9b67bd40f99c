"""grainlab.read_lammps: a LAMMPS granular run's dumps as a grainlab Run (docs/lammps.md)."""
import json
import os
import tempfile
import warnings

from . import _grainlab
from ._run import Run
from ._tables import read_csv


def read_lammps(*dumps, out=None, timestep=None, frames_every=0):
    """The `dump custom` and `dump local` files of a LAMMPS run (gzip or plain, any order),
    imported exactly as `grainlab import lammps` imports them, as a Run: ``series`` (the
    series.csv table: contact stress, fabric, θσ, ω, ...), ``particles()`` and ``contacts()``
    of the last frame, and with ``out`` ``histograms()``. With ``out`` the files are kept there (and
    ``frames_every`` > 0 writes particle frames); otherwise they are read from a temporary
    folder. ``timestep`` (s per step) gives the time column when there is no export.json
    beside the dumps. Malformed dumps raise RuntimeError naming the file and line; a truncated
    last frame is a warning, the frames before it are read."""
    if not dumps:
        raise ValueError("read_lammps: give the dump files")
    paths = [os.fspath(d) for d in dumps]

    def load(folder):
        report = _grainlab.import_lammps(paths, folder, timestep, frames_every)
        if report["warning"]:
            warnings.warn(report["warning"], stacklevel=3)
        with open(os.path.join(folder, "summary.json")) as f:
            summary = json.load(f)
        return Run(read_csv(os.path.join(folder, "series.csv")), summary,
                   read_csv(os.path.join(folder, "particles_final.csv")),
                   read_csv(os.path.join(folder, "contacts_final.csv")), out=folder)

    if out is not None:
        return load(os.fspath(out))
    with tempfile.TemporaryDirectory() as scratch:
        run = load(os.path.join(scratch, "imported"))
    run.out = None  # as a grainlab.run without out=: no histograms kept
    return run

"""grainlab.run: a scene run in this process, its results as numpy arrays."""
import os
import sys

import numpy as np

from . import _grainlab
from ._scene import scene_text
from ._tables import from_columns, read_csv, series_array


class Run:
    """One run's results. ``series`` is a numpy structured array with the columns of
    series.csv (NaN where a value was not measured); ``summary`` the keys of summary.json;
    ``out`` the output directory, or None. A run in a periodic cell (docs/periodic-cell.md)
    has ``cell``, the cell's edge vectors at the end as a 2×2 array h (columns h1, h2, m), and
    ``cell_series``, h at each row of ``series`` (samples × 2 × 2); both are None for a run in
    the ring, and for a run read back with Run.load (the files do not hold h)."""

    def __init__(self, series, summary, particles, contacts, out=None, cell=None, cell_series=None):
        self.series = series
        self.summary = summary
        self.cell = cell
        self.cell_series = cell_series
        self._particles = particles
        self._contacts = contacts
        self.out = out

    @classmethod
    def load(cls, out):
        """The run that `grainlab run` (or grainlab.run with out=) wrote to the directory ``out``."""
        import json
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        return cls(read_csv(os.path.join(out, "series.csv")), summary,
                   read_csv(os.path.join(out, "particles_final.csv")),
                   read_csv(os.path.join(out, "contacts_final.csv")), out=str(out))

    @property
    def status(self):
        return self.summary.get("status")

    @property
    def warnings(self):
        """The validity envelope's warnings (docs/validity.md): a list of dicts with field,
        quantity, value, limit, meaning, and step for one measured during the run."""
        return self.summary.get("warnings", [])

    def series_df(self):
        """The series as a pandas DataFrame (pandas is needed only here)."""
        try:
            import pandas
        except ImportError:
            raise ImportError("Run.series_df needs pandas (Debian: python3-pandas); "
                              "Run.series is the same table as a numpy array") from None
        return pandas.DataFrame(self.series)

    def particles(self):
        """The final particles: id, shape, x, y, angle, vx, vy, spin, radius, boundary. A clump's
        row is its body: its centroid, its angle, and its bounding radius (clump_members() has
        its discs)."""
        return self._particles

    def clump_members(self):
        """The final clumps' discs: id (the clump's particle id), member, x, y, radius, read
        from the output directory's clump_members_final.csv; None when the run has no clumps
        or wrote no output directory (run with out=)."""
        if self.out is None:
            return None
        path = os.path.join(self.out, "clump_members_final.csv")
        return read_csv(path) if os.path.exists(path) else None

    def contacts(self):
        """The final contacts: i, j, px, py, nx, ny, fn, ft, lix, liy, ljx, ljy (contracts.md);
        a wall contact has j < 0 and NaN for ljx, ljy."""
        return self._contacts

    def histograms(self, quantity=None, sample=None):
        """The rose data of histograms.csv (written when the scene's output.histograms is true,
        the default, and the run has an output directory): a structured array with columns
        stage, sample, quantity, bin, value. ``sample`` k is row k of ``series``; bin b covers
        [b, b + 1) · 180°/bins. Quantities: count, density, fn, ft, ln, lt and their fits
        density_fit, ..., lt_fit at the bin centres (docs/micromechanics.md). ``quantity`` and
        ``sample`` (a row index; -1 for the last sample with contacts) select rows."""
        if self.out is None:
            raise ValueError("Run.histograms: this run kept no files; run it with out=DIR "
                             "(grainlab.run(scene, out=DIR)) to keep histograms.csv")
        path = os.path.join(self.out, "histograms.csv")
        if not os.path.exists(path):
            raise FileNotFoundError(f"{path}: no histograms (the scene's output.histograms is false?)")
        table = read_csv(path)
        if quantity is not None:
            table = table[np.asarray(table["quantity"]) == quantity]
        if sample is not None:
            samples = table["sample"]
            if sample < 0 and len(samples):
                sample = np.unique(samples)[sample]
            table = table[samples == sample]
        return table

    def __repr__(self):
        return (f"<grainlab.Run {self.status}: {len(self.series)} samples, "
                f"{self.summary.get('particles')} particles, {self.summary.get('steps')} steps>")


def _progress_reporter(progress):
    """A callable(fraction, stage) for the engine, and a function that closes it."""
    if callable(progress):
        return progress, lambda: None
    if not progress:
        return None, lambda: None
    try:
        from tqdm import tqdm
    except ImportError:
        tqdm = None
    if tqdm is not None:
        bar = tqdm(total=100, unit="%", bar_format="{l_bar}{bar}| {n:.0f}% [{elapsed}<{remaining}]")

        def update(fraction, stage):
            percent = int(fraction * 100)
            if percent > bar.n:
                bar.update(percent - bar.n)
            bar.set_description(stage, refresh=False)
        return update, bar.close
    if not sys.stderr.isatty():
        return None, lambda: None
    last = [-1]

    def line(fraction, stage):
        percent = int(fraction * 100)
        if percent != last[0]:
            last[0] = percent
            sys.stderr.write(f"\r[{percent:3d}%] {stage:<20}")
            sys.stderr.flush()
    return line, lambda: sys.stderr.write("\n")


def run(scene, out=None, progress=True):
    """Runs a scene (dict, preset name, scene file path or JSON text) in this process and
    returns a Run. With ``out``, writes what `grainlab run --out` writes (and the VTK frames if
    the scene's output asks for them). ``progress``: True for a tqdm bar (when tqdm is
    installed; otherwise a line on a terminal's stderr), False for none, or a
    callable(fraction, stage). The GIL is released while the engine runs; Ctrl-C stops the
    run cleanly (its files say cancelled) and raises KeyboardInterrupt. A bad scene raises
    SceneError before anything is written; a run that fails is returned with
    ``summary["status"] == "failed"`` and the reason in ``summary["error"]``."""
    out_dir = "" if out is None else os.fspath(out)
    callback, close = _progress_reporter(progress)
    try:
        if isinstance(scene, str) and scene in _grainlab.presets():
            # The preset's own scene, exactly as `grainlab run --preset` builds it.
            result = _grainlab.run_preset(scene, out_dir, callback)
        else:
            result = _grainlab.run_json(scene_text(scene), out_dir, callback)
    finally:
        close()
    series = series_array(result["columns"], result["stages"], result["values"])
    summary = result["summary"]
    if out_dir:  # the file has a few more keys (profile, speed)
        import json
        with open(os.path.join(out_dir, "summary.json")) as f:
            summary = json.load(f)
    return Run(series, summary, from_columns(result["particles"]),
               from_columns(result["contacts"]), out=out_dir or None,
               cell=result["cell"], cell_series=result["cell_series"])

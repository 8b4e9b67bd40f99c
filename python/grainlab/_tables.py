"""Tables as numpy structured arrays: the series, the final particles and contacts, and the
CSV files `grainlab run` writes. Column names are those of contracts.md."""
import csv
import math

import numpy as np

# Integer and text columns; every other column is float64 (NaN where the CSV cell is empty).
_INTEGER = {"step", "id", "i", "j", "boundary", "sample", "bin"}
_TEXT = {"stage", "shape", "quantity"}


def _dtype(names, text_width):
    fields = []
    for name in names:
        if name in _INTEGER:
            fields.append((name, "i8"))
        elif name in _TEXT:
            fields.append((name, f"U{max(1, text_width)}"))
        else:
            fields.append((name, "f8"))
    return np.dtype(fields)


def from_columns(columns):
    """A structured array from a dict of equal-length columns (numpy arrays or lists)."""
    names = list(columns)
    n = len(columns[names[0]]) if names else 0
    width = max((len(str(v)) for name in names if name in _TEXT for v in columns[name]), default=1)
    out = np.empty(n, dtype=_dtype(names, width))
    for name in names:
        out[name] = columns[name]
    return out


def series_array(columns, stages, values):
    """The series as a structured array: step and time first, stage as text, floats after."""
    table = {}
    for k, name in enumerate(columns):
        if name == "stage":
            table[name] = list(stages)
        elif name in _INTEGER:
            table[name] = values[:, k].astype(np.int64) if len(values) else np.zeros(0, np.int64)
        else:
            table[name] = values[:, k] if len(values) else np.zeros(0)
    return from_columns(table)


def read_csv(path):
    """A CSV (a path or an open text file) written by grainlab (series.csv, particles_final.csv, contacts_final.csv,
    histograms.csv) as a
    structured array. Empty cells (values not measured, a wall's lj) become NaN."""
    if hasattr(path, "read"):
        rows = list(csv.reader(path))
    else:
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path}: empty file, expected a header line")
    header, body = rows[0], rows[1:]
    columns = {}
    for k, name in enumerate(header):
        cells = [r[k] for r in body]
        if name in _TEXT:
            columns[name] = cells
        elif name in _INTEGER:
            columns[name] = np.array([int(c) for c in cells], dtype=np.int64)
        else:
            columns[name] = np.array([float(c) if c != "" else math.nan for c in cells], dtype=np.float64)
    if not header:
        return np.empty(0)
    return from_columns(columns)


def as_columns(table):
    """Any table (structured array, pandas DataFrame, dict of arrays) as a dict of arrays."""
    if isinstance(table, dict):
        return {k: np.asarray(v) for k, v in table.items()}
    if isinstance(table, np.ndarray) and table.dtype.names:
        return {k: table[k] for k in table.dtype.names}
    if hasattr(table, "columns") and hasattr(table, "to_numpy"):  # a pandas DataFrame
        return {str(k): table[k].to_numpy() for k in table.columns}
    raise TypeError("expected a numpy structured array, a pandas DataFrame or a dict of columns, "
                    f"got {type(table).__name__}")

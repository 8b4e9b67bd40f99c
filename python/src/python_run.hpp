#pragma once
// grainlab.run in C++: runs a scene in-process with the GIL released, keeps every series row
// and the final particles and contacts, and (with an output directory) writes what
// `grainlab run` writes. Progress goes to a Python callable; Ctrl-C (or an exception from the
// callable) cancels the run cleanly and is re-raised once the run has stopped.
#include <string>

#include <pybind11/pybind11.h>

#include "grainlab/scene.hpp"

namespace grainlab::python {

namespace py = pybind11;

/// Returns {"columns", "stages", "values" (rows × columns float64, NaN = not measured),
/// "summary" (the keys of summary.json), "particles", "contacts" (dicts of column arrays)}.
/// `out` empty: no files. `progress`: None or a callable(fraction, stage).
py::dict runScene(const Scene& scene, const std::string& out, const py::object& progress);

}  // namespace grainlab::python

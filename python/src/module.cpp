// grainlab._grainlab: the compiled half of the Python package. Scenes travel as JSON text (the
// package turns dicts into it), arrays as numpy, results as dicts. The analysis functions
// call the engine's own estimators (engine/analysis, engine/src/stress.cpp): no formula is
// written twice.
#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "grainlab/analysis/fabric.hpp"
#include "grainlab/analysis/stress_direction.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/lammps/import.hpp"
#include "grainlab/periodic_cell.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/stress.hpp"
#include "python_run.hpp"

namespace py = pybind11;
using namespace grainlab;
using namespace grainlab::python;

namespace {

Scene parseSceneText(const std::string& text) {
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw SceneError("(json)", e.what());
  }
  return parseScene(json);
}

StressTensor stressFromDict(const py::dict& d) {
  for (const char* key : {"sigma11", "sigma12", "sigma21", "sigma22"}) {
    if (!d.contains(key)) throw std::invalid_argument(std::string("stress: missing key ") + key);
  }
  return StressTensor{d["sigma11"].cast<double>(), d["sigma12"].cast<double>(), d["sigma21"].cast<double>(),
                      d["sigma22"].cast<double>()};
}

#define GRAINLAB_FABRIC_FIELDS(X)                                                                      \
  X(a_c) X(theta_c_deg) X(a_n) X(theta_n_deg) X(a_t) X(theta_t_deg) X(a_w) X(a_ln) X(theta_ln_deg) \
      X(a_lt) X(theta_lt_deg) X(f0) X(l0) X(a_w_direct) X(lt0_ratio)

py::dict fabricToDict(const analysis::FabricState& f) {
  py::dict d;
#define X(name) d[#name] = f.name;
  GRAINLAB_FABRIC_FIELDS(X)
#undef X
  d["ends"] = f.ends;
  d["contacts"] = f.contacts;
  return d;
}

analysis::FabricState fabricFromDict(const py::dict& d) {
  analysis::FabricState f;
#define X(name) \
  if (d.contains(#name)) f.name = d[#name].cast<double>();
  GRAINLAB_FABRIC_FIELDS(X)
#undef X
  for (const char* key : {"a_c", "theta_c_deg", "a_n", "theta_n_deg", "a_t", "theta_t_deg"}) {
    if (!d.contains(key)) throw std::invalid_argument(std::string("fabric: missing key ") + key);
  }
  return f;
}

}  // namespace

namespace {
// A periodic cell from Python: None, or a 2×2 array h whose columns are the edges (Run.cell).
std::optional<PeriodicCell> cellFromObject(const py::object& h) {
  if (h.is_none()) return std::nullopt;
  const auto a = py::cast<DoubleArray>(h);
  if (a.ndim() != 2 || a.shape(0) != 2 || a.shape(1) != 2)
    throw std::invalid_argument("cell: must be a 2x2 array h (columns the edges h1, h2) or None");
  const auto v = a.unchecked<2>();
  Eigen::Matrix2d m;
  m << v(0, 0), v(0, 1), v(1, 0), v(1, 1);
  return PeriodicCell(m);  // throws for a degenerate cell
}
}  // namespace

PYBIND11_MODULE(_grainlab, m) {
  m.doc() = "grainlab's engine, run and analysis (use the grainlab package, not this module)";

  // C++ SceneError -> grainlab.SceneError(field, reason), a ValueError with .field.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SceneError& e) {
      py::object cls = py::module_::import("grainlab._errors").attr("SceneError");
      py::object err = cls(e.field(), e.reason());
      PyErr_SetObject(cls.ptr(), err.ptr());
    }
  });

  m.def("presets", &presetNames, "The preset names, in the order `grainlab presets` lists them.");
  m.def(
      "preset_json", [](const std::string& name) { return presetScene(name).dump(); },
      "The preset as scene JSON text.");
  m.def(
      "validate_json", [](const std::string& text) { parseSceneText(text); },
      "Parses and validates scene JSON text; raises SceneError naming the field.");
  m.def(
      "run_json",
      [](const std::string& text, const std::string& out, const py::object& progress) {
        return runScene(parseSceneText(text), out, progress);
      },
      py::arg("scene"), py::arg("out"), py::arg("progress"));
  m.def(
      "run_preset",
      [](const std::string& name, const std::string& out, const py::object& progress) {
        return runScene(parseScene(presetScene(name)), out, progress);
      },
      py::arg("name"), py::arg("out"), py::arg("progress"));

  m.def(
      "contact_stress",
      [](const py::dict& contacts, const DoubleArray& centroids, const FlagArray& inside, double area,
         const py::object& h) {
        const auto records = contactsFromColumns(contacts);
        const auto x = centroidsFromArray(centroids);
        const auto flags = flagsFromArray(inside);
        const auto cell = cellFromObject(h);
        const StressTensor s = contactStress(records, x, flags, area, cell ? &*cell : nullptr);
        py::dict d;
        d["sigma11"] = s.s11;
        d["sigma22"] = s.s22;
        d["sigma12"] = s.s12;
        d["sigma21"] = s.s21;
        d["p"] = s.p();
        d["q"] = s.q();
        return d;
      },
      py::arg("contacts"), py::arg("centroids"), py::arg("inside"), py::arg("area"), py::arg("cell") = py::none());
  m.def(
      "fabric",
      [](const py::dict& contacts, const DoubleArray& centroids, const FlagArray& inside, const py::object& h) {
        const auto records = contactsFromColumns(contacts);
        const auto x = centroidsFromArray(centroids);
        const auto flags = flagsFromArray(inside);
        const auto cell = cellFromObject(h);
        return fabricToDict(analysis::measureFabric(records, x, flags, cell ? &*cell : nullptr));
      },
      py::arg("contacts"), py::arg("centroids"), py::arg("inside"), py::arg("cell") = py::none());
  m.def(
      "theta_sigma_macro", [](const py::dict& s) { return analysis::thetaSigmaMacroDeg(stressFromDict(s)); },
      py::arg("stress"));
  m.def(
      "theta_sigma_fabric",
      [](const py::dict& f, const std::string& method) {
        const analysis::FabricState s = fabricFromDict(f);
        if (method == "eq7") return analysis::thetaSigmaEq7Deg(s);
        if (method == "eq10") return analysis::thetaSigmaEq10Deg(s);
        if (method == "eq11") return analysis::thetaSigmaEq11Deg(s);
        if (method == "sff") return analysis::thetaSigmaSffDeg(s);
        throw std::invalid_argument("method: must be eq7, eq10, eq11 or sff, got " + method);
      },
      py::arg("fabric"), py::arg("method"));
  m.def("omega", &analysis::omegaDeg, py::arg("theta_sigma_deg"), py::arg("theta_strain_rate_deg") = 90.0);
  m.def(
      "phi_mob", [](const py::dict& s) { return analysis::phiMobDeg(stressFromDict(s)); }, py::arg("stress"));
  // grainlab.read_lammps: the same import as `grainlab import lammps` (engine/interop/lammps).
  m.def(
      "import_lammps",
      [](const std::vector<std::string>& dumps, const std::string& out, std::optional<double> timestep,
         int framesEvery) {
        lammps::ImportOptions options;
        options.timestep = timestep;
        options.framesEvery = framesEvery;
        lammps::ImportReport r;
        {
          py::gil_scoped_release release;
          r = lammps::importLammps(dumps, out, options);
        }
        return py::dict(py::arg("frames") = r.frames, py::arg("first_timestep") = r.firstTimestep,
                        py::arg("last_timestep") = r.lastTimestep, py::arg("particles") = r.particles,
                        py::arg("warning") = r.warning);
      },
      py::arg("dumps"), py::arg("out"), py::arg("timestep") = py::none(), py::arg("frames_every") = 0);
}

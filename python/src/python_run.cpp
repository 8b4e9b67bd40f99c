#include "python_run.hpp"

#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/observer_tee.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/periodic_cell.hpp"
#include "grainlab/run.hpp"
#include "grainlab/run_output.hpp"
#include "grainlab/world.hpp"

namespace grainlab::python {
namespace {

// Keeps what the run produces in memory and relays progress to Python. Runs on the thread
// that called grainlab.run, with the GIL released except inside onProgress.
class Collector : public RunObserver {
 public:
  explicit Collector(py::object progress) : progress_(std::move(progress)) {}

  void onSample(const Sample& sample, const World& world) override {
    rows_.push_back(sample.values);
    stages_.push_back(sample.stage);
    if (const PeriodicCell* cell = world.periodicCell()) cellRows_.push_back(cell->edges());
  }

  void onProgress(double fraction, std::string_view stage, const World&) override {
    if (cancel_) return;
    py::gil_scoped_acquire gil;
    // Python's SIGINT handler only runs when asked: here, every few hundred steps.
    if (PyErr_CheckSignals() != 0) {
      error_.emplace();
      cancel_ = true;
      return;
    }
    if (progress_.is_none()) return;
    try {
      progress_(fraction, std::string(stage));
    } catch (py::error_already_set& e) {
      error_.emplace(std::move(e));
      cancel_ = true;
    }
  }

  bool cancelRequested() override { return cancel_; }

  void onFinish(const RunSummary& summary, const World& world) override {
    summary_ = summaryJson(summary, world);
    if (const PeriodicCell* cell = world.periodicCell()) finalCell_ = cell->edges();
    const auto x = world.positions();
    const auto v = world.velocities();
    for (int k = 0; k < world.size(); ++k) {
      id_.push_back(k);
      const ShapeKind kind = world.shapes()[k];
      shape_.push_back(kind == ShapeKind::Disc ? "disc" : kind == ShapeKind::Clump ? "clump" : "polygon");
      px_.push_back(x[k].x());
      py_.push_back(x[k].y());
      angle_.push_back(world.angles()[k]);
      vx_.push_back(v[k].x());
      vy_.push_back(v[k].y());
      spin_.push_back(world.spins()[k]);
      radius_.push_back(world.boundingRadii()[k]);
      boundary_.push_back(world.boundaryFlags()[k] ? 1 : 0);
    }
    world.contacts(contacts_);
    // j's centre as i meets it: in a periodic cell the nearest image, so lj is the branch
    // vector the contact acts through (as contacts_final.csv writes it).
    const PeriodicCell* cell = world.periodicCell();
    for (const ContactRecord& c : contacts_) {
      if (c.isWall()) jCentre_.emplace_back(std::nan(""), std::nan(""));
      else if (cell) jCentre_.push_back(x[c.i] + cell->minimumImage(x[c.j] - x[c.i]));
      else jCentre_.push_back(x[c.j]);
    }
  }

  // Called with the GIL held, after the run.
  py::dict result() {
    if (error_) {
      // Ctrl-C or the callable's own exception, raised only now that the run has stopped.
      error_->restore();
      error_.reset();
      throw py::error_already_set();
    }
    py::dict out;
    out["columns"] = seriesColumns();
    out["stages"] = stages_;
    const auto cols = static_cast<py::ssize_t>(seriesColumns().size());
    py::array_t<double> values({static_cast<py::ssize_t>(rows_.size()), cols});
    auto m = values.mutable_unchecked<2>();
    for (size_t r = 0; r < rows_.size(); ++r)
      for (py::ssize_t c = 0; c < cols; ++c) m(static_cast<py::ssize_t>(r), c) = rows_[r][static_cast<size_t>(c)];
    out["values"] = values;

    // A periodic cell's edges h (columns h1, h2, m) at the end and at each sample; None for a ring.
    out["cell"] = py::none();
    out["cell_series"] = py::none();
    if (finalCell_) {
      py::array_t<double> h({2, 2});
      auto hm = h.mutable_unchecked<2>();
      for (py::ssize_t a = 0; a < 2; ++a)
        for (py::ssize_t b = 0; b < 2; ++b) hm(a, b) = (*finalCell_)(a, b);
      out["cell"] = h;
      py::array_t<double> series({static_cast<py::ssize_t>(cellRows_.size()), py::ssize_t{2}, py::ssize_t{2}});
      auto sm = series.mutable_unchecked<3>();
      for (size_t r = 0; r < cellRows_.size(); ++r)
        for (py::ssize_t a = 0; a < 2; ++a)
          for (py::ssize_t b = 0; b < 2; ++b) sm(static_cast<py::ssize_t>(r), a, b) = cellRows_[r](a, b);
      out["cell_series"] = series;
    }

    // The keys of summary.json, as OutputWriter writes them.
    out["summary"] = py::module_::import("json").attr("loads")(summary_.dump());

    py::dict p;
    p["id"] = column(id_);
    p["shape"] = py::array(py::cast(shape_));
    p["x"] = column(px_);
    p["y"] = column(py_);
    p["angle"] = column(angle_);
    p["vx"] = column(vx_);
    p["vy"] = column(vy_);
    p["spin"] = column(spin_);
    p["radius"] = column(radius_);
    p["boundary"] = column(boundary_);
    out["particles"] = p;

    std::vector<long long> ci, cj;
    std::vector<double> cols12[10];
    const double nan = std::nan("");
    for (size_t k = 0; k < contacts_.size(); ++k) {
      const ContactRecord& c = contacts_[k];
      ci.push_back(c.i);
      cj.push_back(c.j);
      const Vec2 li = c.point - Vec2(px_[c.i], py_[c.i]);
      const Vec2 lj = c.isWall() ? Vec2(nan, nan) : Vec2(c.point - jCentre_[k]);
      const double row[10] = {c.point.x(), c.point.y(), c.normal.x(), c.normal.y(), c.fn, c.ft,
                              li.x(),      li.y(),      lj.x(),       lj.y()};
      for (int k = 0; k < 10; ++k) cols12[k].push_back(row[k]);
    }
    py::dict c;
    c["i"] = column(ci);
    c["j"] = column(cj);
    const char* names[10] = {"px", "py", "nx", "ny", "fn", "ft", "lix", "liy", "ljx", "ljy"};
    for (int k = 0; k < 10; ++k) c[names[k]] = column(cols12[k]);
    out["contacts"] = c;
    return out;
  }

 private:
  py::object progress_;
  bool cancel_ = false;
  std::optional<py::error_already_set> error_;
  std::vector<std::vector<double>> rows_;
  std::vector<std::string> stages_;
  std::vector<Eigen::Matrix2d> cellRows_;    // h at each sample, for a run in a periodic cell
  std::optional<Eigen::Matrix2d> finalCell_;
  nlohmann::json summary_;  // summary.json's content
  std::vector<long long> id_;
  std::vector<std::string> shape_;
  std::vector<double> px_, py_, angle_, vx_, vy_, spin_, radius_;
  std::vector<unsigned char> boundary_;
  std::vector<ContactRecord> contacts_;
  std::vector<Vec2> jCentre_;  // per contact
};

}  // namespace

py::dict runScene(const Scene& scene, const std::string& out, const py::object& progress) {
  Collector collector(progress);
  ObserverTee observers{&collector};
  std::optional<RunOutput> files;  // what `grainlab run --out` writes
  if (!out.empty()) observers.add(files.emplace(out, scene, nullptr));
  RunSummary summary;
  {
    py::gil_scoped_release release;
    summary = grainlab::runScene(scene, observers);
  }
  // Past a hard limit of the validity envelope: a bad scene, raised as SceneError naming the
  // field (the error starts "field: ..."). Nothing was run or written.
  if (summary.refusedInvalid) {
    const size_t colon = summary.error.find(": ");
    throw SceneError(summary.error.substr(0, colon), colon == std::string::npos ? "" : summary.error.substr(colon + 2));
  }
  return collector.result();
}

}  // namespace grainlab::python

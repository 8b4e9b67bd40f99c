#include "grainlab/studies/shape_fidelity/shape_study.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <mutex>
#include <optional>
#include <thread>

#include "grainlab/errors.hpp"
#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/studies/paper/csv_table.hpp"
#include "grainlab/studies/paper/ensemble_stats.hpp"
#include "grainlab/studies/paper/parallel_runs.hpp"
#include "grainlab/studies/paper/shearing_recorder.hpp"
#include "grainlab/studies/tradeoff/ensemble_quantities.hpp"
#include "grainlab/studies/tradeoff/metrics.hpp"
#include "grainlab/studies/tradeoff/paired_bias.hpp"
#include "grainlab/thread_cpu_clock.hpp"

namespace grainlab::shapes {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The trade-off's quantities, and the packing each shape reaches before it is sheared (the
// tolerance of the other void ratios: three units of the paper's last digit).
const std::vector<tradeoff::Quantity>& quantities() {
  static const std::vector<tradeoff::Quantity> q = [] {
    std::vector<tradeoff::Quantity> all = tradeoff::ensembleQuantities();
    all.push_back({"void_ratio_consolidated", 0.003, false});
    return all;
  }();
  return q;
}

// One run of the study: a representation on a specimen ("random", "bedding-30", or "circular"
// for discs, which have no fabric to lay out) with a seed.
struct RunSpec {
  Representation representation;
  std::string assembly;  // the assembly whose preset it runs (for discs: the first asked)
  std::string specimen;
  int seed = 1;
  std::string key(bool quick) const {
    return std::string(quick ? "quick" : "full") + "-" + representation.name() + "-" + specimen + "-seed-" +
           std::to_string(seed);
  }
};

struct RunRecord {
  std::string status;
  std::string error;
  double cpuSeconds = kNaN;  // the whole run's, preparation included: each shape prepares its own specimen
  double wallSeconds = kNaN;
  std::vector<double> values;  // by quantities()
};

RunRecord runOne(const nlohmann::json& sceneJson) {
  RunRecord r;
  report::AssemblyResult shearing;
  report::ShearingRecorder recorder(shearing);
  RunSummary summary;
  const double cpu0 = threadCpuSeconds();
  try {
    summary = runScene(parseScene(sceneJson), recorder);
  } catch (const std::exception& e) {
    summary.status = RunStatus::Failed;
    summary.error = e.what();
  }
  r.cpuSeconds = threadCpuSeconds() - cpu0;
  r.wallSeconds = summary.wallSeconds;
  r.status = std::string(toString(summary.status));
  r.error = summary.error;
  if (summary.status == RunStatus::Completed) {
    r.values = tradeoff::measureQuantities(shearing.shearing, summary.peakPhiMobDeg);
    r.values.push_back(summary.voidRatioAfterConsolidation >= 0 ? summary.voidRatioAfterConsolidation : kNaN);
  } else {
    r.values.assign(quantities().size(), kNaN);
  }
  return r;
}

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
double number(const nlohmann::json& j) { return j.is_number() ? j.get<double>() : kNaN; }

// Written whole to a side file and renamed into place: a record on disk is a finished run.
void save(const fs::path& path, const RunRecord& r) {
  nlohmann::json j{{"status", r.status}, {"error", r.error}, {"cpu_s", number(r.cpuSeconds)},
                   {"wall_s", number(r.wallSeconds)}};
  for (size_t q = 0; q < quantities().size(); ++q) j["values"][quantities()[q].name] = number(r.values[q]);
  const fs::path partial = path.string() + ".partial";
  {
    std::ofstream out(partial);
    out << j.dump(1) << "\n";
    if (!out) throw std::runtime_error("cannot write " + partial.string());
  }
  fs::rename(partial, path);
}

std::optional<RunRecord> load(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    RunRecord r{j.at("status").get<std::string>(), j.value("error", ""), number(j.at("cpu_s")), number(j.at("wall_s")), {}};
    for (const tradeoff::Quantity& q : quantities())
      r.values.push_back(j.at("values").contains(q.name) ? number(j.at("values").at(q.name)) : kNaN);
    return r;
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable: run it again
  }
}

std::string axisOf(const Representation& r) {
  switch (r.shape) {
    case Shape::Hexagons: return "reference";
    case Shape::Clumps: return "clumps";
    case Shape::RollingDiscs: return "rolling discs";
    case Shape::Discs: return "discs";
  }
  return {};
}

}  // namespace

std::vector<std::string> shapeQuantityNames() {
  std::vector<std::string> names;
  for (const tradeoff::Quantity& q : quantities()) names.push_back(q.name);
  return names;
}

ShapeStudy runShapeStudy(const ShapeStudyOptions& opt, std::ostream* progress) {
  if (opt.outDir.empty()) throw SceneError("--out", "give the directory the study writes (and resumes) in");
  if (opt.seeds < 2) throw SceneError("--seeds", "an interval needs 2 seeds or more");
  std::vector<std::string> assemblies = opt.assemblies.empty() ? shapeAssemblies() : opt.assemblies;
  for (const std::string& a : assemblies)
    if (std::find(shapeAssemblies().begin(), shapeAssemblies().end(), a) == shapeAssemblies().end())
      throw SceneError("--assemblies", "\"" + a + "\" is not one of random, bedding-30");
  std::vector<Representation> reps{Representation{}};  // the hexagons, the reference, first
  for (const Representation& r : opt.representations)
    if (std::none_of(reps.begin(), reps.end(), [&](const Representation& x) { return x.name() == r.name(); }))
      reps.push_back(r);

  auto specimenOf = [&](const Representation& r, const std::string& assembly) {
    return r.carriesFabric() ? assembly : std::string("circular");
  };
  std::vector<RunSpec> specs;
  for (const Representation& r : reps)
    for (const std::string& a : assemblies) {
      if (!r.carriesFabric() && a != assemblies.front()) continue;
      for (int seed = 1; seed <= opt.seeds; ++seed) specs.push_back({r, a, specimenOf(r, a), seed});
    }

  const fs::path dir = opt.outDir;
  fs::create_directories(dir / "runs");
  fs::create_directories(dir / "scenes");
  std::vector<std::optional<RunRecord>> records(specs.size());
  std::vector<size_t> todo;
  for (size_t k = 0; k < specs.size(); ++k) {
    records[k] = load(dir / "runs" / (specs[k].key(opt.quick) + ".json"));
    if (!records[k]) todo.push_back(k);
  }
  ShapeStudy study;
  study.runs = specs.size();
  study.runsSkipped = specs.size() - todo.size();
  if (progress)
    *progress << "shapes: " << specs.size() << " runs, " << study.runsSkipped << " already done, running "
              << todo.size() << "\n";

  // In the order planned: the hexagons, the longest runs, first.
  std::atomic<size_t> next{0}, done{0};
  std::mutex lock;
  auto worker = [&] {
    for (size_t i = next++; i < todo.size(); i = next++) {
      const RunSpec& s = specs[todo[i]];
      const nlohmann::json scene = representationScene(s.representation, s.assembly, opt.quick, s.seed);
      std::ofstream(dir / "scenes" / (s.key(opt.quick) + ".json")) << scene.dump(2) << "\n";
      RunRecord r = runOne(scene);
      save(dir / "runs" / (s.key(opt.quick) + ".json"), r);
      const std::lock_guard guard(lock);
      ++done;
      if (progress)
        *progress << "shapes: [" << done << "/" << todo.size() << "] " << s.key(opt.quick) << ": " << r.status << " in "
                  << std::setprecision(3) << r.cpuSeconds << " cpu s" << (r.error.empty() ? "" : " (" + r.error + ")")
                  << "\n";
      records[todo[i]] = std::move(r);
    }
  };
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < report::concurrentRuns(opt.jobs, todo.size()); ++t) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();

  for (const auto& r : records) study.failedRuns += r->status != "completed";

  // The runs of one representation on one specimen, by seed.
  auto ensemble = [&](const Representation& r, const std::string& specimen) {
    std::vector<const RunRecord*> out;
    for (size_t k = 0; k < specs.size(); ++k)
      if (specs[k].representation.name() == r.name() && specs[k].specimen == specimen) out.push_back(&*records[k]);
    return out;
  };
  auto column = [](const std::vector<const RunRecord*>& runs, size_t q) {
    std::vector<double> v;
    for (const RunRecord* r : runs) v.push_back(r->values[q]);
    return v;
  };
  auto cpuOf = [](const std::vector<const RunRecord*>& runs) {
    std::vector<double> v;
    for (const RunRecord* r : runs) v.push_back(r->cpuSeconds);
    return report::meanInterval(v);
  };
  auto failedIn = [](const std::vector<const RunRecord*>& runs) {
    int n = 0;
    for (const RunRecord* r : runs) n += r->status != "completed";
    return n;
  };

  const std::string size = opt.quick ? "quick" : "full";
  report::CsvTable table({"size", "assembly", "representation", "preset", "clump_discs", "rolling_friction", "quantity",
                          "tolerance", "seeds", "mean", "mean_ci_low", "mean_ci_high", "reference_seeds",
                          "reference_mean", "bias", "bias_ci_low", "bias_ci_high", "welch_t", "sd", "verdict", "runs_for_tolerance", "cpu_s",
                          "cpu_s_ci_low", "cpu_s_ci_high", "cost_ratio", "failed_runs"});
  for (const std::string& a : assemblies) {
    const std::vector<const RunRecord*> reference = ensemble(reps.front(), a);
    const report::MeanInterval referenceCpu = cpuOf(reference);
    tradeoff::ParetoPanel panel{size + " " + a + " (" + std::to_string(opt.seeds) + " seeds)", {}};
    for (const Representation& r : reps) {
      const std::vector<const RunRecord*> runs = ensemble(r, specimenOf(r, a));
      const report::MeanInterval cpu = cpuOf(runs);
      const bool isReference = r.shape == Shape::Hexagons;
      for (size_t q = 0; q < quantities().size(); ++q) {
        const tradeoff::Quantity& qu = quantities()[q];
        const std::vector<double> values = column(runs, q), referenceValues = column(reference, q);
        // θσ lies near the vertical (90°) in a biaxial test, ω near 0: each mean is shown near its own.
        const double centre = qu.name.starts_with("theta_sigma_") ? 90.0 : 0.0;
        const report::MeanInterval refMean =
            qu.axial ? report::axialMeanIntervalNear(referenceValues, centre) : report::meanInterval(referenceValues);
        const report::MeanInterval mean = qu.axial ? report::axialMeanIntervalNear(values, refMean.mean) : report::meanInterval(values);
        const tradeoff::BiasEstimate e =
            isReference ? tradeoff::BiasEstimate{} : tradeoff::unpairedBias(values, referenceValues, qu.tolerance, qu.axial);
        table.addRow({size, a, r.name(), representationPreset(r, a, opt.quick), r.clumpDiscs,
                      r.shape == Shape::RollingDiscs ? r.rollingFriction : 0.0, qu.name, qu.tolerance, mean.n,
                      mean.mean, mean.low, mean.high, refMean.n, refMean.mean, e.bias, e.low, e.high, e.t,
                      isReference ? mean.sd : e.sd, isReference ? std::string("reference") : e.verdict, e.runsForTolerance, cpu.mean, cpu.low,
                      cpu.high, cpu.mean / referenceCpu.mean, failedIn(runs)});
        if (q != 0) continue;  // the plot: peak φ_mob
        // |bias| with the interval's image under |·|: it holds |true bias| whenever the interval
        // holds the true bias.
        tradeoff::ParetoPoint p{cpu.mean, isReference ? 0.0 : std::abs(e.bias), r.name(), axisOf(r), false};
        if (!isReference && std::isfinite(e.low)) {
          p.errorLow = e.low <= 0 && e.high >= 0 ? 0.0 : std::min(std::abs(e.low), std::abs(e.high));
          p.errorHigh = std::max(std::abs(e.low), std::abs(e.high));
        }
        panel.points.push_back(p);
      }
    }
    std::vector<double> seconds, error;
    for (const tradeoff::ParetoPoint& p : panel.points) {
      seconds.push_back(p.seconds);
      error.push_back(p.error);
    }
    for (size_t i : tradeoff::paretoFront(seconds, error)) panel.points[i].onFront = true;
    study.panels.push_back(panel);
  }
  table.write((dir / "shapes.csv").string());

  std::vector<std::string> runHeader{"size", "representation", "specimen", "seed", "status", "cpu_s", "wall_s"};
  for (const tradeoff::Quantity& q : quantities()) runHeader.push_back(q.name);
  report::CsvTable runsTable(runHeader);
  for (size_t k = 0; k < specs.size(); ++k) {
    const RunRecord& r = *records[k];
    std::vector<report::CsvCell> row{size, specs[k].representation.name(), specs[k].specimen, specs[k].seed, r.status,
                                     r.cpuSeconds, r.wallSeconds};
    for (double v : r.values) row.emplace_back(v);
    runsTable.addRow(row);
  }
  runsTable.write((dir / "runs.csv").string());

  // μ_r calibrated to the hexagons' mean peak φ_mob on the random assembly.
  report::CsvTable calibration({"size", "kind", "rolling_friction", "seeds", "mean_peak_phi_mob_deg", "ci_low",
                                "ci_high", "hexagons_mean_peak_phi_mob_deg", "note"});
  if (std::find(assemblies.begin(), assemblies.end(), "random") != assemblies.end()) {
    const double target = report::meanInterval(column(ensemble(reps.front(), "random"), 0)).mean;
    std::vector<CalibrationPoint> points;
    for (const Representation& r : reps) {
      if (r.shape != Shape::RollingDiscs) continue;
      const report::MeanInterval m = report::meanInterval(column(ensemble(r, "circular"), 0));
      points.push_back({r.rollingFriction, m.mean});
      calibration.addRow({size, "measured", r.rollingFriction, m.n, m.mean, m.low, m.high, target, ""});
    }
    study.calibration = interpolateRollingFriction(points, target);
    calibration.addRow({size, "interpolated", study.calibration.rollingFriction, 0, target, kNaN, kNaN, target,
                        study.calibration.note});
  }
  calibration.write((dir / "calibration.csv").string());
  return study;
}

}  // namespace grainlab::shapes

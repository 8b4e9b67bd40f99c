#include "grainlab/studies/tradeoff/tradeoff_study.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <mutex>
#include <thread>

#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/studies/paper/csv_table.hpp"
#include "grainlab/studies/paper/parallel_runs.hpp"
#include "grainlab/studies/paper/shearing_recorder.hpp"
#include "grainlab/studies/tradeoff/metrics.hpp"
#include "grainlab/thread_cpu_clock.hpp"

namespace grainlab::tradeoff {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Outcome {
  RunSummary summary;
  double cpuSeconds = kNaN;
  double strainRate = kNaN;  // 1/s of the shearing stage
  RunMetrics metrics;
};

// Runs the scenes on up to `jobs` threads, most expensive first (the caller orders them).
std::vector<Outcome> runAll(const std::vector<nlohmann::json>& scenes, const std::vector<std::string>& names,
                            unsigned jobs, std::ostream* progress) {
  std::vector<Outcome> outcomes(scenes.size());
  std::atomic<size_t> next{0}, done{0};
  std::mutex progressLock;
  auto worker = [&] {
    for (size_t k = next++; k < scenes.size(); k = next++) {
      Outcome& o = outcomes[k];
      report::AssemblyResult shearing;
      report::ShearingRecorder recorder(shearing);
      try {
        const Scene scene = parseScene(scenes[k]);
        for (const StageSpec& s : scene.stages) {
          if (s.type == StageSpec::Type::Biaxial) o.strainRate = s.strainRate;
        }
        const double cpu0 = threadCpuSeconds();
        o.summary = runScene(scene, recorder);
        o.cpuSeconds = threadCpuSeconds() - cpu0;
      } catch (const std::exception& e) {  // a scene the parser refuses: set-up only
        o.summary.status = RunStatus::Failed;
        o.summary.error = e.what();
      }
      o.metrics = measureRun(shearing.shearing, o.summary.peakPhiMobDeg, o.summary.voidRatioAfterConsolidation);
      const std::lock_guard lock(progressLock);
      ++done;
      if (!progress) continue;
      *progress << "tradeoff: [" << done << "/" << scenes.size() << "] " << names[k] << ": " << o.summary.status
                << " in " << std::setprecision(3) << o.summary.wallSeconds << " s"
                << (o.summary.error.empty() ? "" : " (" + o.summary.error + ")") << "\n";
    }
  };
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < report::concurrentRuns(jobs, scenes.size()); ++t) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  return outcomes;
}

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (const std::string& i : items) s += (s.empty() ? "" : "; ") + i;
  return s;
}

}  // namespace

TradeoffStudy runTradeoff(const TradeoffOptions& opt, std::ostream* progress) {
  SweepPlan plan = opt.quick ? quickPlan() : fullPlan();
  if (!opt.presets.empty()) plan.presets = opt.presets;
  if (!opt.axes.empty()) keepAxes(plan, opt.axes);
  for (const std::string& p : plan.presets) presetScene(p);  // an unknown preset fails here

  // The engine axis exists only where the scene parser takes "box2d".
  const std::optional<std::string> refusal = box2dRefusal(plan.presets.front());
  if (refusal && progress) *progress << "tradeoff: engine axis skipped: the parser refuses box2d (" << *refusal << ")\n";
  const std::vector<Setting> settings = expandPlan(plan, refusal);

  // One run per distinct scene; the baseline is shared by every axis.
  std::vector<size_t> runOf(settings.size());
  std::vector<size_t> runSetting;  // run -> its first setting
  for (size_t k = 0; k < settings.size(); ++k) {
    size_t r = 0;
    while (r < runSetting.size() && !settings[runSetting[r]].sameRun(settings[k])) ++r;
    if (r == runSetting.size()) runSetting.push_back(k);
    runOf[k] = r;
  }
  // Most expensive first, so the last to finish is a short one: by timestep, shearing rate
  // and shape (a polygon step costs a few disc steps).
  std::vector<size_t> order(runSetting.size());
  for (size_t r = 0; r < order.size(); ++r) order[r] = r;
  auto cost = [&](size_t r) {
    const Setting& s = settings[runSetting[r]];
    const int vertices = s.vertices > 0 ? s.vertices : presetVertices(s.preset);
    return (1 + 1e-3 / s.inertialNumber) / s.timestepSafety * (vertices > 0 ? vertices / 2.0 : 1.0);
  };
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return cost(a) > cost(b); });

  const std::filesystem::path dir = opt.outDir;
  std::filesystem::create_directories(dir / "scenes");
  std::vector<nlohmann::json> scenes;
  std::vector<std::string> names, sceneFiles(runSetting.size());
  for (size_t r : order) {
    const Setting& s = settings[runSetting[r]];
    scenes.push_back(settingScene(s));
    names.push_back(s.preset + " " + s.axis + " " + s.value);
    char file[32];
    std::snprintf(file, sizeof file, "run-%02zu.json", r);
    sceneFiles[r] = std::string("scenes/") + file;
    std::ofstream(dir / sceneFiles[r]) << scenes.back().dump(2) << "\n";
  }
  if (progress) {
    *progress << "tradeoff: " << settings.size() << " settings, " << scenes.size() << " runs, "
              << report::concurrentRuns(opt.jobs, scenes.size()) << " at a time\n";
  }
  const std::vector<Outcome> ordered = runAll(scenes, names, opt.jobs, progress);
  std::vector<Outcome> outcome(runSetting.size());
  for (size_t k = 0; k < order.size(); ++k) outcome[order[k]] = ordered[k];

  // Errors against each preset's reference run.
  std::vector<std::vector<double>> errors(runSetting.size());
  std::vector<double> maxAngle(runSetting.size(), kNaN), meanAngle(runSetting.size(), kNaN);
  for (size_t r = 0; r < runSetting.size(); ++r) {
    const Setting& s = settings[runSetting[r]];
    size_t ref = 0;
    while (!(settings[runSetting[ref]].preset == s.preset && settings[runSetting[ref]].axis == "reference")) ++ref;
    const bool usable = outcome[r].summary.status == RunStatus::Completed && outcome[ref].summary.status == RunStatus::Completed;
    errors[r] = usable ? metricErrors(outcome[r].metrics, outcome[ref].metrics)
                       : std::vector<double>(errorNames().size(), kNaN);
    maxAngle[r] = maxAngleErrorDeg(errors[r]);
    meanAngle[r] = meanAngleErrorDeg(errors[r]);
  }
  // The Pareto front of cost against the mean angle error, per preset.
  auto costOf = [&](size_t r) { return opt.cost == "cpu" ? outcome[r].cpuSeconds : outcome[r].summary.wallSeconds; };
  std::vector<bool> onFront(runSetting.size(), false);
  std::vector<ParetoPanel> panels;
  for (const std::string& preset : plan.presets) {
    std::vector<size_t> runs;
    std::vector<double> seconds, error;
    for (size_t r = 0; r < runSetting.size(); ++r) {
      if (settings[runSetting[r]].preset != preset) continue;
      runs.push_back(r);
      seconds.push_back(costOf(r));
      error.push_back(meanAngle[r]);
    }
    for (size_t i : paretoFront(seconds, error)) onFront[runs[i]] = true;
    ParetoPanel panel{preset, {}};
    for (size_t r : runs) {
      const Setting& s = settings[runSetting[r]];
      // The run shared by several axes is the baseline they all turn away from.
      const bool baseline = std::count(runOf.begin(), runOf.end(), r) > 1;
      const std::string axis = baseline ? "baseline" : s.axis;
      const std::string label = baseline || s.axis == "reference" || s.axis == "noise" ? axis : s.value;
      panel.points.push_back({costOf(r), meanAngle[r], label, axis, onFront[r]});
      if (s.axis == "noise") panel.noiseFloor = meanAngle[r];
    }
    panels.push_back(panel);
  }

  std::vector<std::string> header{"preset", "axis", "value", "timestep_safety", "inertial_number", "strain_rate_per_s",
                                  "vertices", "sample_strain", "engine", "status", "wall_s", "cpu_s", "steps",
                                  "particles", "measured_inertial_number", "shearing_kinetic_energy",
                                  "peak_phi_mob_deg", "phi_mob_20_deg"};
  for (double e : kOmegaStrains) header.push_back("omega_" + std::to_string(std::lround(100 * e)) + "_deg");
  header.insert(header.end(), {"theta_sigma_gap_deg", "void_ratio"});
  for (const std::string& n : errorNames()) header.push_back("err_" + n);
  header.insert(header.end(), {"mean_angle_error_deg", "max_angle_error_deg", "pareto", "scene", "note"});
  report::CsvTable table(header);
  for (size_t k = 0; k < settings.size(); ++k) {
    const Setting& s = settings[k];
    const size_t r = runOf[k];
    const Outcome& o = outcome[r];
    const RunMetrics& m = o.metrics;
    const int vertices = s.vertices > 0 ? s.vertices : presetVertices(s.preset);
    std::vector<report::CsvCell> row{s.preset, s.axis, s.value, s.timestepSafety, s.inertialNumber, o.strainRate,
                                     vertices > 0 ? report::CsvCell(vertices) : report::CsvCell(""),
                                     s.sampleStrain, s.engine, std::string(toString(o.summary.status)), o.summary.wallSeconds,
                                     o.cpuSeconds, static_cast<double>(o.summary.steps), o.summary.particles,
                                     m.inertialNumber, m.kineticEnergy, m.peakPhiMobDeg, m.phiMobAtEndDeg};
    for (double w : m.omegaDeg) row.emplace_back(w);
    row.insert(row.end(), {m.thetaSigmaGapDeg, m.voidRatio >= 0 ? m.voidRatio : kNaN});
    for (double e : errors[r]) row.emplace_back(e);
    std::vector<std::string> notes = o.summary.notes;
    if (!o.summary.error.empty()) notes.insert(notes.begin(), o.summary.error);
    row.insert(row.end(), {meanAngle[r], maxAngle[r], onFront[r] ? 1 : 0, sceneFiles[r], joined(notes)});
    table.addRow(row);
  }
  if (refusal) {
    for (const std::string& preset : plan.presets) {
      std::vector<report::CsvCell> row(header.size(), report::CsvCell(""));
      row[0] = preset;
      row[1] = "engine";
      row[2] = "box2d";
      row[8] = "box2d";
      row[9] = "skipped";
      row.back() = "the scene parser refuses it: " + *refusal;
      table.addRow(row);
    }
  }
  table.write((dir / "tradeoff.csv").string());
  TradeoffStudy study;
  study.panels = std::move(panels);
  for (size_t k = 0; k < settings.size(); ++k) {
    const size_t r = runOf[k];
    study.settings.push_back({settings[k], outcome[r].summary.wallSeconds, outcome[r].cpuSeconds, meanAngle[r],
                              maxAngle[r], errors[r].back(), onFront[r]});
  }
  for (const Outcome& o : outcome) study.failedRuns += o.summary.status != RunStatus::Completed;
  return study;
}

}  // namespace grainlab::tradeoff

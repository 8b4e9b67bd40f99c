#include "grainlab/studies/tradeoff/ensemble_tradeoff.hpp"

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

#include "grainlab/observer_tee.hpp"
#include "grainlab/prepared_specimen.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/studies/paper/csv_table.hpp"
#include "grainlab/studies/paper/ensemble_stats.hpp"
#include "grainlab/studies/paper/parallel_runs.hpp"
#include "grainlab/studies/paper/shearing_recorder.hpp"
#include "grainlab/studies/tradeoff/ensemble_quantities.hpp"
#include "grainlab/studies/tradeoff/metrics.hpp"
#include "grainlab/thread_cpu_clock.hpp"

namespace grainlab::tradeoff {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The servo is designed to hold σ11 within 2% (engine/src/membrane_stages.cpp): a setting whose
// median deviation is larger tests another boundary condition, and the study says so.
constexpr double kLateralStressHeld = 0.02;

struct Job {
  nlohmann::json scene;
  std::string name;
  std::string stageDirectory;  // where a preparing run keeps its stages' ends; empty: nowhere
};

struct Result {
  RunSummary summary;
  double cpuSeconds = kNaN;         // of the shearing: the run's less its preparation's
  double preparationCpuSeconds = kNaN;
  double lateralStressOff = kNaN;
  std::vector<double> values;  // by ensembleQuantities()
};

// The thread's CPU time at the last sample before the shearing stage (the preparation's last,
// taken as its last stage ends): what preparing, or loading, the specimen cost.
class ShearingClock : public RunObserver {
 public:
  explicit ShearingClock(std::string shearing) : shearing_(std::move(shearing)) {}
  void onSample(const Sample& sample, const World&) override {
    if (sample.stage != shearing_ && !shearingSeen_) reached_ = threadCpuSeconds();
    shearingSeen_ = shearingSeen_ || sample.stage == shearing_;
  }
  double reached() const { return reached_; }

 private:
  std::string shearing_;
  double reached_ = kNaN;
  bool shearingSeen_ = false;
};

std::string shearingStageName(const Scene& scene) {
  for (const StageSpec& s : scene.stages)
    if (isShearing(s.type)) return s.name;
  return {};
}

double shearingPressure(const Scene& scene) {
  for (const StageSpec& s : scene.stages)
    if (s.type == StageSpec::Type::Biaxial) return s.pressure;
  return kNaN;
}

std::vector<Result> runJobs(const std::vector<Job>& jobs, unsigned threadsAsked, std::ostream* progress) {
  std::vector<Result> results(jobs.size());
  std::atomic<size_t> next{0}, done{0};
  std::mutex lock;
  auto worker = [&] {
    for (size_t k = next++; k < jobs.size(); k = next++) {
      Result& r = results[k];
      report::AssemblyResult shearing;
      report::ShearingRecorder recorder(shearing);
      double pressure = kNaN;
      try {
        const Scene scene = parseScene(jobs[k].scene);
        pressure = shearingPressure(scene);
        ShearingClock clock(shearingStageName(scene));
        ObserverTee observers{&recorder, &clock};
        const double cpu0 = threadCpuSeconds();
        r.summary = runScene(scene, observers, {}, {}, jobs[k].stageDirectory);
        const double cpu1 = threadCpuSeconds();
        r.preparationCpuSeconds = clock.reached() - cpu0;
        r.cpuSeconds = cpu1 - clock.reached();
      } catch (const std::exception& e) {
        r.summary.status = RunStatus::Failed;
        r.summary.error = e.what();
      }
      const bool ok = r.summary.status == RunStatus::Completed;
      r.values = ok ? measureQuantities(shearing.shearing, r.summary.peakPhiMobDeg)
                    : std::vector<double>(ensembleQuantities().size(), kNaN);
      r.lateralStressOff = ok ? lateralStressDeviation(shearing.shearing, pressure) : kNaN;
      const std::lock_guard guard(lock);
      ++done;
      if (progress) {
        *progress << "tradeoff: [" << done << "/" << jobs.size() << "] " << jobs[k].name << ": " << r.summary.status
                  << " in " << std::setprecision(3) << r.cpuSeconds << " cpu s"
                  << (r.summary.error.empty() ? "" : " (" + r.summary.error + ")") << "\n";
      }
    }
  };
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < report::concurrentRuns(threadsAsked, jobs.size()); ++t) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  return results;
}

// The setting's scene for one seed; the strain rate is the one that gives the setting's inertial
// number on that seed's specimen.
nlohmann::json seedScene(const Setting& s, int seed) {
  nlohmann::json scene = settingScene(s);
  scene["seed"] = seed;
  scene["name"] = scene["name"].get<std::string>() + ", seed " + std::to_string(seed);
  const double rate = strainRateFor(scene, s.inertialNumber);
  for (nlohmann::json& stage : scene["stages"])
    if (stage.value("type", "") == "biaxial") stage["strain_rate"] = rate;
  return scene;
}

// Only the shearing changes: the setting can shear the reference's specimen.
bool shearingOnly(const Setting& s, const Setting& reference) {
  return s.engine == reference.engine && s.vertices == reference.vertices &&
         s.velocityIterations == reference.velocityIterations;
}

// The stage a shearing setting starts after: the one before the preset's first shearing stage.
std::string preparedStage(const std::string& preset) {
  const Scene scene = parseScene(presetScene(preset));
  for (size_t k = 1; k < scene.stages.size(); ++k)
    if (isShearing(scene.stages[k].type)) return scene.stages[k - 1].name;
  throw std::runtime_error(preset + ": no shearing stage after a preparation");
}

std::string text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

double mean(const std::vector<double>& v) { return report::meanInterval(v).mean; }

}  // namespace

EnsembleStudy runEnsembleTradeoff(const TradeoffOptions& opt, std::ostream* progress) {
  SweepPlan plan = opt.quick ? quickPlan() : fullPlan();
  if (!opt.presets.empty()) plan.presets = opt.presets;
  if (!opt.axes.empty()) keepAxes(plan, opt.axes);
  for (const std::string& p : plan.presets) presetScene(p);  // an unknown preset fails here
  const std::optional<std::string> refusal = box2dRefusal(plan.presets.front());
  const std::vector<Setting> settings = expandPlan(plan, refusal);
  const int seeds = opt.seeds;

  // Distinct runs (the baseline sits on every axis but runs once per seed).
  std::vector<size_t> runOf(settings.size()), runSetting;
  for (size_t k = 0; k < settings.size(); ++k) {
    size_t r = 0;
    while (r < runSetting.size() && !settings[runSetting[r]].sameRun(settings[k])) ++r;
    if (r == runSetting.size()) runSetting.push_back(k);
    runOf[k] = r;
  }
  auto referenceRun = [&](size_t r) {
    size_t ref = 0;
    while (!(settings[runSetting[ref]].preset == settings[runSetting[r]].preset &&
             settings[runSetting[ref]].axis == "reference"))
      ++ref;
    return ref;
  };
  std::vector<bool> paired(runSetting.size());
  for (size_t r = 0; r < runSetting.size(); ++r)
    paired[r] = shearingOnly(settings[runSetting[r]], settings[runSetting[referenceRun(r)]]);

  const fs::path dir = opt.outDir;
  fs::create_directories(dir / "scenes");
  auto specimenDir = [&](const std::string& preset, int seed) {
    return (dir / "specimens" / preset / ("seed-" + std::to_string(seed))).string();
  };
  // results[r][seed - 1]
  std::vector<std::vector<Result>> results(runSetting.size(), std::vector<Result>(static_cast<size_t>(seeds)));
  auto runPhase = [&](bool preparing) {
    std::vector<Job> jobs;
    std::vector<std::pair<size_t, int>> slots;
    for (size_t r = 0; r < runSetting.size(); ++r) {
      const Setting& s = settings[runSetting[r]];
      if ((s.axis == "reference") != preparing) continue;
      for (int seed = 1; seed <= seeds; ++seed) {
        Job job{seedScene(s, seed), s.preset + " " + s.axis + " " + s.value + " seed " + std::to_string(seed), {}};
        if (preparing) {
          job.scene["output"]["stage_checkpoints"] = true;
          job.stageDirectory = specimenDir(s.preset, seed);
        } else if (paired[r]) {
          job.scene["start_from"] = {{"checkpoint", stageCheckpointPath(specimenDir(s.preset, seed), preparedStage(s.preset))}};
        }
        char file[48];
        std::snprintf(file, sizeof file, "run-%02zu-seed-%d.json", r, seed);
        std::ofstream(dir / "scenes" / file) << job.scene.dump(2) << "\n";
        jobs.push_back(std::move(job));
        slots.emplace_back(r, seed);
      }
    }
    if (progress) *progress << "tradeoff: " << (preparing ? "preparing and shearing " : "testing ") << jobs.size() << " runs\n";
    std::vector<Result> out = runJobs(jobs, opt.jobs, progress);
    for (size_t k = 0; k < out.size(); ++k) results[slots[k].first][static_cast<size_t>(slots[k].second - 1)] = std::move(out[k]);
  };
  runPhase(true);
  runPhase(false);

  const std::vector<Quantity>& quantities = ensembleQuantities();
  auto column = [&](size_t r, size_t q) {
    std::vector<double> v;
    for (const Result& x : results[r]) v.push_back(x.values[q]);
    return v;
  };
  auto cpu = [&](size_t r) {
    std::vector<double> v;
    for (const Result& x : results[r]) v.push_back(x.cpuSeconds);
    return mean(v);
  };
  auto prep = [&](size_t r) {
    std::vector<double> v;
    for (const Result& x : results[r]) v.push_back(x.preparationCpuSeconds);
    return mean(v);
  };
  auto lateral = [&](size_t r) {
    std::vector<double> v;
    for (const Result& x : results[r]) v.push_back(x.lateralStressOff);
    return mean(v);
  };
  auto estimate = [&](size_t r, size_t q) {
    const size_t ref = referenceRun(r);
    const Quantity& qu = quantities[q];
    if (!paired[r]) return unpairedBias(column(r, q), column(ref, q), qu.tolerance, qu.axial);
    std::vector<double> d;
    for (size_t s = 0; s < static_cast<size_t>(seeds); ++s)
      d.push_back(difference(results[r][s].values[q], results[ref][s].values[q], qu.axial));
    return pairedBias(d, qu.tolerance);
  };
  // Per seed, the mean |difference| of the angle quantities from that seed's reference run.
  auto angleDeviation = [&](size_t r) {
    const size_t ref = referenceRun(r);
    std::vector<double> perSeed;
    for (size_t s = 0; s < static_cast<size_t>(seeds); ++s) {
      double sum = 0;
      int n = 0;
      for (size_t q = 0; q < quantities.size(); ++q) {
        if (quantities[q].tolerance != 1.0) continue;  // the angles, in degrees
        sum += std::abs(difference(results[r][s].values[q], results[ref][s].values[q], quantities[q].axial));
        ++n;
      }
      perSeed.push_back(sum / n);
    }
    return report::meanInterval(perSeed);
  };

  EnsembleStudy study;
  std::vector<std::string> header{"preset",  "axis",     "value",         "paired",       "quantity",
                                  "tolerance", "seeds",  "reference_mean", "bias",        "bias_ci_low",
                                  "bias_ci_high", "sd",  "verdict",       "cpu_s",        "runs_for_tolerance",
                                  "cpu_s_for_tolerance", "preparation_cpu_s", "lateral_stress_off", "timestep_safety", "inertial_number",
                                  "sample_strain", "engine", "vertices", "failed_runs", "note"};
  report::CsvTable table(header);
  for (size_t k = 0; k < settings.size(); ++k) {
    const Setting& s = settings[k];
    const size_t r = runOf[k];
    const size_t ref = referenceRun(r);
    const double cpuPerRun = cpu(r), off = lateral(r);
    int failed = 0;
    std::string note;
    for (const Result& x : results[r]) {
      if (x.summary.status == RunStatus::Completed) continue;
      ++failed;
      if (note.empty()) note = x.summary.error;
    }
    if (off > kLateralStressHeld) {
      note += std::string(note.empty() ? "" : "; ") + "sigma11 is " + text(100 * off) +
              "% off its target (median over shearing; reference: " + text(100 * lateral(ref)) +
              "%): the lateral servo does not follow this shearing, so the setting tests another boundary condition";
    }
    for (size_t q = 0; q < quantities.size(); ++q) {
      const bool reference = s.axis == "reference";
      const BiasEstimate e = reference ? BiasEstimate{} : estimate(r, q);
      const report::MeanInterval refValues = report::meanInterval(column(ref, q));
      // The reference's row gives its own seed-to-seed sd: the spread every other row is judged against.
      const double sd = reference ? refValues.halfWidth() * std::sqrt(refValues.n) / report::studentT975(refValues.n - 1) : e.sd;
      table.addRow({s.preset, s.axis, s.value, paired[r] ? 1 : 0, quantities[q].name, quantities[q].tolerance,
                    reference ? refValues.n : e.seeds, refValues.mean, e.bias, e.low, e.high, sd,
                    reference ? std::string("reference") : e.verdict, cpuPerRun, e.runsForTolerance,
                    e.runsForTolerance * cpuPerRun, prep(r), off, s.timestepSafety, s.inertialNumber, s.sampleStrain, s.engine,
                    s.vertices, failed, note});
      if (!reference) study.judgements.push_back({s, paired[r], quantities[q].name, quantities[q].tolerance, e, cpuPerRun, off});
    }
  }
  table.write((dir / "tradeoff.csv").string());

  // runs.csv: every run's values, for whoever wants to check a verdict.
  std::vector<std::string> runHeader{"preset", "axis", "value", "seed", "paired", "status", "cpu_s",
                                     "preparation_cpu_s", "wall_s",
                                     "lateral_stress_off"};
  for (const Quantity& q : quantities) runHeader.push_back(q.name);
  report::CsvTable runs(runHeader);
  for (size_t r = 0; r < runSetting.size(); ++r) {
    const Setting& s = settings[runSetting[r]];
    for (size_t seed = 0; seed < static_cast<size_t>(seeds); ++seed) {
      const Result& x = results[r][seed];
      std::vector<report::CsvCell> row{s.preset, s.axis, s.value, static_cast<int>(seed + 1), paired[r] ? 1 : 0,
                                       std::string(toString(x.summary.status)), x.cpuSeconds, x.preparationCpuSeconds,
                                       x.summary.wallSeconds,
                                       x.lateralStressOff};
      for (double v : x.values) row.emplace_back(v);
      runs.addRow(row);
    }
  }
  runs.write((dir / "runs.csv").string());

  for (const std::string& preset : plan.presets) {
    ParetoPanel panel{preset + " (" + std::to_string(seeds) + " seeds)", {}};
    for (size_t r = 0; r < runSetting.size(); ++r) {
      const Setting& s = settings[runSetting[r]];
      if (s.preset != preset) continue;
      const report::MeanInterval d = angleDeviation(r);
      const bool baseline = std::count(runOf.begin(), runOf.end(), r) > 1;
      const std::string axis = baseline ? "baseline" : s.axis;
      const std::string label = baseline || s.axis == "reference" || s.axis == "noise" ? axis : s.value;
      ParetoPoint p{cpu(r), d.mean, label + (paired[r] ? "" : " (own specimens)"), axis, false};
      if (s.axis != "reference") {
        p.errorLow = d.low;
        p.errorHigh = d.high;
      }
      panel.points.push_back(p);
      if (s.axis == "noise") panel.noiseFloor = d.mean;
    }
    std::vector<double> seconds, error;
    for (const ParetoPoint& p : panel.points) {
      seconds.push_back(p.seconds);
      error.push_back(p.error);
    }
    for (size_t i : paretoFront(seconds, error)) panel.points[i].onFront = true;
    study.panels.push_back(panel);
  }
  for (const auto& rs : results)
    for (const Result& x : rs) study.failedRuns += x.summary.status != RunStatus::Completed;
  return study;
}

}  // namespace grainlab::tradeoff

#include "grainlab/studies/tradeoff/ensemble_tradeoff.hpp"

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <mutex>
#include <thread>

#include "grainlab/observer_tee.hpp"
#include "grainlab/prepared_specimen.hpp"
#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/studies/paper/parallel_runs.hpp"
#include "grainlab/studies/paper/shearing_recorder.hpp"
#include "grainlab/studies/tradeoff/ensemble_judgement.hpp"
#include "grainlab/studies/tradeoff/ensemble_plan.hpp"
#include "grainlab/studies/tradeoff/shearing_clock.hpp"
#include "grainlab/thread_cpu_clock.hpp"

namespace grainlab::tradeoff {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Job {
  nlohmann::json scene;
  std::string name;
  std::string stageDirectory;  // where a preparing run keeps its stages' ends; empty: nowhere
};

double shearingPressure(const Scene& scene) {
  for (const StageSpec& s : scene.stages)
    if (s.type == StageSpec::Type::Biaxial) return s.pressure;
  return kNaN;
}

std::vector<EnsembleRunResult> runJobs(const std::vector<Job>& jobs, unsigned threadsAsked, std::ostream* progress) {
  std::vector<EnsembleRunResult> results(jobs.size());
  std::atomic<size_t> next{0}, done{0};
  std::mutex lock;
  auto worker = [&] {
    for (size_t k = next++; k < jobs.size(); k = next++) {
      EnsembleRunResult& r = results[k];
      report::AssemblyResult shearing;
      report::ShearingRecorder recorder(shearing);
      double pressure = kNaN;
      RunSummary summary;
      try {
        const Scene scene = parseScene(jobs[k].scene);
        pressure = shearingPressure(scene);
        ShearingClock clock(shearingStageName(scene));
        ObserverTee observers{&recorder, &clock};
        const double cpu0 = threadCpuSeconds();
        summary = runScene(scene, observers, {}, {}, jobs[k].stageDirectory);
        const double cpu1 = threadCpuSeconds();
        r.preparationCpuSeconds = clock.reached() - cpu0;
        r.cpuSeconds = cpu1 - clock.reached();
      } catch (const std::exception& e) {
        summary.status = RunStatus::Failed;
        summary.error = e.what();
      }
      r.status = summary.status;
      r.error = summary.error;
      r.wallSeconds = summary.wallSeconds;
      measureEnsembleRun(r, shearing.shearing, summary.peakPhiMobDeg, pressure);
      const std::lock_guard guard(lock);
      ++done;
      if (progress) {
        *progress << "tradeoff: [" << done << "/" << jobs.size() << "] " << jobs[k].name << ": " << r.status
                  << " in " << std::setprecision(3) << r.cpuSeconds << " cpu s"
                  << (r.error.empty() ? "" : " (" + r.error + ")") << "\n";
      }
    }
  };
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < report::concurrentRuns(threadsAsked, jobs.size()); ++t) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  return results;
}

}  // namespace

EnsembleStudy runEnsembleTradeoff(const TradeoffOptions& opt, std::ostream* progress) {
  const EnsemblePlan plan = planEnsemble(opt);
  const fs::path dir = opt.outDir;
  fs::create_directories(dir / "scenes");
  auto specimenDir = [&](const std::string& preset, int seed) {
    return (dir / "specimens" / preset / ("seed-" + std::to_string(seed))).string();
  };
  // results[r][seed - 1]
  std::vector<std::vector<EnsembleRunResult>> results(plan.runSetting.size(),
                                                      std::vector<EnsembleRunResult>(static_cast<size_t>(plan.seeds)));
  auto runPhase = [&](bool preparing) {
    std::vector<Job> jobs;
    const std::vector<EnsembleRun> runs = ensembleRuns(plan, preparing);
    for (const EnsembleRun& run : runs) {
      const std::string& preset = plan.settings[plan.runSetting[run.run]].preset;
      Job job{run.scene, run.name, {}};
      if (preparing) job.stageDirectory = specimenDir(preset, run.seed);
      if (run.paired)
        job.scene["start_from"] = {{"checkpoint", stageCheckpointPath(specimenDir(preset, run.seed), preparedStage(preset))}};
      std::ofstream(dir / "scenes" / run.file) << job.scene.dump(2) << "\n";
      jobs.push_back(std::move(job));
    }
    if (progress) *progress << "tradeoff: " << (preparing ? "preparing and shearing " : "testing ") << jobs.size() << " runs\n";
    std::vector<EnsembleRunResult> out = runJobs(jobs, opt.jobs, progress);
    for (size_t k = 0; k < out.size(); ++k) results[runs[k].run][static_cast<size_t>(runs[k].seed - 1)] = std::move(out[k]);
  };
  runPhase(true);
  runPhase(false);

  EnsembleTables tables = judgeEnsemble(plan, results);
  tables.tradeoff.write((dir / "tradeoff.csv").string());
  tables.runs.write((dir / "runs.csv").string());
  return tables.study;
}

}  // namespace grainlab::tradeoff

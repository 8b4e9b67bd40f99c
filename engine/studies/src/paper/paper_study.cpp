#include "grainlab/studies/paper/paper_study.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "grainlab/presets.hpp"
#include "grainlab/studies/paper/parallel_runs.hpp"
#include "grainlab/studies/paper/run_loader.hpp"
#include "grainlab/studies/paper/run_plan.hpp"
#include "grainlab/studies/cluster.hpp"

namespace grainlab::report {

namespace fs = std::filesystem;

std::vector<std::string> paperPresets(bool quick) {
  std::vector<std::string> names{"circular",           "elongated-random",     "elongated-bedding-0",
                                 "elongated-bedding-30", "elongated-bedding-60", "elongated-bedding-90"};
  if (quick) {
    for (std::string& n : names) n += "-quick";
  }
  return names;
}

PaperStudy runPaperStudy(const PaperOptions& options, std::ostream* progress) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::string> presets = paperPresets(options.quick);
  const fs::path runsDir = fs::path(options.outDir) / "runs";
  fs::create_directories(runsDir);
  const size_t planned = presets.size() * static_cast<size_t>(std::max(1, options.seeds));
  const bool ranks = options.cluster && options.cluster->size() > 1;
  const unsigned concurrent = options.reportOnly ? 0
                              : ranks            ? static_cast<unsigned>(options.cluster->size())
                                                 : concurrentRuns(options.jobs, planned);
  if (progress) {
    if (options.reportOnly) *progress << "[paper] rebuilding the report from " << runsDir.string() << "\n";
    else *progress << "[paper] " << presets.size() << " assemblies × " << options.seeds << " seed(s), " << concurrent
                   << " run(s) at a time" << (ranks ? " (MPI ranks)" : "") << ", into " << options.outDir << "\n";
  }
  // (1) the runs, (2) executed, each into its own directory.
  std::vector<std::pair<std::string, int>> toLoad;
  if (options.reportOnly) {
    for (const std::string& preset : presets) {
      const std::vector<int> seeds = seedsOnDisk(runsDir.string(), preset);
      for (int seed : seeds) toLoad.emplace_back(preset, seed);
      if (seeds.empty()) toLoad.emplace_back(preset, 0);  // 0: the single-run layout runs/<preset>/
    }
  } else {
    const std::vector<PlannedRun> plan = planRuns(presets, options.seeds, runsDir.string());
    executeRuns(plan, options.jobs, progress, options.cluster);
    if (options.cluster && !options.cluster->isRoot()) return {};  // rank 0 reads them back
    for (const PlannedRun& r : plan) toLoad.emplace_back(r.preset, r.seed);
  }
  // (3) what is on disk.
  PaperStudy study;
  for (const auto& [preset, seed] : toLoad) {
    const fs::path dir = seed > 0 ? runsDir / preset / ("seed-" + std::to_string(seed)) : runsDir / preset;
    try {
      study.runs.push_back(loadAssemblyResult(dir.string(), preset));
      study.runs.back().seed = std::max(seed, 1);
    } catch (const std::exception& e) {
      AssemblyResult failed;
      try {
        failed = describeAssembly(preset, parseScene(presetScene(preset)));
      } catch (const std::exception&) {
        failed.preset = preset;
      }
      failed.seed = std::max(seed, 1);
      failed.summary.status = RunStatus::Failed;
      failed.summary.error = e.what();
      study.runs.push_back(std::move(failed));
    }
  }
  study.concurrentRuns = concurrent;
  // Seeds per assembly as found (the --report-only case included).
  for (const std::string& preset : presets) {
    study.seeds = std::max<int>(study.seeds, static_cast<int>(std::count_if(
        study.runs.begin(), study.runs.end(), [&](const AssemblyResult& a) { return a.preset == preset; })));
  }
  study.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return study;
}

}  // namespace grainlab::report

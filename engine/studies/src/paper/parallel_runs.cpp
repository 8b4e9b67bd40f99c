#include "grainlab/studies/paper/parallel_runs.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <thread>

#include "grainlab/studies/paper/assembly_recorder.hpp"
#include "grainlab/studies/paper/run_loader.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/studies/cluster.hpp"
#include "grainlab/studies/run_batch.hpp"

namespace grainlab::report {

unsigned concurrentRuns(unsigned requested, size_t runs) {
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  unsigned n = requested == 0 ? hardware : std::min(requested, hardware);
  n = static_cast<unsigned>(std::min<size_t>(n, runs));
  return std::max(1u, n);
}

std::vector<RunSummary> executeRuns(const std::vector<PlannedRun>& plan, unsigned jobs, std::ostream* progress,
                                    const studies::Cluster* cluster) {
  std::vector<studies::BatchRun> batch;
  batch.reserve(plan.size());
  for (const PlannedRun& run : plan) batch.push_back({run.id, run.dir, run.scene});
  studies::BatchOptions options;
  options.jobs = concurrentRuns(jobs, plan.size());
  options.progress = progress;
  options.label = "paper";
  std::map<std::string, const PlannedRun*> byId;
  for (const PlannedRun& run : plan) byId[run.id] = &run;
  // The recorder's in-memory result only feeds roses.json; the report reads the disk.
  options.observer = [&byId](const studies::BatchRun& run,
                             const std::filesystem::path& workDir) -> std::unique_ptr<RunObserver> {
    const PlannedRun& planned = *byId.at(run.id);
    return std::make_unique<AssemblyRecorder>(describeAssembly(planned.preset, parseScene(planned.scene)),
                                              workDir.string());
  };
  const studies::Cluster alone(studies::Cluster::Join::Alone);
  const std::vector<studies::BatchRunResult> results = studies::runBatch(batch, options, cluster ? *cluster : alone);
  std::vector<RunSummary> summaries;
  for (size_t k = 0; k < results.size(); ++k) {
    try {
      summaries.push_back(readRunSummary(plan[k].dir));
    } catch (const std::exception& e) {  // not even a summary: the batch's own word on it
      RunSummary s;
      s.status = results[k].status;
      s.error = results[k].error.empty() ? e.what() : results[k].error;
      summaries.push_back(std::move(s));
    }
  }
  return summaries;
}

}  // namespace grainlab::report

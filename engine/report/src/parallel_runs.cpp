#include "grainlab/report/parallel_runs.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <filesystem>
#include <fstream>
#include <thread>

#include "grainlab/report/assembly_recorder.hpp"
#include "grainlab/report/progress_board.hpp"
#include "grainlab/scene.hpp"

namespace grainlab::report {

unsigned concurrentRuns(unsigned requested, size_t runs) {
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  unsigned n = requested == 0 ? hardware : std::min(requested, hardware);
  n = static_cast<unsigned>(std::min<size_t>(n, runs));
  return std::max(1u, n);
}

std::vector<RunSummary> executeRuns(const std::vector<PlannedRun>& plan, unsigned jobs, std::ostream* progress) {
  std::vector<RunSummary> summaries(plan.size());
  std::vector<std::string> names;
  for (const PlannedRun& r : plan) names.push_back(r.id);
  ProgressBoard board(progress, names);
  std::atomic<size_t> next{0};

  auto runOne = [&](size_t k) {
    const PlannedRun& run = plan[k];
    try {
      const Scene scene = parseScene(run.scene);
      std::filesystem::create_directories(run.dir);
      {
        std::ofstream out(std::filesystem::path(run.dir) / "scene.json", std::ios::binary | std::ios::trunc);
        out << run.scene.dump(2) << "\n";
        if (!out) throw std::runtime_error("cannot write " + run.dir + "/scene.json");
      }
      // The recorder's in-memory result only feeds roses.json; the report reads the disk.
      AssemblyResult scratch = describeAssembly(run.preset, scene);
      AssemblyRecorder recorder(scratch, run.dir, &board, k);
      summaries[k] = runScene(scene, recorder);
    } catch (const std::exception& e) {
      // Only set-up can throw here (a bad scene, an unwritable directory): runScene reports a
      // failing simulation in its summary instead.
      summaries[k].status = "failed";
      summaries[k].error = e.what();
      board.finished(k, "failed: " + std::string(e.what()), 0.0);
    }
  };
  auto worker = [&] {
    for (size_t k = next++; k < plan.size(); k = next++) runOne(k);
  };

  const unsigned n = concurrentRuns(jobs, plan.size());
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < n; ++t) threads.emplace_back(worker);
  worker();  // this thread works too
  for (std::thread& t : threads) t.join();
  return summaries;
}

}  // namespace grainlab::report

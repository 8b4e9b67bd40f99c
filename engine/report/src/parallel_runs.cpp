#include "grainlab/report/parallel_runs.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <filesystem>
#include <thread>

#include "grainlab/presets.hpp"
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

std::vector<AssemblyResult> runAssemblies(const std::vector<std::string>& presets, const std::string& runsDir,
                                          unsigned jobs, std::ostream* progress) {
  std::vector<AssemblyResult> results(presets.size());
  ProgressBoard board(progress, presets);
  std::atomic<size_t> next{0};

  auto runOne = [&](size_t k) {
    const std::string& preset = presets[k];
    try {
      const Scene scene = parseScene(presetScene(preset));
      results[k] = describeAssembly(preset, scene);
      AssemblyRecorder recorder(results[k], (std::filesystem::path(runsDir) / preset).string(), &board, k);
      runScene(scene, recorder);
    } catch (const std::exception& e) {
      // Only set-up can throw here (a bad preset, an unwritable directory): runScene reports
      // a failing simulation in its summary instead.
      results[k].preset = preset;
      results[k].summary.status = "failed";
      results[k].summary.error = e.what();
      board.finished(k, "failed: " + std::string(e.what()), 0.0);
    }
  };
  auto worker = [&] {
    for (size_t k = next++; k < presets.size(); k = next++) runOne(k);
  };

  const unsigned n = concurrentRuns(jobs, presets.size());
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < n; ++t) threads.emplace_back(worker);
  worker();  // this thread works too
  for (std::thread& t : threads) t.join();
  return results;
}

}  // namespace grainlab::report

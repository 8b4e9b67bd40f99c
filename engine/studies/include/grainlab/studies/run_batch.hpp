#pragma once
// A batch of runs, each scene into its own directory: run side by side on this machine, or
// spread over MPI ranks with rank 0 handing them out one at a time (a slow run holds up
// nothing else). A run works in a hidden ".<name>.partial" directory that is renamed into
// place when it ends, so a directory under its own name always holds a finished run; a run
// already completed there for the same scene is skipped, so running the same batch again
// resumes it (and a run whose scene changed is run again). A run killed half-way continues
// from the checkpoint its partial directory keeps (every output.checkpoint_every_s), with
// the outputs an uninterrupted run would have written. On one machine, once no run is left to
// start, the cores the finished runs leave idle are lent to the runs still going.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/run.hpp"

namespace grainlab::studies {

class Cluster;

struct BatchRun {
  std::string id;              ///< shown in progress lines
  std::filesystem::path dir;   ///< where its outputs end up (scene.json and what `grainlab run` writes)
  nlohmann::json scene;        ///< a valid scene (checked before the batch starts)
};

/// How a run ended, as its summary.json says.
struct BatchRunResult {
  RunStatus status = RunStatus::Failed;
  std::string error;
  double wallSeconds = 0;
  bool reused = false;         ///< completed by an earlier invocation, not run again
  bool resumed = false;        ///< continued from the checkpoint an interrupted attempt left
  /// The most threads it ran on beyond its scene's own: cores that finished runs left idle,
  /// lent to it (same results, sooner). Always 0 under MPI.
  int threadsLent = 0;
};

/// Builds the observer that writes one run's files into `workDir` (the partial directory).
/// The default writes exactly what `grainlab run` writes (RunOutput).
using ObserverFactory =
    std::function<std::unique_ptr<RunObserver>(const BatchRun& run, const std::filesystem::path& workDir)>;

struct BatchOptions {
  unsigned jobs = 0;                 ///< runs at once in this process; 0 = hardware threads, or 1 under MPI
  std::ostream* progress = nullptr;  ///< progress lines (written by rank 0 only); may be null
  std::string label = "batch";       ///< the progress lines' prefix, e.g. "sweep"
  ObserverFactory observer;          ///< empty = RunOutput, as `grainlab run`
};

/// Runs every run not yet completed in its directory. On rank 0 (or without MPI) returns one
/// result per run, in order; other ranks only work and return an empty vector. Never throws
/// for a failing run: its result (and its directory's summary.json) says why.
std::vector<BatchRunResult> runBatch(const std::vector<BatchRun>& runs, const BatchOptions& options,
                                     const Cluster& cluster);

/// What a run directory's summary.json records, or nothing if `dir` holds no finished run.
std::optional<BatchRunResult> finishedRun(const std::filesystem::path& dir);

/// The name of the file each run directory keeps its scene in.
inline constexpr const char* kSceneFile = "scene.json";

}  // namespace grainlab::studies

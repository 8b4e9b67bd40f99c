#pragma once
// Executes the planned runs of a paper ensemble through the studies' batch executor: side by
// side on this machine, or spread over MPI ranks, each run in its own World with its own
// observer, so what a run computes does not depend on how many run beside it or where. Each
// run's directory is written only by its AssemblyRecorder (scene.json first), through a
// partial folder renamed into place; a run already completed for the same scene is kept, so
// an interrupted `grainlab paper` resumes. The report reads the runs back from disk.
#include <ostream>
#include <vector>

#include "grainlab/studies/paper/run_plan.hpp"
#include "grainlab/run.hpp"

namespace grainlab::studies { class Cluster; }

namespace grainlab::report {

/// How many runs go at once: `requested` (0 = as many as there are hardware threads), never
/// more than std::thread::hardware_concurrency() (at least 1) nor than `runs`.
unsigned concurrentRuns(unsigned requested, size_t runs);

/// Runs every planned run not yet completed into its directory (scene.json, what `grainlab
/// run` writes, and roses.json), at most concurrentRuns(jobs, plan.size()) at a time, or one
/// per rank when `cluster` spans several MPI ranks (null: this process alone). Progress lines
/// go to `progress` (may be null). On rank 0 returns each run's summary (status, error, wall
/// time) in the order of `plan`; a run whose scene or directory is bad has status "failed"
/// and error saying why. Other ranks only work and get an empty vector.
std::vector<RunSummary> executeRuns(const std::vector<PlannedRun>& plan, unsigned jobs, std::ostream* progress,
                                    const studies::Cluster* cluster = nullptr);

}  // namespace grainlab::report

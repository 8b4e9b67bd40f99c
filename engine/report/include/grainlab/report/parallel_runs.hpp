#pragma once
// Executes a list of planned runs on std::threads, each in its own World with its own
// observer, so what a run computes does not depend on how many run beside it. Each run's
// directory is written only by its AssemblyRecorder (and scene.json before it starts); the
// report reads the runs back from disk. The sweep executor can stand in for this function.
#include <ostream>
#include <vector>

#include "grainlab/report/run_plan.hpp"
#include "grainlab/run.hpp"

namespace grainlab::report {

/// How many runs go at once: `requested` (0 = as many as there are hardware threads), never
/// more than std::thread::hardware_concurrency() (at least 1) nor than `runs`.
unsigned concurrentRuns(unsigned requested, size_t runs);

/// Runs every planned run into its directory (scene.json, what `grainlab run` writes, and
/// roses.json), at most concurrentRuns(jobs, plan.size()) at a time; progress lines go to
/// `progress` (may be null). Returns each run's summary in the order of `plan`: a run whose
/// scene or directory is bad has status "failed" and error saying why.
std::vector<RunSummary> executeRuns(const std::vector<PlannedRun>& plan, unsigned jobs, std::ostream* progress);

}  // namespace grainlab::report

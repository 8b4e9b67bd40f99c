#pragma once
// Runs several presets at once on std::threads, each in its own World with its own observer,
// so what a run computes does not depend on how many run beside it.
#include <ostream>
#include <string>
#include <vector>

#include "grainlab/report/assembly_result.hpp"

namespace grainlab::report {

/// How many runs go at once: `requested` (0 = as many as there are hardware threads), never
/// more than std::thread::hardware_concurrency() (at least 1) nor than `runs`.
unsigned concurrentRuns(unsigned requested, size_t runs);

/// Runs each preset (names as presetNames()) with its output in runsDir/<preset>/, at most
/// concurrentRuns(jobs, presets.size()) at a time. Progress lines go to `progress` (may be
/// null). Results come back in the order of `presets`; a run that fails, or whose preset or
/// output directory is bad, has summary.status "failed" and summary.error saying why.
std::vector<AssemblyResult> runAssemblies(const std::vector<std::string>& presets, const std::string& runsDir,
                                          unsigned jobs, std::ostream* progress);

}  // namespace grainlab::report

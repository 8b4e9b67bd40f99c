#pragma once
// sweep.csv: one row per run with its varied parameters, how it ended, and its scalar
// results, read back from the run's own summary.json and the last row of its series.csv.
#include <filesystem>
#include <string>
#include <vector>

#include "grainlab/studies/run_batch.hpp"
#include "grainlab/studies/sweep_spec.hpp"

namespace grainlab::studies {

/// The columns after the parameters: status, error, wall_seconds, then the results.
const std::vector<std::string>& sweepResultColumns();

/// The text of sweep.csv for `runs`, whose outputs are in runsDir/<id>/.
std::string sweepTable(const std::vector<SweepRun>& runs, const std::vector<BatchRunResult>& results,
                       const std::filesystem::path& runsDir);

}  // namespace grainlab::studies

#pragma once
// Inside runBatch: one run into its directory, and the MPI schedule that hands runs out.
#include <vector>

#include "core_lending.hpp"
#include "grainlab/studies/batch_progress.hpp"
#include "grainlab/studies/run_batch.hpp"

namespace grainlab::studies {

/// Runs one scene in its partial directory and renames that into place. Never throws. With
/// `lending`, the run takes the idle cores it is lent.
BatchRunResult executeRun(const BatchRun& run, const ObserverFactory& factory, BatchProgress& progress,
                          CoreLending* lending = nullptr);

#ifdef GRAINLAB_HAS_MPI
/// Rank 0 hands out `pending` (indices into runs) one at a time to whichever rank asks, and
/// runs them itself on a second thread; the others run what they are given until told to
/// stop. `results` (rank 0's) receives each run's result.
void runDistributed(const std::vector<BatchRun>& runs, const std::vector<size_t>& pending, const BatchOptions& options,
                    BatchProgress& progress, std::vector<BatchRunResult>& results, const Cluster& cluster);
#endif

}  // namespace grainlab::studies

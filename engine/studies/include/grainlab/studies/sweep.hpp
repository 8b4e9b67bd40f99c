#pragma once
// `grainlab sweep`: every run of a sweep spec into DIR (docs/sweeps.md):
//   DIR/sweep.json   the spec and the list of runs with their parameters
//   DIR/runs/<id>/   scene.json and exactly what `grainlab run` writes
//   DIR/sweep.csv    one row per run: its parameters, status, wall time, scalar results
// on this machine or across MPI ranks; running it again on DIR resumes it.
#include <filesystem>
#include <ostream>

#include "grainlab/studies/sweep_spec.hpp"

namespace grainlab::studies {

class Cluster;

struct SweepOptions {
  std::filesystem::path outDir;
  unsigned jobs = 0;                 ///< runs at once without MPI; 0 = hardware threads
  std::ostream* progress = nullptr;  ///< progress lines (rank 0); may be null
};

struct SweepOutcome {
  size_t runs = 0, completed = 0, failed = 0;  ///< on rank 0; other ranks see zeros
};

/// Expands and validates the whole sweep first: a bad spec, or DIR holding another sweep,
/// throws SceneError (naming the spec's field, or "--out") before anything is written. Then
/// runs what is not yet complete and writes sweep.csv.
SweepOutcome runSweep(const SweepSpec& spec, const SweepOptions& options, const Cluster& cluster);

}  // namespace grainlab::studies

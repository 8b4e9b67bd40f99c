#pragma once
// What the server keeps about a run: the row of the runs table and the stored sample rows.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grainlab/run_status.hpp"

namespace grainlab::server {

/// A run's state is grainlab::RunStatus (grainlab/run_status.hpp): the engine's, the API's and
/// the database's one vocabulary.
using grainlab::RunStatus;

/// The stored run, and its stage, whose end a run started from (start_from.run_id).
struct RunOrigin {
  std::int64_t runId = 0;
  std::string stage;
};

struct RunRecord {
  std::int64_t id = 0;
  std::string name;
  std::string preset;              ///< empty unless created from a preset
  std::string scene;               ///< the scene JSON as submitted (or the preset's)
  RunStatus status = RunStatus::Queued;
  std::string error;               ///< why it failed or was interrupted
  std::string stage;               ///< the stage it is in (or ended in)
  double progress = 0;             ///< 0..1
  int particles = 0;               ///< estimated when queued, exact once started
  std::int64_t steps = 0;
  double createdAt = 0;            ///< Unix seconds
  std::optional<double> startedAt, finishedAt;
  std::optional<double> wallSeconds;    ///< the simulation's own wall time
  std::optional<double> cpuSeconds;     ///< CPU time of the thread that ran it (see run_service)
  /// Of cpuSeconds, the part before the first sample of its shearing stage: preparing (or
  /// loading) its specimen. None for a run without shearing, or resumed from a checkpoint.
  std::optional<double> preparationCpuSeconds;
  /// The wall time it needs at least, estimated when queued (RunCost::certainSeconds: the
  /// free and shearing stages; compaction and consolidation end on criteria and add to it).
  std::optional<double> estimatedSeconds;
  std::optional<double> peakPhiMobDeg;
  std::string warnings = "[]";     ///< the validity envelope's, as summary.json's "warnings" (JSON)
  std::optional<RunOrigin> origin; ///< set when it started from a stored run's stage
  /// The program that produced it: "grainlab", or "lammps" for an imported LAMMPS run
  /// (`grainlab import lammps --db`). The API's `origin`.
  std::string producedBy = "grainlab";
  std::string study;               ///< the study it belongs to (the sweep it was imported from); empty if none
};

/// One row of the series as the engine produced it.
struct SampleRecord {
  std::int64_t seq = 0;            ///< 0, 1, 2... within the run
  std::int64_t step = 0;
  double time = 0;
  std::string stage;
  std::vector<double> values;      ///< as in grainlab::Sample::values
};

/// A stored replay frame without its bytes.
struct FrameInfo {
  std::int64_t seq = 0;            ///< 0, 1, 2... within the run
  std::int64_t step = 0;
  double time = 0;
  std::int64_t bytes = 0;
};

}  // namespace grainlab::server

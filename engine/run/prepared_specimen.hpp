#pragma once
// Saving a run's state at a stage's end and starting another run from it
// (grainlab/prepared_specimen.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/scene.hpp"

namespace grainlab {

class RunContext;

/// What the run loop carries over from the stages the specimen went through.
struct PreparedHistory {
  std::vector<std::string> notes;  ///< the preparation's summary notes
  bool timestepNoted = false;
};

/// Writes the state of `context`, whose stage `stageIndex` has just ended, to `path`
/// (atomically and durably); returns the file's payload size in bytes. Throws
/// std::runtime_error if it cannot be written.
std::uint64_t writeStageCheckpoint(const std::string& path, const Scene& scene, RunContext& context,
                                   std::size_t stageIndex, const PreparedHistory& history);

/// Loads the specimen `scene.startFrom` names into `context` (just built from `scene`) and
/// returns the index of the first stage to run. Throws SceneError naming start_from's field:
/// no such checkpoint, unreadable, another format version, or a specimen the scene does not
/// fit (engine, particles, material, stages).
std::size_t loadPreparedSpecimen(const Scene& scene, RunContext& context, PreparedHistory& history);

}  // namespace grainlab

#pragma once
// Prepared specimens: a run keeps its state at the end of each stage (output.stage_checkpoints),
// and another run can start from one (the scene's "start_from", `grainlab run --from DIR[:STAGE]`)
// instead of preparing its own specimen: prepare once, test many times.
//
// A stage checkpoint is a checkpoint file (grainlab/checkpoint.hpp) whose payload holds the
// particles, the contacts with their tangential history, the ring and its servo state, the
// sampler's references and the clock, as they stand when the stage has ended, with what the
// specimen was made with (engine, particle count and shapes, material), so a scene it does not
// fit is refused. A run started from it skips the scene's stages up to and including that stage
// (the scene must have a stage of the same name and type at the same place) and runs the rest:
// it writes exactly the rows the original run wrote after that stage when its later stages are
// the same.
#include <cstdint>
#include <string>

#include "grainlab/scene.hpp"

namespace grainlab {

/// The folder of a run's directory where its stage checkpoints are kept.
inline constexpr const char* kStageCheckpointFolder = "stages";

/// DIR/stages/NAME.checkpoint: where a run in `runDirectory` keeps the end of its stage `stage`
/// (characters other than letters, digits, '-', '_' and '.' in the name become '_').
std::string stageCheckpointPath(const std::string& runDirectory, const std::string& stage);

/// The checkpoint file a scene's start_from names: start_from.checkpoint, or the run's stage
/// checkpoint (start_from.stage, or if it is empty the stage before the scene's first shearing
/// stage). Throws SceneError naming start_from's field if there is none.
std::string startFromPath(const Scene& scene);

/// Whether a run of `scene` keeps stage checkpoints where its caller gives them a folder:
/// output.stage_checkpoints, by default on for dem and off for box2d.
bool keepsStageCheckpoints(const Scene& scene);

}  // namespace grainlab

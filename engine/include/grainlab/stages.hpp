#pragma once
// The stages a scene can list (contracts.md): free, compaction, isotropic, biaxial, and the
// loading paths rotation, cyclic and simple_shear (docs/loading-paths.md).
#include <memory>

#include "grainlab/scene.hpp"
#include "grainlab/stage.hpp"

namespace grainlab {

class World;
class Membrane;

/// `membrane` may be null only for free stages (the scene parser guarantees it).
std::unique_ptr<Stage> makeStage(const StageSpec& spec, const OutputSpec& output, World& world,
                                 Membrane* membrane);

/// The same stage types in the world's periodic cell (free, isotropic, biaxial, simple_shear,
/// and rotation stress-controlled; the scene parser refuses the others there): servos command
/// strain rates up to `rateCap`, 1/s (an isotropic stage: its own strain_rate, as in the ring)
/// (engine/src/cell_scene_stages.cpp, cell_rotation_stage.cpp).
std::unique_ptr<Stage> makeCellStage(const StageSpec& spec, const OutputSpec& output, World& world, double rateCap);

}  // namespace grainlab

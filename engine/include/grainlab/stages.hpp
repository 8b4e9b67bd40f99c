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

}  // namespace grainlab

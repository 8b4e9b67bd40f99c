#pragma once
// `grainlab scene-keys [--json | --markdown]`: every key the scene parser accepts, with its
// kind, default, range, choices and the stage types that read it (grainlab/scene_keys.hpp).
#include <string>
#include <vector>

namespace grainlab {

int sceneKeysCommand(const std::vector<std::string>& args);

}  // namespace grainlab

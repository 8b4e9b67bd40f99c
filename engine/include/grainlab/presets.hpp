#pragma once
// Named scenes: the paper's six assemblies and a quick variant of each.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace grainlab {

/// In a stable order: circular, elongated-random, elongated-bedding-{0,30,60,90}, then the
/// -quick variants, then the demos.
std::vector<std::string> presetNames();
/// The preset as scene JSON; throws SceneError("preset", ...) for an unknown name.
nlohmann::json presetScene(const std::string& name);

}  // namespace grainlab

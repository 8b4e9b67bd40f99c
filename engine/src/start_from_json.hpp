#pragma once
// The scene's "start_from" object (grainlab/prepared_specimen.hpp): its shape only. Whether
// the specimen it names exists and fits the scene is checked when the run starts.
#include <optional>

#include <nlohmann/json.hpp>

#include "grainlab/scene.hpp"

namespace grainlab {

/// Nothing for null; throws SceneError naming start_from's field otherwise.
std::optional<StartFrom> parseStartFrom(const nlohmann::json& json);

}  // namespace grainlab

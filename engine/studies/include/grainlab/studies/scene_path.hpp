#pragma once
// A dotted path into a scene's JSON, as sweeps name what they vary: "material.friction",
// "seed", "stages.2.strain_rate" (an array is indexed by a number).
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace grainlab::studies {

/// Sets `value` at `path` in `scene`. A key missing from an object is created (whether the
/// scene accepts it is the scene parser's word); an array index must exist. Throws
/// std::invalid_argument with the reason for an empty segment, an index that is not a
/// number or out of range, or a path that goes through a number, string or boolean.
void setAtPath(nlohmann::json& scene, std::string_view path, const nlohmann::json& value);

/// The name the scene parser gives the same field: "stages.2.strain_rate" -> "stages[2].strain_rate".
std::string sceneFieldName(std::string_view path);

}  // namespace grainlab::studies

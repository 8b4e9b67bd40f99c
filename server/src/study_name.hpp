#pragma once
// A study's name: its URL (/api/studies/NAME) and the prefix of its runs' names. One rule for
// every kind of study the server launches (sweeps, paper studies, trade-off studies).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace grainlab::server {

/// The spec's "name", checked (1 to 64 letters, digits, '.', '-' or '_', starting with a letter
/// or digit), or `fallback` when the spec has none; without a fallback the name is required.
/// Throws ApiError(400) on field "name".
std::string studyName(const nlohmann::ordered_json& spec, const std::optional<std::string>& fallback = std::nullopt);

}  // namespace grainlab::server

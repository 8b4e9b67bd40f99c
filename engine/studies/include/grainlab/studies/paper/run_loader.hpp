#pragma once
// Reading a finished run back from its output directory (series.csv, summary.json and the
// report's roses.json), so a report can be rebuilt without running the assemblies again.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/studies/paper/assembly_result.hpp"
#include "grainlab/scene.hpp"

namespace grainlab::report {

/// {"roses": [{"target_strain", "axial_strain", "histograms": PolarHistograms JSON or null}]}.
nlohmann::json rosesToJson(const std::vector<RoseSnapshot>& roses);
/// Fills the snapshots whose target strain matches one in `json` (the others stay empty).
/// Throws nlohmann::json::exception for malformed JSON.
void rosesFromJson(const nlohmann::json& json, std::vector<RoseSnapshot>& roses);

/// The run of `preset` whose output is in `runDir`: its summary, its shearing series and, if
/// roses.json is there, its rose snapshots. Throws std::runtime_error naming the file when
/// series.csv or summary.json is missing or unreadable.
/// A run directory's summary.json; throws std::runtime_error if it cannot be read.
RunSummary readRunSummary(const std::string& runDir);

AssemblyResult loadAssemblyResult(const std::string& runDir, const std::string& preset);

}  // namespace grainlab::report

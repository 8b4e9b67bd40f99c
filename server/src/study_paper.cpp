// POST /api/studies with {"paper": {"seeds": N, "quick": bool}}: the paper's six assemblies,
// N seeds each, as `grainlab paper` runs them: the same presets, the same seeds 1..N, the
// same scenes (grainlab::report::planRuns, the CLI's own list), queued as one study.
#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/studies/paper/paper_study.hpp"
#include "grainlab/studies/paper/run_plan.hpp"
#include "api_types.hpp"
#include "run_service.hpp"
#include "study_name.hpp"

namespace grainlab::server {

std::string RunService::launchPaperStudy(const nlohmann::ordered_json& spec) {
  for (const auto& [key, value] : spec.items())
    if (key != "paper" && key != "name")
      throw ApiError(400, "unknown key (a paper study takes name and paper: {seeds, quick})", key);
  const nlohmann::ordered_json& paper = spec["paper"];
  if (!paper.is_object()) throw ApiError(400, "must be an object: {\"seeds\": N, \"quick\": true|false}", "paper");
  for (const auto& [key, value] : paper.items())
    if (key != "seeds" && key != "quick") throw ApiError(400, "unknown key (the paper takes seeds and quick)", "paper." + key);
  int seeds = 1;
  if (paper.contains("seeds")) {
    const auto& n = paper["seeds"];
    if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > 100000)
      throw ApiError(400, "must be a whole number of seeds, at least 1 (got " + n.dump() + ")", "paper.seeds");
    seeds = n.get<int>();
  }
  bool quick = false;
  if (paper.contains("quick")) {
    if (!paper["quick"].is_boolean()) throw ApiError(400, "must be true or false", "paper.quick");
    quick = paper["quick"].get<bool>();
  }
  const std::string name = studyName(spec, std::string("paper") + (quick ? "-quick" : "") + "-" + std::to_string(seeds) + "-seeds");
  const std::vector<std::string> presets = report::paperPresets(quick);
  const std::size_t count = presets.size() * static_cast<std::size_t>(seeds);
  const std::size_t ceiling = static_cast<std::size_t>(manager_.maxConcurrent() + std::max(0, options_.maxQueuedRuns));
  if (count > ceiling)
    throw ApiError(400,
                   "the paper with " + std::to_string(seeds) + " seeds is " + std::to_string(count) +
                       " runs; this server holds at most " + std::to_string(ceiling) + " at once (" +
                       std::to_string(manager_.maxConcurrent()) + " running, " +
                       std::to_string(options_.maxQueuedRuns) + " queued: grainlab serve --max-concurrent, --max-queued)",
                   "paper.seeds");

  std::vector<StudyRun> runs;
  for (report::PlannedRun& planned : report::planRuns(presets, seeds, "runs")) {
    const std::string description = planned.preset + ", seed " + std::to_string(planned.seed);
    runs.push_back({std::move(planned.scene), planned.id, planned.preset,
                    {{"preset", planned.preset}, {"seed", planned.seed}}, description});
  }
  // The spec kept as posted, with what was taken by default written out.
  nlohmann::ordered_json stored{{"name", name}, {"paper", {{"seeds", seeds}, {"quick", quick}}}};
  return storeStudy(name, stored, std::move(runs), "paper.seeds", [](const std::string& field, std::size_t k) {
    return "runs[" + std::to_string(k) + "]" + (field.empty() ? "" : "." + field);
  });
}

}  // namespace grainlab::server

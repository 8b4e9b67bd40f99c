#pragma once
// The runs of a paper ensemble, listed before anything runs: each (preset, seed) becomes a run
// id, its output directory DIR/runs/<preset>/seed-<seed>/ and the scene it runs (the preset
// with its "seed" set). Executing the list is parallel_runs' job; reading it back, run_loader's.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace grainlab::report {

struct PlannedRun {
  std::string id;        ///< "<preset>/seed-<seed>", unique in the plan
  std::string preset;    ///< e.g. "elongated-bedding-30-quick"
  int seed = 1;          ///< the scene's "seed": 1..N for an ensemble of N
  std::string dir;       ///< runsDir/<preset>/seed-<seed>
  nlohmann::json scene;  ///< the preset's scene JSON with "seed" = seed
};

/// Every preset with seeds 1..seeds, preset by preset. Throws std::invalid_argument for
/// seeds < 1, and what presetScene throws for an unknown preset.
std::vector<PlannedRun> planRuns(const std::vector<std::string>& presets, int seeds, const std::string& runsDir);

/// The seeds found on disk for `preset` under runsDir (its seed-<s> folders), ascending.
std::vector<int> seedsOnDisk(const std::string& runsDir, const std::string& preset);

}  // namespace grainlab::report

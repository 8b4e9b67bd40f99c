#include "grainlab/studies/paper/run_plan.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "grainlab/presets.hpp"

namespace grainlab::report {

namespace fs = std::filesystem;

std::vector<PlannedRun> planRuns(const std::vector<std::string>& presets, int seeds, const std::string& runsDir) {
  if (seeds < 1) throw std::invalid_argument("seeds: at least 1, not " + std::to_string(seeds));
  std::vector<PlannedRun> plan;
  for (const std::string& preset : presets) {
    const nlohmann::json base = presetScene(preset);
    for (int s = 1; s <= seeds; ++s) {
      PlannedRun run;
      run.preset = preset;
      run.seed = s;
      run.id = preset + "/seed-" + std::to_string(s);
      run.dir = (fs::path(runsDir) / preset / ("seed-" + std::to_string(s))).string();
      run.scene = base;
      run.scene["seed"] = s;
      plan.push_back(std::move(run));
    }
  }
  return plan;
}

std::vector<int> seedsOnDisk(const std::string& runsDir, const std::string& preset) {
  std::vector<int> seeds;
  const fs::path dir = fs::path(runsDir) / preset;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return seeds;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (!e.is_directory() || !name.starts_with("seed-") || name.size() == 5) continue;
    const std::string digits = name.substr(5);
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    seeds.push_back(std::stoi(digits));
  }
  std::sort(seeds.begin(), seeds.end());
  return seeds;
}

}  // namespace grainlab::report

#include "check_command.hpp"

#include <iostream>

#include "grainlab/presets.hpp"
#include "grainlab/run_cost.hpp"
#include "grainlab/scene.hpp"

namespace grainlab {

int checkCommand(const std::vector<std::string>& args) {
  const bool preset = args.size() == 2 && args[0] == "--preset";
  if (!preset && (args.size() != 1 || args[0].empty() || args[0][0] == '-')) {
    std::cerr << "grainlab check: give a SCENE.json or --preset NAME\n";
    return 2;
  }
  const nlohmann::json json = preset ? presetScene(args[1]) : loadSceneJson(args[0]);
  const Scene scene = parseScene(json);  // a SceneError names the field (main prints it)
  const RunCost cost = estimateSceneCost(scene);
  std::cout << "ok: " << scene.stages.size() << " stages; " << cost.describe() << "\n";
  return 0;
}

}  // namespace grainlab

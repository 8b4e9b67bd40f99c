#include "check_command.hpp"

#include <iostream>

#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/validity.hpp"

namespace grainlab {

int checkCommand(const std::vector<std::string>& args) {
  const bool preset = args.size() == 2 && args[0] == "--preset";
  if (!preset && (args.size() != 1 || args[0].empty() || args[0][0] == '-')) {
    std::cerr << "grainlab check: give a SCENE.json or --preset NAME\n";
    return 2;
  }
  const nlohmann::json json = preset ? presetScene(args[1]) : loadSceneJson(args[0]);
  const Scene scene = parseScene(json);  // a SceneError names the field (main prints it)
  // The cost's hard limit is grainlab run's (without --force). A start_from is read as
  // grainlab run reads it: a specimen that is missing or does not fit is a SceneError by
  // field, and only the stages run on it are counted.
  const ValidityAssessment validity = assessSceneValidity(scene, 30 * 86400.0);
  if (!validity.refusals.empty()) {
    std::cerr << "error: " << validity.refusalMessage() << "\n";
    return 2;
  }
  for (const ValidityWarning& w : validity.warnings) std::cout << describe(w) << "\n";
  const std::size_t first = validity.cost.firstStage;
  std::cout << "ok: " << scene.stages.size() << " stages";
  if (first > 0)
    std::cout << ", " << scene.stages.size() - first << " of them run on the prepared specimen (the end of stage '"
              << scene.stages[first - 1].name << "')";
  std::cout << "; " << validity.cost.describe() << "\n";
  return 0;
}

}  // namespace grainlab

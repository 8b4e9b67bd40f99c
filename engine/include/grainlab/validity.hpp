#pragma once
// The validity envelope: the quantities that decide whether a run's results mean anything,
// worked out from the scene (and the world built from it) before the first step, each with
// two limits. Past a hard limit the result is meaningless and the scene is refused, naming
// the field that drives it; past a soft limit the run goes on, carrying a warning. The same
// limits are checked on the measured quantities while the run goes (ValidityMonitor).
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/run_cost.hpp"
#include "grainlab/scene.hpp"

namespace grainlab {

class World;

/// A quantity past its soft limit (or, in a refusal, its hard limit).
struct ValidityWarning {
  std::string field;     ///< the scene field that drives it, e.g. "stages[2].strain_rate"
  std::string quantity;  ///< one of validityQuantities()' names, e.g. "inertial_number"
  double value = 0;
  double limit = 0;
  std::string meaning;   ///< what it means for the results, in words
  std::int64_t step = -1;  ///< the step of the first crossing during the run; -1: before the first step
};

/// One quantity of the envelope and its two limits.
struct ValidityQuantity {
  std::string name;
  std::string unit;
  bool upper = true;   ///< the limits bound it from above (false: from below)
  double soft = 0, hard = 0;
  std::string definition;
  std::string softReason, hardReason;
};

/// The envelope's table (docs/validity.md is its prose).
const std::vector<ValidityQuantity>& validityQuantities();
const ValidityQuantity& validityQuantity(const std::string& name);

/// The envelope of one scene, before its first step.
struct ValidityAssessment {
  RunCost cost;
  std::vector<ValidityWarning> warnings;  ///< past soft limits
  std::vector<ValidityWarning> refusals;  ///< past hard limits: the scene must not run
  /// The refusals, "; "-separated: "field: quantity value > limit: meaning (why)".
  std::string refusalMessage() const;
};

/// The quantities the scene alone decides (particles across the specimen, the ring's disc
/// size, the spread of explicit particle sizes), before the world is built.
ValidityAssessment assessSceneAlone(const Scene& scene);
/// The envelope of `scene` on `world` (built from it, not yet stepped), with its cost.
/// `maxSeconds`: the cost's hard limit (RunLimits::maxSeconds; infinite: none).
ValidityAssessment assessValidity(const Scene& scene, const World& world, const RunCost& cost, double maxSeconds);
/// The same, building the world first (as estimateSceneCost). A scene with start_from is
/// assessed as runScene would run it: on its prepared specimen, counting only the stages after
/// it; a specimen that is missing or does not fit throws SceneError naming start_from's field.
ValidityAssessment assessSceneValidity(const Scene& scene, double maxSeconds);

/// The scene field most likely responsible for a run that failed for physical reasons (a
/// runaway overlap, a non-finite state): the envelope quantity furthest past, or nearest to,
/// its soft limit, with the figures. Empty if every quantity is well inside.
std::string likelyCause(const Scene& scene, const World& world);

/// "warnings": [{"field", "quantity", "value", "limit", "meaning"[, "step"]}].
nlohmann::json warningsJson(const std::vector<ValidityWarning>& warnings);
std::vector<ValidityWarning> warningsFromJson(const nlohmann::json& warnings);
/// One line for people: "warning: stages[2].strain_rate: inertial_number 0.38 > 0.001: ...".
std::string describe(const ValidityWarning& warning);

}  // namespace grainlab

#include "grainlab/run_cost.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "grainlab/world.hpp"
#include "run_context.hpp"

namespace grainlab {
namespace {

// One thread's particle-steps per second by kind of scene, rounded down from the benchmarks
// and the presets' runs (docs/benchmarks.md, docs/polygon-contacts.md, 2026-11-25): discs
// 30-50 M, polygons 7-17 M, Box2D's rigid bodies about 1 M. An estimate's order of magnitude
// is what matters here; the progress line's time left is measured as the run goes.
constexpr double kDiscSpeed = 20e6;
constexpr double kPolygonSpeed = 6e6;
constexpr double kRigidSpeed = 0.7e6;
// A timestep below this is itself the problem (the presets step at about 1e-6 s).
constexpr double kTinyTimestep = 1e-9;

std::string stagePath(size_t k, const char* field) { return "stages." + std::to_string(k) + "." + field; }

}  // namespace

RunCost estimateRunCost(const Scene& scene, const World& world, std::size_t firstStage) {
  RunCost cost;
  cost.timestep = world.timestep();
  cost.firstStage = firstStage;
  cost.particles = world.size();
  cost.particleStepsPerSecond = scene.solver.engine == SolverSpec::Engine::Box2d ? kRigidSpeed
                                : world.hasPolygons()                           ? kPolygonSpeed
                                                                                : kDiscSpeed;
  double longest = -1;
  std::string longestField;
  for (size_t k = firstStage; k < scene.stages.size(); ++k) {
    const StageSpec& s = scene.stages[k];
    double time = 0;
    std::string field;
    switch (s.type) {
      case StageSpec::Type::Free:
        time = s.duration;
        field = stagePath(k, "duration");
        cost.certainTime += time;
        break;
      case StageSpec::Type::Biaxial:
        time = std::min(s.maxTime, s.strainRate > 0 ? s.targetAxialStrain / s.strainRate : s.maxTime);
        field = stagePath(k, time == s.maxTime ? "max_time" : "strain_rate");
        cost.certainTime += time;
        break;
      case StageSpec::Type::Rotation:
        time = std::min(s.maxTime, s.duration);
        field = stagePath(k, time == s.maxTime ? "max_time" : "duration");
        cost.certainTime += time;
        break;
      case StageSpec::Type::SimpleShear:
        time = std::min(s.maxTime, s.targetShearStrain / s.shearRate);
        field = stagePath(k, time == s.maxTime ? "max_time" : "shear_rate");
        cost.certainTime += time;
        break;
      case StageSpec::Type::Cyclic:  // ends at a limit: known in strain, bounded in stress ratio
        if (s.strainAmplitude) {
          time = std::min(s.maxTime, 4 * *s.strainAmplitude * s.cycles / s.strainRate);
          field = stagePath(k, time == s.maxTime ? "max_time" : "cycles");
          cost.certainTime += time;
        } else {
          time = s.maxTime;
          field = stagePath(k, "max_time");
          cost.boundedTime += time;
        }
        break;
      case StageSpec::Type::Compaction:
      case StageSpec::Type::Isotropic:
        time = s.maxTime;
        field = stagePath(k, "max_time");
        cost.boundedTime += time;
        break;
    }
    // The certain stages are what a refusal rests on, so the field is one of theirs.
    const bool certain = s.type == StageSpec::Type::Free || s.type == StageSpec::Type::Biaxial ||
                         s.type == StageSpec::Type::Rotation || s.type == StageSpec::Type::SimpleShear ||
                         (s.type == StageSpec::Type::Cyclic && s.strainAmplitude);
    if (certain && time > longest) {
      longest = time;
      longestField = field;
    }
  }
  // Which field to change: the timestep's source if the timestep is absurdly small, else the
  // stage that asks for the most simulated time.
  if (cost.timestep < kTinyTimestep) {
    if (scene.solver.timestep > 0) cost.field = "solver.timestep";
    else if (scene.solver.timestepSafety < 1e-3) cost.field = "solver.timestep_safety";
    // A density under a thousandth of quartz's (2,650 kg/m³) is the likelier typo.
    else if (scene.material.density < 1e-3 * 2650) cost.field = "material.density";
    else cost.field = "material.normal_stiffness";
  } else {
    cost.field = longestField;
  }
  return cost;
}

RunCost estimateSceneCost(const Scene& scene) {
  RunContext context(scene);
  return estimateRunCost(scene, context.world());
}

std::string humanDuration(double seconds) {
  std::ostringstream os;
  os.precision(2);
  if (!std::isfinite(seconds)) os << "forever";
  else if (seconds < 120) os << std::fixed << std::setprecision(0) << std::max(seconds, 1.0) << " s";
  else if (seconds < 7200) os << std::fixed << std::setprecision(0) << seconds / 60 << " min";
  else if (seconds < 3 * 86400) os << std::fixed << std::setprecision(1) << seconds / 3600 << " h";
  else if (seconds < 3 * 365.25 * 86400) os << std::fixed << std::setprecision(0) << seconds / 86400 << " days";
  else os << seconds / (365.25 * 86400) << " years";
  return os.str();
}

std::string RunCost::describe() const {
  std::ostringstream os;
  os.precision(3);
  // A lower bound, and said to be one: the stages that end on a criterion (compaction,
  // consolidation) count for nothing here, and they made up 43-57 % of the steps of the
  // presets measured (docs/biaxial-test.md, "Wall time": elongated-bedding-30 3.34e5 counted,
  // 597,370 run; circular-quick 8.22e4 counted, 181,351 run). The wall times assume one idle
  // core; a loaded machine is slower.
  os << "timestep " << timestep << " s, " << particles << " particles: lower bound " << certainSteps()
     << " steps, about " << humanDuration(certainSeconds()) << " at " << particleStepsPerSecond / 1e6
     << " M particle-steps/s on one idle core";
  if (boundedTime > 0)
    os << "; stages that end on a criterion add more: at most " << (certainTime + boundedTime) / timestep
       << " steps (about " << humanDuration(mostSeconds()) << ") if every stage runs to its time limit";
  return os.str();
}

}  // namespace grainlab

#include "grainlab/run_cost.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "grainlab/world.hpp"
#include "run_context.hpp"

namespace grainlab {
namespace {

// One thread's particle-steps per second by kind of scene, the fastest and the slowest a run
// of that kind may step, so that the seconds below are bounds and not guesses. Measured on
// every preset (docs/run-times.md, commit f2feb20, a 2-core Xeon): discs 35-66 M, polygons
// 9.1-19.8 M; Box2D's rigid bodies about 1 M (docs/speed-accuracy.md). The fastest is the
// measured maximum with 50 % to spare (a faster machine or a faster step), the slowest the
// minimum less 20 %: a lower bound on a run's time must not be beaten, and the "at most" must
// not be exceeded, on the machines this runs on.
constexpr double kDiscFastest = 100e6, kDiscSlowest = 28e6;
constexpr double kPolygonFastest = 30e6, kPolygonSlowest = 7e6;
constexpr double kRigidFastest = 2e6, kRigidSlowest = 0.5e6;
// A timestep below this is itself the problem (the presets step at about 1e-6 s).
constexpr double kTinyTimestep = 1e-9;

std::string stagePath(size_t k, const char* field) { return "stages." + std::to_string(k) + "." + field; }

}  // namespace

RunCost estimateRunCost(const Scene& scene, const World& world, std::size_t firstStage) {
  RunCost cost;
  cost.timestep = world.timestep();
  cost.firstStage = firstStage;
  cost.particles = world.size();
  const bool rigid = scene.solver.engine == SolverSpec::Engine::Box2d, polygons = world.hasPolygons();
  cost.fastestParticleStepsPerSecond = rigid ? kRigidFastest : polygons ? kPolygonFastest : kDiscFastest;
  cost.slowestParticleStepsPerSecond = rigid ? kRigidSlowest : polygons ? kPolygonSlowest : kDiscSlowest;
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
  // Bounds, and said to be: the steps counted are those of the stages whose length is known
  // (the criterion stages, compaction and consolidation, made up 43-57 % of the presets'
  // steps, docs/run-times.md), and the seconds take the fastest rate a run of this kind steps
  // at. The "at most" counts every stage to its time limit at the slowest rate.
  os << "timestep " << timestep << " s, " << particles << " particles: lower bound " << certainSteps()
     << " steps, at least " << humanDuration(certainSeconds()) << " on one idle core (at up to "
     << fastestParticleStepsPerSecond / 1e6 << " M particle-steps/s)";
  if (boundedTime > 0)
    os << "; stages that end on a criterion add more: at most " << (certainTime + boundedTime) / timestep
       << " steps (at most " << humanDuration(mostSeconds()) << " at " << slowestParticleStepsPerSecond / 1e6
       << " M particle-steps/s or faster) if every stage runs to its time limit";
  return os.str();
}

}  // namespace grainlab

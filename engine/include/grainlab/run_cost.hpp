#pragma once
// What a run will cost, estimated before its first step, so that a scene whose cost is absurd
// (a stiffness of 1e30 N/m makes the timestep 1e-17 s) is refused with the field that drives
// it, instead of sitting at 0 % for ever.
#include <cstddef>
#include <limits>
#include <string>

#include "grainlab/scene.hpp"

namespace grainlab {

class World;

struct RunCost {
  /// s of simulated time: free stages' durations and biaxial stages' target strain over their
  /// rate (capped at their time limit). A run takes at least this long.
  double certainTime = 0;
  /// s of simulated time of the stages that end on a criterion (compaction, consolidation),
  /// counted to their time limit: the run takes at most certainTime plus this.
  double boundedTime = 0;
  double timestep = 0;                ///< s
  int particles = 0;
  /// One thread's particle-steps per second for this kind of scene (discs, polygons, Box2D):
  /// the fastest and the slowest measured, with a margin (run_cost.cpp), so that the seconds
  /// below bound the run's CPU time from both sides.
  double fastestParticleStepsPerSecond = 0, slowestParticleStepsPerSecond = 0;
  /// The first of the scene's stages counted: a run started from a prepared specimen runs only
  /// the stages after the one the specimen ended.
  std::size_t firstStage = 0;
  /// The scene field that drives the cost ("material.normal_stiffness", "stages.2.strain_rate"...).
  std::string field;
  double certainSteps() const { return certainTime / timestep; }
  /// The least a run can take on one idle core: the certain steps at the fastest rate.
  double certainSeconds() const { return certainSteps() * particles / fastestParticleStepsPerSecond; }
  /// The most: every stage to its time limit, at the slowest rate.
  double mostSeconds() const {
    return (certainTime + boundedTime) / timestep * particles / slowestParticleStepsPerSecond;
  }
  /// One line for people: the steps, the timestep and the bounds on the time.
  std::string describe() const;
};

/// The cost of running `scene` on `world` (built from it, not yet stepped), from its stage
/// `firstStage` on (a run started from a prepared specimen runs only the stages after it).
RunCost estimateRunCost(const Scene& scene, const World& world, std::size_t firstStage = 0);
/// The same, building the world first (the specimen is generated and its first forces
/// computed: milliseconds for a few thousand particles). Throws as runScene's set-up fails.
RunCost estimateSceneCost(const Scene& scene);

/// A wall time in words: "40 s", "3.2 h", "3e+08 years".
std::string humanDuration(double seconds);

/// How long a run may be expected to take before it is refused (runScene's `limits`).
struct RunLimits {
  double maxSeconds = std::numeric_limits<double>::infinity();
};

}  // namespace grainlab

#pragma once
// Where a step's time goes, accumulated over the run (seconds).
namespace grainlab {

struct Profile {
  double neighbors = 0;  ///< neighbour-list rebuilds
  double forces = 0;     ///< contact detection and contact law
  double integrate = 0;  ///< kick and drift, and the check whether the neighbour list must be rebuilt
  long long rebuilds = 0;
  long long box2dCalls = 0;  ///< polygon manifolds asked of Box2D (the rest were reused)
};

}  // namespace grainlab

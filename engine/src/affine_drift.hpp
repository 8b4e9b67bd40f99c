#pragma once
// The periodic cell's affine motion of the particles, after leapfrog's drift by their
// fluctuation velocities: x ← x + (L x) dt, the same map the cell's edges take in a step
// (PeriodicCell::advance), so a particle carried by the field keeps its place in the cell.
#include <Eigen/Core>

#include "grainlab/particle_store.hpp"

namespace grainlab {

inline void affineDrift(ParticleStore& particles, const Eigen::Matrix2d& L, double dt, int begin, int end) {
  Vec2* x = particles.position.data();
  for (int k = begin; k < end; ++k) {
    if (particles.motion[k] != Motion::Dynamic) continue;  // kinematic and fixed particles move as told
    x[k] += (L * x[k]) * dt;
  }
}

}  // namespace grainlab

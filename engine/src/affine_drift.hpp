#pragma once
// The periodic cell's affine motion of the particles, after leapfrog's drift by their
// fluctuation velocities: x ← x + (L x) dt, the same map the cell's edges take in a step
// (PeriodicCell::advance), so a particle carried by the field keeps its place in the cell.
#include <Eigen/Core>

#include "grainlab/particle_store.hpp"

namespace grainlab {

inline void affineDrift(ParticleStore& particles, const Eigen::Matrix2d& L, double dt, int begin, int end) {
  // L and dt in locals and the positions as plain doubles: a store to a position cannot be
  // taken to change them, so they stay in registers through the loop. The arithmetic is
  // Eigen's (L x) dt term for term, (L₀₀ x + L₀₁ y) dt and (L₁₀ x + L₁₁ y) dt: the same bits.
  const double l00 = L(0, 0), l01 = L(0, 1), l10 = L(1, 0), l11 = L(1, 1), step = dt;
  double* x = particles.position.data()->data();
  const Motion* motion = particles.motion.data();
  for (int k = begin; k < end; ++k) {
    if (motion[k] != Motion::Dynamic) continue;  // kinematic and fixed particles move as told
    const double px = x[2 * k], py = x[2 * k + 1];
    x[2 * k] = px + (l00 * px + l01 * py) * step;
    x[2 * k + 1] = py + (l10 * px + l11 * py) * step;
  }
}

}  // namespace grainlab

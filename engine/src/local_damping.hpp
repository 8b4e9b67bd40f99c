#pragma once
// Cundall's non-viscous damping of one body's force and torque, shared by every contact loop.
#include <cmath>

#include "grainlab/particle_store.hpp"

namespace grainlab {

/// Reduces each force component and the torque by α|F| against the direction of motion, so
/// it removes energy without slowing a steady drift. Bodies that forces do not move are left.
inline void applyLocalDamping(ParticleStore& particles, int k, double alpha) {
  if (particles.motion[k] != Motion::Dynamic) return;
  // The sign as a difference of two comparisons, not as branches: velocities' signs are
  // random, and mispredicted branches made this a seventh of a polygon run's time. The same
  // values (+1, −1 or 0), so the same bits.
  auto sign = [](double v) { return static_cast<double>(static_cast<int>(v > 0) - static_cast<int>(v < 0)); };
  Vec2& f = particles.force[k];
  const Vec2& v = particles.velocity[k];
  f.x() -= alpha * std::abs(f.x()) * sign(v.x());
  f.y() -= alpha * std::abs(f.y()) * sign(v.y());
  double& torque = particles.torque[k];
  torque -= alpha * std::abs(torque) * sign(particles.spin[k]);
}

}  // namespace grainlab

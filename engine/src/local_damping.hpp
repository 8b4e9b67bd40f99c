#pragma once
// Cundall's non-viscous damping of one body's force and torque, shared by every contact loop.
#include <cmath>

#include "grainlab/particle_store.hpp"

namespace grainlab {

/// Reduces each force component and the torque by α|F| against the direction of motion, so
/// it removes energy without slowing a steady drift. Bodies that forces do not move are left.
inline void applyLocalDamping(ParticleStore& particles, int k, double alpha) {
  if (particles.motion[k] != Motion::Dynamic) return;
  auto sign = [](double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); };
  Vec2& f = particles.force[k];
  const Vec2& v = particles.velocity[k];
  f.x() -= alpha * std::abs(f.x()) * sign(v.x());
  f.y() -= alpha * std::abs(f.y()) * sign(v.y());
  double& torque = particles.torque[k];
  torque -= alpha * std::abs(torque) * sign(particles.spin[k]);
}

}  // namespace grainlab

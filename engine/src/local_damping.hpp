#pragma once
// Cundall's non-viscous damping of the bodies' forces and torques, shared by every contact loop.
#include <cmath>

#include "grainlab/particle_store.hpp"
#include "local_damping_kernel.hpp"

namespace grainlab {

/// Reduces each force component and the torque of particles [begin, end) by α|F| against the
/// direction of motion, so it removes energy without slowing a steady drift. Bodies that forces
/// do not move are left.
///
/// Written as one pass over the arrays with selects, not branches: velocities' signs are random,
/// and a branch per component, mispredicted half the time, made the damping a fourteenth of a
/// polygon run's time. Each value still takes f − (α|f|)·sign(v), sign +1, −1 or 0, so the bits
/// are those of the branching form.
inline void applyLocalDampingScalar(ParticleStore& particles, int begin, int end, double alpha) {
  auto sign = [](double v) { return static_cast<double>(static_cast<int>(v > 0) - static_cast<int>(v < 0)); };
  double* __restrict f = particles.force.data()->data();  // x y per particle
  const double* __restrict v = particles.velocity.data()->data();
  double* __restrict tau = particles.torque.data();
  const double* __restrict w = particles.spin.data();
  const Motion* __restrict motion = particles.motion.data();
  for (int k = begin; k < end; ++k) {
    const bool dynamic = motion[k] == Motion::Dynamic;
    const double fx = f[2 * k], fy = f[2 * k + 1], t = tau[k];
    const double dampedX = fx - alpha * std::abs(fx) * sign(v[2 * k]);
    const double dampedY = fy - alpha * std::abs(fy) * sign(v[2 * k + 1]);
    const double dampedT = t - alpha * std::abs(t) * sign(w[k]);
    f[2 * k] = dynamic ? dampedX : fx;
    f[2 * k + 1] = dynamic ? dampedY : fy;
    tau[k] = dynamic ? dampedT : t;
  }
}

/// The damping on the run's path: on the wide one several particles per instruction
/// (local_damping_kernel.hpp), to the same bits.
inline void applyLocalDamping(ParticleStore& particles, int begin, int end, double alpha, bool widePath) {
  if (widePath) applyLocalDampingWide(particles, begin, end, alpha);
  else applyLocalDampingScalar(particles, begin, end, alpha);
}

}  // namespace grainlab

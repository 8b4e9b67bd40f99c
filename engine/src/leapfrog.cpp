#include "leapfrog.hpp"

#include <cmath>

#include "disc_leapfrog_kernel.hpp"
#include "incremental_rotation.hpp"
#include "polygon_leapfrog_kernel.hpp"

namespace grainlab {

void leapfrogAdvance(ParticleStore& particles, double dt, int begin, int end, bool widePath) {
  if (widePath) {
    if (particles.polygons.empty() && particles.clumps.empty()) leapfrogDiscsWide(particles, dt, begin, end);
    else leapfrogPolygonsWide(particles, dt, begin, end);
    return;
  }
  leapfrogAdvanceScalar(particles, dt, begin, end, widePath);
}

void leapfrogAdvanceScalar(ParticleStore& particles, double dt, int begin, int end, bool incrementalRotation) {
  // Local pointers: through the vectors, every store would make the compiler reload them.
  Vec2* __restrict x = particles.position.data();
  Vec2* __restrict v = particles.velocity.data();
  Vec2* __restrict f = particles.force.data();
  double* __restrict angle = particles.angle.data();
  double* __restrict w = particles.spin.data();
  double* __restrict tau = particles.torque.data();
  const double* invMass = particles.invMass.data();
  const double* invInertia = particles.invInertia.data();
  for (int k = begin; k < end; ++k) {
    v[k] += f[k] * (invMass[k] * dt);
    w[k] += tau[k] * (invInertia[k] * dt);
    x[k] += v[k] * dt;
    if (w[k] != 0) {
      const double turn = w[k] * dt;
      angle[k] += turn;
      // Only polygons' and clumps' contacts depend on their orientation: a disc's rotation is kept in
      // its angle alone (sincos was a fifth of a disc pile's step).
      if (incrementalRotation && particles.shape[k] != ShapeKind::Disc) {
        advanceRotation(particles.cosAngle[k], particles.sinAngle[k], turn, angle[k]);
      } else if (particles.shape[k] != ShapeKind::Disc) {
        ::sincos(angle[k], &particles.sinAngle[k], &particles.cosAngle[k]);
      }
    }
    f[k] = particles.bodyForce(k);
    tau[k] = 0;
  }
}

}  // namespace grainlab

// What the World reports about its state without changing it: energies and health.
#include <cmath>
#include <sstream>

#include "grainlab/errors.hpp"
#include "grainlab/world.hpp"
#include "solver.hpp"

namespace grainlab {

double World::kineticEnergy() const {
  // Leapfrog's velocities live half a step behind the positions; the energy is taken with
  // them brought to the positions' time, v + a·dt/2, as velocity Verlet would report it.
  const double half = solver_->velocitiesLagHalfStep() ? 0.5 * timestep() : 0.0;
  const ParticleStore& p = particles_;
  double e = 0;
  for (int k = 0; k < size(); ++k) {
    if (p.motion[k] != Motion::Dynamic) continue;
    const Vec2 v = p.velocity[k] + p.force[k] * (p.invMass[k] * half);
    const double w = p.spin[k] + p.torque[k] * p.invInertia[k] * half;
    e += 0.5 * p.mass[k] * v.squaredNorm() + 0.5 * p.inertia[k] * w * w;
  }
  return e;
}

double World::elasticEnergy() const { return solver_->elasticEnergy(); }

void World::checkHealth() const {
  const ParticleStore& p = particles_;
  for (int k = 0; k < size(); ++k) {
    const bool finite = std::isfinite(p.position[k].x()) && std::isfinite(p.position[k].y()) &&
                        std::isfinite(p.velocity[k].x()) && std::isfinite(p.velocity[k].y()) &&
                        std::isfinite(p.angle[k]) && std::isfinite(p.spin[k]);
    if (!finite) {
      std::ostringstream os;
      os << "particle " << k << " has a non-finite position or velocity at step " << steps_
         << " (t = " << time_ << " s): the simulation diverged; the timestep " << timestep()
         << " s against a critical timestep of " << criticalTimestep() << " s is the usual cause";
      throw SimulationError(os.str());
    }
  }
  solver_->checkOverlaps(steps_, timestep(), criticalTimestep());
}

}  // namespace grainlab

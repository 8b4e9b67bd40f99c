// A dense, undamped, frictionless packing conserves kinetic plus spring energy.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/world_helpers.hpp"

namespace grainlab {
namespace {

double worstEnergyError(double safety, int steps) {
  World world(test::material(1e8, 1.0, 0.0));
  std::vector<Wall> walls;
  for (const ParticleSpec& p : test::jammedLattice(20, walls)) world.addParticle(p);
  for (const Wall& w : walls) world.addWall(w);
  world.setTimestepSafety(safety);
  world.step();
  const double e0 = world.kineticEnergy() + world.elasticEnergy();
  EXPECT_GT(world.elasticEnergy(), 0.1 * e0);  // dense: much of the energy is in the springs
  double worst = 0;
  for (int k = 1; k < steps; ++k) {
    world.step();
    if (k % 100 == 0) {
      const double e = world.kineticEnergy() + world.elasticEnergy();
      worst = std::max(worst, std::abs(e - e0) / e0);
    }
  }
  return worst;
}

TEST(Energy, DenseUndampedFrictionlessPackingConservesEnergy) {
  // Leapfrog is symplectic: the energy does not drift, it oscillates by O((ω dt)²), ω the
  // packing's highest frequency (a few times a single contact's). At a timestep of 0.02 of
  // the critical one that is well under 0.1%.
  EXPECT_LT(worstEnergyError(0.02, 100000), 1e-3);
}

TEST(Energy, ErrorShrinksAsTheTimestepSquared) {
  // The second-order signature of the integrator: halving dt quarters the error (within
  // the scatter of contacts opening and closing).
  const double coarse = worstEnergyError(0.08, 20000), fine = worstEnergyError(0.04, 40000);
  EXPECT_GT(coarse / fine, 2.5);
  EXPECT_LT(coarse / fine, 6.0);
}

}  // namespace
}  // namespace grainlab

// A discs-only scene runs a force loop of its own (no polygon code, the contact point and the
// lever arms folded into the law). It must give the general loop's forces, to rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "engine/world_helpers.hpp"

namespace grainlab {
namespace {

// The jammed lattice with seeded spins of up to ±12 rad/s (a disc's own speed over its radius,
// so rolling and sliding both load the tangential springs), on a floor wall. With
// `farPolygon`, a square far above it turns the general loop on without touching anything.
void fillLattice(World& world, bool farPolygon) {
  std::vector<Wall> walls;
  std::vector<ParticleSpec> discs = test::jammedLattice(12, walls);
  std::uint64_t state = 11;
  for (ParticleSpec& p : discs) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;  // LCG: same on every platform
    p.spin = 24.0 * (static_cast<double>(state >> 11) * 0x1.0p-53 - 0.5);
    world.addParticle(p);
  }
  world.addWall(walls[2]);  // the floor only: a particle above the lattice meets no wall
  if (farPolygon) world.addParticle(test::box(0.004, 0.004, {0.02, 1.0}));
}

// The largest contact force (the scale rounding errors are relative to) and the largest
// tangential one.
struct ForceScale {
  double total = 0, tangential = 0;
};
ForceScale largestContactForces(const World& world) {
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  ForceScale largest;
  for (const ContactRecord& c : contacts) {
    largest.total = std::max(largest.total, std::hypot(c.fn, c.ft));
    largest.tangential = std::max(largest.tangential, std::abs(c.ft));
  }
  return largest;
}

TEST(DiscPath, DiscsOnlyLoopGivesTheGeneralLoopsForcesAndTorques) {
  const Material material = test::material(1e8, 0.5, 0.5);
  World discs(material), general(material);
  fillLattice(discs, false);
  fillLattice(general, true);
  ASSERT_FALSE(discs.hasPolygons());
  ASSERT_TRUE(general.hasPolygons());
  general.setTimestep(discs.timestep());
  const int n = discs.size();
  for (int step = 1; step <= 5; ++step) {
    discs.step();
    general.step();
    const ForceScale largest = largestContactForces(general);
    ASSERT_GT(largest.tangential, 0.05 * largest.total);  // friction is engaged
    const double fScale = largest.total, tScale = fScale * 0.002;  // lever arm: a radius
    // The loops round differently: a few ulp (1.1e-16) of fScale per force. Then positions
    // differ by up to an ulp (7e-18 m at 5 cm), a contact 8e-5 m deep feels that as up to
    // 1e-13 of its force, and the packing amplifies it step by step (measured: 3e-16 after
    // one step, 2e-14 after five, 2e-13 after twenty). Five steps load the tangential
    // springs and stay well below 1e-12; a wrong lever arm or sign is 1e-5 or more.
    for (int k = 0; k < n; ++k) {
      EXPECT_LE((discs.forces()[k] - general.forces()[k]).norm(), 1e-12 * fScale) << "disc " << k << ", step " << step;
      EXPECT_LE(std::abs(discs.torques()[k] - general.torques()[k]), 1e-12 * tScale)
          << "disc " << k << ", step " << step;
    }
  }
}

}  // namespace
}  // namespace grainlab

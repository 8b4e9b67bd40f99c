// A diverging simulation stops with a message that says why, and writes no NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "engine/world_helpers.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"

namespace grainlab {
namespace {

class RowCollector : public RunObserver {
 public:
  void onSample(const Sample& s, const World&) override { rows += formatSeriesRow(s) + "\n"; }
  std::string rows;
};

// The jammed lattice: beyond the critical timestep its stored energy blows up.
Scene jammed(double timestepOverCritical) {
  Scene scene;
  scene.material = test::material(1e8, 1.0, 0.5);
  scene.particles = test::jammedLattice(10, scene.walls);
  World probe(scene.material);
  for (const ParticleSpec& p : scene.particles) probe.addParticle(p);
  scene.solver.timestep = timestepOverCritical * probe.criticalTimestep();
  StageSpec free;
  free.name = "free";
  free.duration = 3000 * scene.solver.timestep;
  scene.stages = {free};
  scene.output.sampleInterval = 10 * scene.solver.timestep;
  return scene;
}

TEST(Stability, TimestepBeyondCriticalFailsWithReasonAndNoNaN) {
  RowCollector rows;
  const RunSummary s = runScene(jammed(3.0), rows);
  EXPECT_EQ(s.status, RunStatus::Failed);
  EXPECT_NE(s.error.find("timestep"), std::string::npos) << s.error;
  EXPECT_EQ(rows.rows.find("nan"), std::string::npos);
  EXPECT_EQ(rows.rows.find("inf"), std::string::npos);
}

TEST(Stability, TimestepBelowCriticalCompletes) {
  RowCollector rows;
  EXPECT_EQ(runScene(jammed(0.2), rows).status, RunStatus::Completed);
}

TEST(Stability, CriticalTimestepMatchesTheStiffestLightestContact) {
  const double r = 0.002, kn = 1e8, kt = 5e7;
  World world(test::material(kn, 1.0, 0.5, kt));
  world.addParticle(test::disc(r, {0, 0}));
  world.addParticle(test::disc(2 * r, {1, 0}));
  const double m = 2650 * kPi * r * r;  // the lighter disc; rotational factor 1 + m r²/I = 3
  EXPECT_NEAR(world.criticalTimestep(), 2 * std::sqrt(0.5 * m / std::max(kn, 3 * kt)), 1e-15);
  EXPECT_NEAR(world.timestep(), 0.2 * world.criticalTimestep(), 1e-18);
}

TEST(Stability, PolygonCriticalTimestepSeesTheNormalSpringThroughRotation) {
  // A square of side s: I = m s²/6 and R = s/√2, so 1 + m R²/I = 4 for both springs.
  const double side = 0.004, kn = 1e8, kt = 5e7;
  World world(test::material(kn, 1.0, 0.5, kt));
  world.addParticle(test::box(side, side, {0, 0}));
  const double m = 2650 * side * side;
  EXPECT_NEAR(world.criticalTimestep(), 2 * std::sqrt(0.5 * m / (4 * kn)), 1e-15);
}

}  // namespace
}  // namespace grainlab

namespace grainlab {
namespace {

// A chain of equal discs pressed between two walls, undamped: its highest mode has
// ω² = (4k/m) sin²(Nπ / 2(N+1)), so leapfrog is stable only below 2/ω, about √(m/k): √2 times
// shorter than the single-contact critical timestep √(2m/k).
struct Chain {
  static constexpr int kDiscs = 20;
  static constexpr double kR = 0.002, kStiffness = 1e8;
  World world{test::material(kStiffness, 1.0, 0.0)};
  double mass = 0;
  Chain() {
    std::uint64_t state = 3;
    for (int k = 0; k < kDiscs; ++k) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      const double kick = static_cast<double>(state >> 11) * 0x1.0p-53 - 0.5;
      world.addParticle(test::disc(kR, {k * 2 * kR * 0.999, 0}, {0.01 * kick, 0}));
    }
    world.addWall(Wall{Vec2(-kR * 0.999, 0), Vec2(1, 0)});
    world.addWall(Wall{Vec2((kDiscs - 1) * 2 * kR * 0.999 + kR * 0.999, 0), Vec2(-1, 0)});
    mass = world.masses()[0];
  }
  double stableLimit() const {
    const double s = std::sin(kDiscs * kPi / (2.0 * (kDiscs + 1)));
    return 2.0 / std::sqrt(4 * kStiffness / mass * s * s);
  }
  // Energy after `steps`, relative to the start.
  double energyGrowth(double dt, int steps) {
    world.setTimestep(dt);
    world.step();
    const double e0 = world.kineticEnergy() + world.elasticEnergy();
    for (int k = 0; k < steps; ++k) world.step();
    return (world.kineticEnergy() + world.elasticEnergy()) / e0;
  }
};

TEST(Stability, PackingTimestepIsTheChainsOwnLimitNotTheSingleContactOne) {
  Chain chain;
  chain.world.setTimestep(1e-12);
  chain.world.step();  // contacts in place
  int particle = -1, contacts = 0;
  const double bound = chain.world.packingTimestep(&particle, &contacts);
  EXPECT_EQ(contacts, 2);
  // Conservative, and tight for a chain (the highest mode's sine is 0.9972 at N = 20).
  EXPECT_LE(bound, chain.stableLimit());
  EXPECT_GT(bound, 0.99 * chain.stableLimit());
  // Two contacts, no tangential spring (frictionless): 2 √(½m / 2k) = √(m/k).
  EXPECT_NEAR(bound, std::sqrt(chain.mass / Chain::kStiffness), 1e-12);
}

TEST(Stability, ChainBelowPackingBoundKeepsItsEnergyAboveItsLimitBlowsUp) {
  Chain below, above;
  const double limit = below.stableLimit();
  EXPECT_NEAR(below.energyGrowth(0.95 * limit, 20000), 1.0, 0.05);
  // Still under the single-contact critical timestep (so not refused), yet unstable.
  ASSERT_LT(1.05 * limit, above.world.criticalTimestep());
  EXPECT_GT(above.energyGrowth(1.05 * limit, 2000), 10.0);
}

TEST(Stability, RunAbovePackingBoundSaysSoInItsNotes) {
  auto notesAt = [](double safety) {
    Scene scene = jammed(0.1);
    scene.material.restitution = 0.5;
    scene.solver.timestep = 0;
    scene.solver.timestepSafety = safety;
    RowCollector rows;
    return runScene(scene, rows).notes;
  };
  EXPECT_TRUE(notesAt(0.2).empty());
  // Between this lattice's packing bound (0.40-0.44 of the critical timestep) and the validity
  // envelope's hard limit (0.45, refused: docs/validity.md).
  const std::vector<std::string> notes = notesAt(0.44);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("packing's stability bound"), std::string::npos);
  EXPECT_NE(notes[0].find("timestep_safety"), std::string::npos);
}

}  // namespace
}  // namespace grainlab

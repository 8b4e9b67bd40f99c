// The neighbour list's skin (WorldSettings::skinFraction) trades rebuilds for listed pairs and
// changes no result between walls: the list keeps its pairs in (i, j) order, so the touching
// pairs' forces are added in the same order whatever else is listed, and a pair left out is
// too far apart to touch and keeps no state (no history, no polygon features). A dense pile of
// polygons and one of discs, shuffled and pressed so that contacts form, break and re-form
// through the run, are stepped with three skins on each contact path: every position,
// velocity, force, angle, spin and torque must keep its bits while the rebuilds differ.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>
#include <span>
#include <string>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/world.hpp"
#include "wide_path_support.hpp"
#include "world_helpers.hpp"

namespace grainlab {
namespace {

template <class T>
bool sameBits(std::span<const T> a, std::span<const T> b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size_bytes()) == 0;
}

// Every state the next step starts from, bit for bit (−0 is not +0).
void expectSameState(const World& a, const World& b, const std::string& what) {
  EXPECT_TRUE(sameBits(a.positions(), b.positions())) << what;
  EXPECT_TRUE(sameBits(a.velocities(), b.velocities())) << what;
  EXPECT_TRUE(sameBits(a.forces(), b.forces())) << what;
  EXPECT_TRUE(sameBits(a.angles(), b.angles())) << what;
  EXPECT_TRUE(sameBits(a.spins(), b.spins())) << what;
  EXPECT_TRUE(sameBits(a.torques(), b.torques())) << what;
}

TEST(VerletSkin, ChangesNoResultBetweenWalls) {
  for (const SimdPath path : {SimdPath::Baseline, SimdPath::Wide}) {
    for (const bool polygons : {false, true}) {
      const std::string what = std::string(path == SimdPath::Wide ? "wide" : "baseline") + (polygons ? ", polygons" : ", discs");
      overrideSimdPath(path);
      const Scene scene = test::pressedPile(10, 10, polygons, 11);
      WorldSettings thick, thin, thinnest;
      thick.skinFraction = 0.3;
      thin.skinFraction = 0.15;
      thinnest.skinFraction = 0.02;
      const std::unique_ptr<World> worlds[] = {test::worldOf(scene, thick), test::worldOf(scene, thin),
                                               test::worldOf(scene, thinnest)};
      for (int k = 0; k < 8000; ++k) {  // onto the floor and into each other
        for (const auto& w : worlds) w->step();
      }
      std::vector<ContactRecord> contacts;
      worlds[0]->contacts(contacts);
      EXPECT_GT(contacts.size(), 50u) << what;  // the pile of 100 is in contact (64-87 contacts)
      // The thinner skins rebuilt more often: the lists differed through the run.
      EXPECT_GT(worlds[2]->profile().rebuilds, 2 * worlds[0]->profile().rebuilds) << what;
      EXPECT_GT(worlds[0]->profile().rebuilds, 3) << what;
      for (int w = 1; w < 3; ++w) expectSameState(*worlds[0], *worlds[w], what + ", skin " + std::to_string(w));
    }
  }
  overrideSimdPath(std::nullopt);
}

// In a periodic cell a rebuild also wraps the positions into the cell, which rounds them, so
// there the skin would decide the results: the cell keeps its own (ContactSolver::initialize)
// and WorldSettings::skinFraction leaves a cell's results alone. 16 discs far apart in a
// sheared cell, at up to 1 m/s, cross its edges and meet; with the setting taken in the cell
// too, the two worlds part in their last bits.
TEST(VerletSkin, LeavesAPeriodicCellsResultsAlone) {
  const double r = 0.001, edge = 0.0176;
  Eigen::Matrix2d h, L;
  h << edge, 0, 0, edge;
  L << 0, 50, 0, 0;  // simple shear, 1/s
  for (const SimdPath path : {SimdPath::Baseline, SimdPath::Wide}) {
    overrideSimdPath(path);
    auto cellWorld = [&](double skinFraction) {
      WorldSettings settings;
      settings.skinFraction = skinFraction;
      auto world = std::make_unique<World>(test::material(1e6, 0.7, 0.4), settings);
      world->setPeriodicCell(h);
      std::mt19937_64 rng(5);
      std::uniform_real_distribution<double> u(-1, 1);
      for (int k = 0; k < 16; ++k) {
        const Vec2 x((k % 4 + 0.5 + 0.1 * u(rng)) * edge / 4, (k / 4 + 0.5 + 0.1 * u(rng)) * edge / 4);
        world->addParticle(test::disc(r * (1 + 0.05 * u(rng)), x, Vec2(u(rng), u(rng))));  // up to 1 m/s
      }
      world->setCellVelocityGradient(L);
      world->setTimestep(2e-7);
      world->initialize();
      return world;
    };
    const std::unique_ptr<World> thick = cellWorld(0.3), thin = cellWorld(0.15);
    int wraps = 0, touching = 0;
    std::vector<ContactRecord> contacts;
    for (int k = 0; k < 20000; ++k) {
      const std::vector<Vec2> before(thick->positions().begin(), thick->positions().end());
      thick->step();
      thin->step();
      for (int p = 0; p < thick->size(); ++p) wraps += (thick->positions()[p] - before[p]).norm() > 0.5 * edge;
      thick->contacts(contacts);
      touching += !contacts.empty();
      contacts.clear();
    }
    const std::string what = path == SimdPath::Wide ? "wide" : "baseline";
    EXPECT_GE(wraps, 2) << what;       // particles crossed the cell's edges (4)
    EXPECT_GT(touching, 100) << what;  // and met
    expectSameState(*thick, *thin, what);
  }
  overrideSimdPath(std::nullopt);
}

}  // namespace
}  // namespace grainlab

// The neighbour list's skin (WorldSettings::skinFraction) trades rebuilds for listed pairs and
// changes no result between walls: the list keeps its pairs in (i, j) order, so the touching
// pairs' forces are added in the same order whatever else is listed, and a pair left out is
// too far apart to touch and keeps no state (no history, no polygon features). A dense pile of
// polygons and one of discs, shuffled and pressed so that contacts form, break and re-form
// through the run, are stepped with three skins on each contact path: every position,
// velocity, force, angle, spin and torque must keep its bits while the rebuilds differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <string>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/world.hpp"
#include "wide_path_support.hpp"

namespace grainlab {
namespace {

Scene pressedPile(bool polygons) {
  Scene scene = pileScene(10, 10, polygons);
  std::mt19937_64 rng(11);
  std::shuffle(scene.particles.begin(), scene.particles.end(), rng);
  for (ParticleSpec& p : scene.particles) p.position *= 0.85;  // neighbours overlap from the start
  scene.gravity *= 50;
  return scene;
}

TEST(VerletSkin, ChangesNoResultBetweenWalls) {
  for (const SimdPath path : {SimdPath::Baseline, SimdPath::Wide}) {
    for (const bool polygons : {false, true}) {
      const std::string what = std::string(path == SimdPath::Wide ? "wide" : "baseline") + (polygons ? ", polygons" : ", discs");
      overrideSimdPath(path);
      const Scene scene = pressedPile(polygons);
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
      for (int w = 1; w < 3; ++w) {
        const World& a = *worlds[0];
        const World& b = *worlds[w];
        EXPECT_TRUE(std::equal(a.positions().begin(), a.positions().end(), b.positions().begin())) << what << ", skin " << w;
        EXPECT_TRUE(std::equal(a.velocities().begin(), a.velocities().end(), b.velocities().begin())) << what;
        EXPECT_TRUE(std::equal(a.forces().begin(), a.forces().end(), b.forces().begin())) << what;
        EXPECT_TRUE(std::equal(a.angles().begin(), a.angles().end(), b.angles().begin())) << what;
        EXPECT_TRUE(std::equal(a.spins().begin(), a.spins().end(), b.spins().begin())) << what;
        EXPECT_TRUE(std::equal(a.torques().begin(), a.torques().end(), b.torques().begin())) << what;
      }
    }
  }
  overrideSimdPath(std::nullopt);
}

}  // namespace
}  // namespace grainlab

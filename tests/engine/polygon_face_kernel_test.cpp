// The wide path's polygon contacts (polygon_face_batch.hpp, polygon_face_kernel.hpp): the
// face-against-edge pairs measured several per instruction must give measurePolygons' bits
// lane by lane, and a polygon pile on the wide path the baseline's forces to rounding, the same
// bits on any number of threads: each on every instruction set this build compiled, forced in
// turn (vectors of 1 to 8 doubles).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/world.hpp"
#include "polygon_collider.hpp"
#include "polygon_face_batch.hpp"
#include "wide_path_support.hpp"
#include "world_helpers.hpp"

namespace grainlab {
namespace {

constexpr double kUnit = 0x1p-53;  // a double's unit roundoff

bool sameBits(const ContactGeometry& a, const ContactGeometry& b) {
  const double x[5] = {a.normal.x(), a.normal.y(), a.point.x(), a.point.y(), a.overlap};
  const double y[5] = {b.normal.x(), b.normal.y(), b.point.x(), b.point.y(), b.overlap};
  return std::memcmp(x, y, sizeof x) == 0;
}

// Random pairs of four shapes (hexagons, a triangle and an octagon: the incident edge wraps at
// other corners), their features found at one pose and measured at another a little moved,
// some still touching and some slid apart. The kernel does measurePolygons' operations in its
// order, without fused products (the build contracts none) and with IEEE division, so the bound
// is zero: every lane must equal the scalar answer bit for bit. Two ranges of odd lengths (one
// starting past slot 0) cover the part-vectors at their ends.
TEST(PolygonFaceBatch, MeasuresWithMeasurePolygonsBits) {
  if (!test::wideSimdBuilt()) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  test::onEveryWideTarget([&](const std::string& target) {
    PolygonCollider collider(1.0 / 0.0025);
    const int shapes[] = {collider.add(test::ellipseHexagon(0.005)), collider.add(test::ellipseHexagon(0.0045)),
                          collider.add(test::regularPolygon(3, 0.0025)), collider.add(test::regularPolygon(8, 0.002))};
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int pairs = 2003, split = 997;
    PolygonFaceBatch batch;
    batch.resize(pairs);
    std::vector<ContactGeometry> expected;
    int slot = 0, touching = 0;
    while (slot < pairs) {
      const int a = shapes[rng() % 4], b = shapes[rng() % 4];
      const double reach = collider.polygon(a).circumradius + collider.polygon(b).circumradius;
      const double dir = 2 * kPi * unit(rng);
      const Pose pa{Vec2(0.01 * unit(rng), 0.01 * unit(rng)), 0, 0};
      const double angleA = 2 * kPi * unit(rng), angleB = 2 * kPi * unit(rng);
      const Pose ra{pa.x, std::cos(angleA), std::sin(angleA)};
      const Pose rb{ra.x + (0.4 + 0.6 * unit(rng)) * reach * Vec2(std::cos(dir), std::sin(dir)), std::cos(angleB), std::sin(angleB)};
      CachedContact kept;
      if (!collider.keepPolygonFeatures(a, ra, b, rb, kept)) continue;
      // Moved by up to 15 % of the size and 0.3 rad: the kept features, measured where they are now.
      const double turn = 0.3 * (2 * unit(rng) - 1);
      const Pose moved{rb.x + 0.15 * reach * Vec2(2 * unit(rng) - 1, 2 * unit(rng) - 1), std::cos(angleB + turn),
                       std::sin(angleB + turn)};
      CachedContact held = kept;
      held.slack = std::numeric_limits<double>::infinity();  // measured as kept, not searched again
      expected.push_back(collider.collidePolygons(a, ra, b, moved, &held));
      touching += expected.back().overlap > 0;
      batch.add(slot, slot, kept, a, ra, b, moved, collider);
      ++slot;
    }
    batch.measure(collider, 0, split);
    batch.measure(collider, split, pairs - split);
    int differing = 0;
    double worst = 0;
    for (int k = 0; k < pairs; ++k) {
      const ContactGeometry& got = batch.contact(k);
      if (!sameBits(got, expected[static_cast<size_t>(k)])) ++differing;
      worst = std::max(worst, std::abs(got.overlap - expected[static_cast<size_t>(k)].overlap));
    }
    EXPECT_EQ(differing, 0) << target << ": largest overlap difference " << worst << " m";
    // Both outcomes are exercised: touching lanes and lanes whose features no longer touch.
    EXPECT_GT(touching, pairs / 4) << target;
    EXPECT_LT(touching, pairs - pairs / 10) << target;
  });
}

// A shuffled polygon pile pressed together under 50 g, in contact (test::pressedPile, as the
// incremental rotation test builds it).
Scene pressedPolygonPile() { return test::pressedPile(12, 12, true, 7); }
std::unique_ptr<World> makeWorld(const Scene& scene, int threads) {
  WorldSettings settings;
  settings.threads = threads;
  auto w = std::make_unique<World>(scene.material, settings);
  for (const ParticleSpec& p : scene.particles) w->addParticle(p);
  for (const Wall& wall : scene.walls) w->addWall(wall);
  w->setGravity(scene.gravity);
  return w;
}

// One step from the same state on each path, with the pile's forces within rounding of the
// baseline's: tests/engine/incremental_rotation_test.cpp (the wide step there measures the
// pile's face-against-edge contacts in this batch).

// The batch is laid out per range of pairs, and each range measures its own slots: 1, 2 and 3
// threads must give the same bits.
TEST(PolygonFaceBatch, SameBitsOnOneTwoAndThreeThreads) {
  if (!test::wideSimdBuilt()) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  const Scene scene = pressedPolygonPile();
  test::onEveryWideTarget([&](const std::string& target) {
    std::vector<std::vector<double>> states;
    for (const int threads : {1, 2, 3}) {
      const std::unique_ptr<World> w = makeWorld(scene, threads);
      for (int k = 0; k < 1000; ++k) w->step();
      std::vector<double> state;
      for (int p = 0; p < w->size(); ++p) {
        state.insert(state.end(), {w->positions()[p].x(), w->positions()[p].y(), w->angles()[p], w->forces()[p].x(),
                                   w->forces()[p].y(), w->torques()[p]});
      }
      states.push_back(state);
    }
    for (size_t t = 1; t < states.size(); ++t) {
      EXPECT_EQ(0, std::memcmp(states[0].data(), states[t].data(), states[0].size() * sizeof(double)))
          << target << ", " << t + 1 << " threads";
    }
  });
}

}  // namespace
}  // namespace grainlab

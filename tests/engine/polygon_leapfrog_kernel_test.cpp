// The wide path's leapfrog for scenes of discs with polygons or clumps (polygon_leapfrog_kernel.hpp)
// gives the bits of the wide path's scalar loop (leapfrogAdvanceScalar() with incremental
// rotation): kick, drift, angle, and each polygon's or clump's cos and sin by the series or, for
// a large turn, by sincos. The wide path's polygon and clump runs keep their bits only if this
// holds exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <random>
#include <utility>
#include <vector>

#include "grainlab/particle_store.hpp"
#include "incremental_rotation.hpp"
#include "leapfrog.hpp"
#include "wide_path_support.hpp"

namespace grainlab {
namespace {

constexpr double kStep = 0x1p-18;  // 3.8 µs; a power of two, so a spin of 4096 rad/s turns exactly 1/64
constexpr int kParticles = 45;     // no whole number of vectors on any target

class PolygonLeapfrogKernel : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!test::wideSimdBuilt()) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  }
};

// Discs, polygons and clumps mixed (one in three a disc, one in six a clump) of every motion,
// under gravity whose y is negative. Spins: none (w = 0 lanes, of both zeros' signs), a turn of
// exactly kMaxIncrementalTurn (the series) and one a rounding above it (sincos), turns of a
// tenth of a radian (sincos) and small random turns with torques (the series). Cos and sin
// start a few ulps off the unit circle, as after a long run, so the renormalisation shows in
// their bits.
ParticleStore mixedScene(unsigned seed) {
  ParticleStore store;
  store.gravity = Vec2(0.7, -9.81);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Material material;
  const Polygon hexagon = test::ellipseHexagon(0.002), square = test::regularPolygon(4, 0.001);
  for (int k = 0; k < kParticles; ++k) {
    ParticleSpec spec;
    if (k % 3 == 2) {
      spec.radius = 0.001 * (1.5 + u(rng));
    } else if (k % 6 == 4) {  // a clump of three discs in a line
      spec.shape = ShapeKind::Clump;
      spec.members = {{Vec2(-0.001, 0), 0.0006}, {Vec2(0, 0), 0.0006}, {Vec2(0.001, 0), 0.0006}};
    } else {
      spec.shape = ShapeKind::Polygon;
      const Polygon& shape = k % 2 ? hexagon : square;
      spec.vertices.assign(shape.vertices.begin(), shape.vertices.begin() + shape.count);
    }
    spec.position = Vec2(u(rng), u(rng));
    spec.velocity = Vec2(u(rng), u(rng));
    spec.angle = k % 4 == 0 ? -0.0 : 3 * u(rng);
    const double over = std::nextafter(kMaxIncrementalTurn / kStep, 1e9);
    const int kind = k % 8;
    spec.spin = kind == 0 ? 0.0 : kind == 1 ? -0.0 : kind == 2 ? kMaxIncrementalTurn / kStep : kind == 3 ? -over
              : kind == 4 ? 0.1 / kStep * u(rng) : 50 * u(rng);
    spec.motion = k % 5 == 1 ? Motion::Fixed : k % 7 == 2 ? Motion::Kinematic : Motion::Dynamic;
    store.add(spec, material);
    store.cosAngle[k] *= 1 + 5e-16 * u(rng);
    store.sinAngle[k] *= 1 + 5e-16 * u(rng);
    // A kick of the order of the velocity, so that each product's rounding shows in the sum;
    // no torque where the spin is to stay as it was set.
    store.force[k] = Vec2(u(rng), u(rng)) / (store.invMass[k] > 0 ? store.invMass[k] * kStep : 1.0);
    if (kind >= 5) store.torque[k] = u(rng) * 50 / (store.invInertia[k] > 0 ? store.invInertia[k] * kStep : 1.0);
  }
  return store;
}

void expectSameBits(const ParticleStore& a, const ParticleStore& b, const std::string& what) {
  EXPECT_TRUE(test::sameBits(a.position, b.position)) << what;
  EXPECT_TRUE(test::sameBits(a.velocity, b.velocity)) << what;
  EXPECT_TRUE(test::sameBits(a.force, b.force)) << what;
  EXPECT_TRUE(test::sameBits(a.angle, b.angle)) << what;
  EXPECT_TRUE(test::sameBits(a.spin, b.spin)) << what;
  EXPECT_TRUE(test::sameBits(a.torque, b.torque)) << what;
  EXPECT_TRUE(test::sameBits(a.cosAngle, b.cosAngle)) << what;
  EXPECT_TRUE(test::sameBits(a.sinAngle, b.sinAngle)) << what;
}

TEST_F(PolygonLeapfrogKernel, GivesTheWideScalarLoopsBits) {
  const std::pair<int, int> ranges[] = {{0, kParticles}, {3, 42}, {5, 6}, {8, 24}, {1, 12}};
  int targets = 0;
  test::onEveryWideTarget([&](const std::string& target) {
    targets += 1;
    for (unsigned seed = 1; seed <= 20; ++seed) {
      for (const auto& [begin, end] : ranges) {
        ParticleStore scalar = mixedScene(seed), wide = mixedScene(seed);
        for (int step = 0; step < 3; ++step) {
          leapfrogAdvanceScalar(scalar, kStep, begin, end, true);
          leapfrogAdvance(wide, kStep, begin, end, true);
        }
        expectSameBits(scalar, wide, target + ", seed " + std::to_string(seed) + ", [" + std::to_string(begin) +
                                         ", " + std::to_string(end) + ")");
      }
    }
  });
  EXPECT_GE(targets, 1);
}

// The scene tests what it says: both of a polygon's (and a clump's) rotations are taken, the
// series right at its limit, and a spinning disc's cos and sin stay as they were, as do particles
// outside the range.
TEST_F(PolygonLeapfrogKernel, TheSceneTakesBothRotationsAndLeavesTheRestAlone) {
  const ParticleStore before = mixedScene(1);
  ParticleStore after = mixedScene(1);
  leapfrogAdvance(after, kStep, 3, 42, true);
  int series = 0, sincos = 0, atTheLimit = 0, spinningDiscs = 0, turningClumps = 0;
  for (int k = 3; k < 42; ++k) {
    const double turn = after.spin[k] * kStep;
    if (after.shape[k] == ShapeKind::Disc) {
      spinningDiscs += turn != 0;
      EXPECT_EQ(after.cosAngle[k], before.cosAngle[k]) << k;
      EXPECT_EQ(after.sinAngle[k], before.sinAngle[k]) << k;
    } else if (turn != 0) {
      EXPECT_NE(after.cosAngle[k], before.cosAngle[k]) << k;
      turningClumps += after.shape[k] == ShapeKind::Clump;
      (std::abs(turn) <= kMaxIncrementalTurn ? series : sincos) += 1;
      atTheLimit += std::abs(turn) == kMaxIncrementalTurn;
      if (std::abs(turn) > kMaxIncrementalTurn) {  // sincos of the new angle, exactly
        double s, c;
        ::sincos(after.angle[k], &s, &c);
        EXPECT_EQ(after.cosAngle[k], c) << k;
        EXPECT_EQ(after.sinAngle[k], s) << k;
      }
    } else {
      EXPECT_EQ(after.cosAngle[k], before.cosAngle[k]) << k;
    }
  }
  EXPECT_GE(series, 8);
  EXPECT_GE(sincos, 4);
  EXPECT_GE(atTheLimit, 2);
  EXPECT_GE(spinningDiscs, 4);
  EXPECT_GE(turningClumps, 3);
  for (const int k : {0, 1, 2, 42, 43, 44}) {
    EXPECT_EQ(after.position[k], before.position[k]) << k;
    EXPECT_EQ(after.cosAngle[k], before.cosAngle[k]) << k;
    EXPECT_EQ(after.force[k], before.force[k]) << k;
  }
  EXPECT_NE(after.position[3], before.position[3]);
  EXPECT_FALSE(std::signbit(after.force[6].y()));  // a fixed particle's force restarts at +0 (6 % 5 == 1)
}

}  // namespace
}  // namespace grainlab

// The wide path's kick and drift of discs and its skin check give the scalar loops' bits and
// answers: the same arithmetic, several particles per instruction (disc_leapfrog_kernel.hpp,
// skin_check_kernel.hpp). The wide path's runs keep their bits only if these hold exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "grainlab/particle_store.hpp"
#include "grainlab/simd_path.hpp"
#include "leapfrog.hpp"
#include "neighbor_list.hpp"
#include "wide_path_support.hpp"

namespace grainlab {
namespace {

class WideIntegration : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!test::wideSimdBuilt()) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  }
};

// 37 discs (no whole number of vectors on any target) of every motion, some spinning and some
// not, angles of both zeros' signs, forces of every sign, under gravity whose y is negative (a
// fixed disc's weight must stay +0, not 0 × g = −0).
ParticleStore discs() {
  ParticleStore store;
  store.gravity = Vec2(0.7, -9.81);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  Material material;
  for (int k = 0; k < 37; ++k) {
    ParticleSpec spec;
    spec.radius = 0.001 * (1.5 + u(rng));
    spec.position = Vec2(u(rng), u(rng));
    spec.velocity = Vec2(u(rng), u(rng));
    spec.spin = k % 3 == 0 ? 0.0 : 50 * u(rng);
    spec.angle = k % 4 == 0 ? -0.0 : u(rng);
    spec.motion = k % 5 == 1 ? Motion::Fixed : k % 7 == 2 ? Motion::Kinematic : Motion::Dynamic;
    store.add(spec, material);
    // A kick of the order of the velocity, so that each product's rounding shows in the sum.
    store.force[k] = Vec2(u(rng), u(rng)) / (store.invMass[k] > 0 ? store.invMass[k] * 3.7e-6 : 1.0);
    store.torque[k] = u(rng) * 50 / (store.invInertia[k] > 0 ? store.invInertia[k] * 3.7e-6 : 1.0);
  }
  return store;
}

TEST_F(WideIntegration, KickAndDriftGiveTheScalarLoopsBits) {
  const double dt = 3.7e-6;
  test::onEveryWideTarget([&](const std::string& target) {
    for (const auto& [begin, end] : {std::pair{0, 37}, std::pair{3, 34}, std::pair{5, 6}}) {
      ParticleStore scalar = discs(), wide = discs();
      for (int step = 0; step < 3; ++step) {
        leapfrogAdvance(scalar, dt, begin, end, false);
        leapfrogAdvance(wide, dt, begin, end, true);
      }
      EXPECT_TRUE(test::sameBits(scalar.position, wide.position)) << target << " [" << begin << ", " << end << ")";
      EXPECT_TRUE(test::sameBits(scalar.velocity, wide.velocity)) << target << " [" << begin << ", " << end << ")";
      EXPECT_TRUE(test::sameBits(scalar.force, wide.force)) << target << " [" << begin << ", " << end << ")";
      EXPECT_TRUE(test::sameBits(scalar.angle, wide.angle)) << target << " [" << begin << ", " << end << ")";
      EXPECT_TRUE(test::sameBits(scalar.spin, wide.spin)) << target << " [" << begin << ", " << end << ")";
      EXPECT_TRUE(test::sameBits(scalar.torque, wide.torque)) << target << " [" << begin << ", " << end << ")";
    }
  });
  // The loop moved what it should: a fixed disc keeps its place, a dynamic one does not.
  ParticleStore before = discs(), after = discs();
  leapfrogAdvance(after, dt, 0, 37, true);
  EXPECT_EQ(after.position[1], before.position[1]);  // fixed (k % 5 == 1)
  EXPECT_NE(after.position[0], before.position[0]);
  EXPECT_FALSE(std::signbit(after.force[1].y()));  // a fixed disc's force restarts at +0
}

TEST_F(WideIntegration, SkinCheckAnswersAsTheScalarCheck) {
  test::onEveryWideTarget([&](const std::string& target) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    const int n = 37;
    const double skin = 0.001;
    std::vector<Vec2> at(n);
    std::vector<double> radii(n, 0.0004);
    std::vector<Motion> motions(n, Motion::Dynamic);
    const std::vector<Wall> walls;
    for (int k = 0; k < n; ++k) at[static_cast<size_t>(k)] = Vec2(0.01 * k, 0.003 * u(rng));
    NeighborList list;
    ASSERT_TRUE(list.update(at, radii, motions, walls, skin, true)) << target;
    // One disc moved by half the skin times 1 ± a few ulps, in a random direction: the checks
    // must agree at the boundary, where a fused or reordered sum would answer otherwise.
    int beyond = 0, within = 0;
    for (int trial = 0; trial < 4000; ++trial) {
      std::vector<Vec2> moved = at;
      const int k = static_cast<int>(rng() % n);
      const double angle = 3.14159 * u(rng);
      const double reach = 0.5 * skin * (1 + 4e-16 * u(rng));
      moved[static_cast<size_t>(k)] += reach * Vec2(std::cos(angle), std::sin(angle));
      for (const auto& [begin, end] : {std::pair{0, n}, std::pair{k, k + 1}, std::pair{1, n - 1}}) {
        const bool expected = list.outdated(moved, begin, end, false);
        EXPECT_EQ(list.outdated(moved, begin, end, true), expected)
            << target << ": disc " << k << " in [" << begin << ", " << end << ")";
        if (begin == 0 && end == n) (expected ? beyond : within) += 1;
      }
    }
    // Both answers were tested.
    EXPECT_GT(beyond, 100) << target;
    EXPECT_GT(within, 100) << target;
  });
}

}  // namespace
}  // namespace grainlab

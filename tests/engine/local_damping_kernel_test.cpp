// The wide path's local damping (local_damping_kernel.hpp) gives the scalar loop's bits on every
// instruction set, and both give Cundall's closed form: each force component and the torque of a
// dynamic particle lose α|f| against their own velocity's sign, nothing where that velocity is
// zero, and particles that forces do not move keep their forces.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <utility>

#include "grainlab/particle_store.hpp"
#include "local_damping.hpp"
#include "wide_path_support.hpp"

namespace grainlab {
namespace {

constexpr int kParticles = 45;  // no whole number of vectors on any target
constexpr double kAlpha = 0.3;

class LocalDampingKernel : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!test::wideSimdBuilt()) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  }
};

// Discs of every motion. Velocities and spins: positive, negative, +0 and −0 (no damping);
// forces and torques of both signs and both zeros, so that a sign taken wrong, or a damping
// applied where the velocity is zero, shows in the bits.
ParticleStore scene(unsigned seed) {
  ParticleStore store;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Material material;
  auto value = [&](int kind) { return kind == 0 ? 0.0 : kind == 1 ? -0.0 : u(rng); };
  for (int k = 0; k < kParticles; ++k) {
    ParticleSpec spec;
    spec.radius = 0.001;
    spec.motion = k % 5 == 1 ? Motion::Fixed : k % 7 == 2 ? Motion::Kinematic : Motion::Dynamic;
    store.add(spec, material);
    store.velocity[k] = Vec2(value(static_cast<int>(rng() % 6)), value(static_cast<int>(rng() % 6)));
    store.spin[k] = value(static_cast<int>(rng() % 6));
    store.force[k] = Vec2(value(static_cast<int>(rng() % 8)), value(static_cast<int>(rng() % 8))) * 1e3;
    store.torque[k] = value(static_cast<int>(rng() % 8));
  }
  return store;
}

TEST_F(LocalDampingKernel, GivesTheScalarLoopsBits) {
  const std::pair<int, int> ranges[] = {{0, kParticles}, {3, 42}, {5, 6}, {8, 24}, {1, 12}};
  int targets = 0;
  test::onEveryWideTarget([&](const std::string& target) {
    targets += 1;
    for (unsigned seed = 1; seed <= 20; ++seed) {
      for (const auto& [begin, end] : ranges) {
        ParticleStore scalar = scene(seed), wide = scene(seed);
        applyLocalDampingScalar(scalar, begin, end, kAlpha);
        applyLocalDampingWide(wide, begin, end, kAlpha);
        const std::string what = target + ", seed " + std::to_string(seed) + ", [" + std::to_string(begin) + ", " +
                                 std::to_string(end) + ")";
        EXPECT_TRUE(test::sameBits(scalar.force, wide.force)) << what;
        EXPECT_TRUE(test::sameBits(scalar.torque, wide.torque)) << what;
      }
    }
  });
  EXPECT_GE(targets, 1);
}

TEST_F(LocalDampingKernel, TakesCundallsClosedFormOnBothPaths) {
  for (const bool wide : {false, true}) {
    const ParticleStore before = scene(3);
    ParticleStore after = scene(3);
    applyLocalDamping(after, 3, 42, kAlpha, wide);
    int damped = 0, still = 0;
    for (int k = 0; k < kParticles; ++k) {
      const bool moves = k >= 3 && k < 42 && before.motion[k] == Motion::Dynamic;
      const double f[3] = {before.force[k].x(), before.force[k].y(), before.torque[k]};
      const double v[3] = {before.velocity[k].x(), before.velocity[k].y(), before.spin[k]};
      const double out[3] = {after.force[k].x(), after.force[k].y(), after.torque[k]};
      for (int c = 0; c < 3; ++c) {
        // (1 ∓ α) f, exactly: α|f| against the motion, with |f| = ±f.
        const double expected = !moves || v[c] == 0 ? f[c] : f[c] * (v[c] * f[c] > 0 ? 1 - kAlpha : 1 + kAlpha);
        EXPECT_NEAR(out[c], expected, 1e-15 * std::abs(f[c])) << (wide ? "wide" : "scalar") << ", particle " << k;
        if (!moves || v[c] == 0) {
          EXPECT_EQ(std::signbit(out[c]), std::signbit(f[c])) << k;  // left as it was, zeros' signs too
        }
        (moves && v[c] != 0 && f[c] != 0 ? damped : still) += 1;
      }
    }
    EXPECT_GE(damped, 30);  // the scene tests what it says: many damped, many left
    EXPECT_GE(still, 20);
  }
}

}  // namespace
}  // namespace grainlab

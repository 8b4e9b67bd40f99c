// The wide path advances a polygon's cos and sin by its step's turn (incremental_rotation.hpp)
// instead of sincos of its angle. It must agree with sincos to rounding after one step, keep
// its norm at 1 and its phase within the rounding it accumulates over a long run, and give a
// polygon pile the baseline's forces to within what that rounding moves a contact by.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/particle_store.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/world.hpp"
#include "incremental_rotation.hpp"
#include "leapfrog.hpp"
#include "wide_path_support.hpp"
#include "world_helpers.hpp"

namespace grainlab {
namespace {

constexpr double kUnit = 0x1p-53;  // a double's unit roundoff

// One turn from (cos θ, sin θ), against cos and sin of θ + δ in long double (64-bit mantissa:
// exact to well below a double's rounding here). The series is exact to rounding for
// |δ| ≤ 1/64; the rounding is: glibc's sincos of θ, ≤ 1 ulp each (2u); cos δ and sin δ, a few
// u; the two products and the sum, 3u; the renormalisation, 3u. 16u bounds it. A sine series
// short of its δ⁵ term (8e-12 at 1/64) fails by four orders of magnitude, a turn the wrong way
// by more. (The renormalisation hides an error in cos δ alone: it moves the norm, not the phase.)
TEST(IncrementalRotation, OneTurnIsExactToRounding) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> angle(-50, 50), exponent(-12, std::log10(kMaxIncrementalTurn));
  double worst = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const double theta = angle(rng);
    const double delta = (trial % 2 ? 1 : -1) * std::pow(10.0, exponent(rng));
    double c, s;
    ::sincos(theta, &s, &c);
    rotateIncrementally(c, s, delta);
    const long double exact = static_cast<long double>(theta) + static_cast<long double>(delta);
    worst = std::max({worst, std::abs(c - static_cast<double>(cosl(exact))), std::abs(s - static_cast<double>(sinl(exact)))});
  }
  EXPECT_LE(worst, 16 * kUnit);
  EXPECT_GT(worst, 0);  // the comparison sees rounding at all
}

// At the largest incremental turn the last series term kept matters: 1/64 is where it is tested.
TEST(IncrementalRotation, TheLargestIncrementalTurnIsExactToRounding) {
  for (const double delta : {kMaxIncrementalTurn, -kMaxIncrementalTurn}) {
    double c = 1, s = 0;
    rotateIncrementally(c, s, delta);
    EXPECT_LE(std::abs(c - static_cast<double>(cosl(delta))), 4 * kUnit);
    EXPECT_LE(std::abs(s - static_cast<double>(sinl(delta))), 4 * kUnit);
  }
}

// A million steps of a steady spin: the norm stays within rounding of 1 (renormalised every
// step; without it the norm walks by about √N u ≈ 1e-13), and the phase within the rounding a
// step adds, N × 8u (random signs make it far less).
TEST(IncrementalRotation, AMillionStepsKeepNormAndPhase) {
  const int steps = 1000000;
  const double theta0 = 0.7, delta = 3.1e-5;
  double c, s;
  ::sincos(theta0, &s, &c);
  for (int k = 0; k < steps; ++k) rotateIncrementally(c, s, delta);
  EXPECT_LE(std::abs(c * c + s * s - 1), 8 * kUnit);
  const long double exact = static_cast<long double>(theta0) + static_cast<long double>(steps) * delta;
  const double phase = std::abs(std::atan2(s * static_cast<double>(cosl(exact)) - c * static_cast<double>(sinl(exact)),
                                           c * static_cast<double>(cosl(exact)) + s * static_cast<double>(sinl(exact))));
  EXPECT_LE(phase, steps * 8 * kUnit);
}

TEST(IncrementalRotation, ALargeTurnTakesSincosOfTheAngle) {
  double c = 1, s = 0;
  const double angle = 0.3;
  advanceRotation(c, s, 2 * kMaxIncrementalTurn, angle);
  double sc, ss;
  ::sincos(angle, &ss, &sc);
  EXPECT_EQ(c, sc);
  EXPECT_EQ(s, ss);
}

// A shuffled polygon pile pressed together under 50 g, stepped on the baseline, then one step
// more on each path. The wide path differs only in the polygons' cos and sin, which it holds
// within 16u of cos and sin of the exact angle while sincos holds them within 2u of those of
// the rounded angle (within u|θ| of the exact one): within Δ = (u max|θ| + 18u) rad of each
// other. A contact point moves by at most its lever (the circumradius a) times that, so an
// overlap by 2aΔ (both bodies); a normal force by k_n 2aΔ per contact. The rest moves less:
// the force's direction turns by Δ (|F|Δ, with |F| ≪ k_n a), the lever in the damping's
// relative velocity by aΔ (ω aΔ). A particle has at most 8 contacts: 8 × 2 × k_n 2aΔ bounds its
// force gap, a times that its torque's. A turn the wrong way or a skipped update moves an
// overlap by a ω dt, orders of magnitude above aΔ ≈ 1e-14 a. The wide step also measures the
// polygons' face-against-edge contacts in batches (polygon_face_kernel.hpp), to the scalar
// measurement's bits, so a broken term there fails this bound too (an end's depth without its
// rise: a 2,203 N gap against the 6.85e-8 N bound). On every instruction set this build
// compiled, forced in turn.
TEST(IncrementalRotation, APolygonPileGetsTheBaselinesForcesToRounding) {
  overrideSimdPath(SimdPath::Wide);
  const bool built = simdPath() == SimdPath::Wide;
  overrideSimdPath(std::nullopt);
  if (!built) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  test::onEveryWideTarget([&](const std::string& target) {
    SCOPED_TRACE(target);
    const Scene scene = test::pressedPile(12, 12, true, 7);
    const std::unique_ptr<World> baseline = test::worldOf(scene, {}), wide = test::worldOf(scene, {});
    overrideSimdPath(SimdPath::Baseline);
    for (int k = 0; k < 8000; ++k) {  // onto the floor and into each other
      baseline->step();
      wide->step();
    }
    baseline->step();
    overrideSimdPath(SimdPath::Wide);
    wide->step();
    overrideSimdPath(std::nullopt);
    double largestAngle = 0, largestRadius = 0, forceGap = 0, torqueGap = 0;
    for (int p = 0; p < baseline->size(); ++p) {
      ASSERT_EQ(baseline->angles()[p], wide->angles()[p]);  // the angle itself is advanced alike
      largestAngle = std::max(largestAngle, std::abs(baseline->angles()[p]));
      forceGap = std::max(forceGap, (wide->forces()[p] - baseline->forces()[p]).norm());
      torqueGap = std::max(torqueGap, std::abs(wide->torques()[p] - baseline->torques()[p]));
    }
    for (const ParticleSpec& p : scene.particles) {
      for (const Vec2& v : p.vertices) largestRadius = std::max(largestRadius, v.norm());
    }
    std::vector<ContactRecord> contacts;
    baseline->contacts(contacts);
    ASSERT_GT(contacts.size(), 100u) << "time " << baseline->time();  // the pile is in contact
    const auto polygonPairs = std::count_if(contacts.begin(), contacts.end(), [](const ContactRecord& c) { return c.j >= 0; });
    ASSERT_GT(polygonPairs, 100) << "the pile's polygons press on each other (not only on the walls)";
    const double delta = kUnit * largestAngle + 18 * kUnit;
    const double forceBound = 8 * 2 * scene.material.normalStiffness * 2 * largestRadius * delta;
    EXPECT_LE(forceGap, forceBound);
    EXPECT_LE(torqueGap, forceBound * largestRadius);
    EXPECT_GT(forceGap, 0);  // the paths do differ: the wide step took the incremental rotation
  });
}

// A clump's members are placed from its body's cos and sin, so the wide path turns a clump as
// it turns a polygon: by the series where the step's turn is at most 1/64, by sincos of the
// angle beyond; the baseline takes sincos of the angle every step. Each clump here starts a few
// ulps off the unit circle, as after a long run, so that the series' result (renormalised)
// differs in its bits from sincos of the new angle: a clump left to sincos on the wide path
// fails the first expectation, a clump given the series on the baseline the second.
TEST(IncrementalRotation, AClumpTurnsByTheSeriesOnTheWidePathAndBySincosOnTheBaseline) {
  constexpr double kStep = 0x1p-18;
  const double spins[] = {50.0, -3000.0, kMaxIncrementalTurn / kStep, 0.1 / kStep, -0.1 / kStep};
  ParticleStore store;
  Material material;
  for (size_t k = 0; k < std::size(spins); ++k) {
    ParticleSpec spec;
    spec.shape = ShapeKind::Clump;
    spec.members = {{Vec2(-0.001, 0), 0.0006}, {Vec2(0, 0), 0.0006}, {Vec2(0.001, 0), 0.0006}};
    spec.position = Vec2(0.01 * static_cast<double>(k), 0);
    spec.angle = 0.3 + static_cast<double>(k);
    spec.spin = spins[k];
    store.add(spec, material);
    store.cosAngle[k] *= 1 + 0x1p-50;
    store.sinAngle[k] *= 1 - 0x1p-50;
  }
  ASSERT_FALSE(store.clumps.empty());
  ParticleStore wide = store, baseline = store;
  const int n = static_cast<int>(store.size());
  leapfrogAdvance(wide, kStep, 0, n, true);
  leapfrogAdvance(baseline, kStep, 0, n, false);
  int bySeries = 0;
  for (int k = 0; k < n; ++k) {
    SCOPED_TRACE("clump " + std::to_string(k) + ", spin " + std::to_string(spins[k]));
    ASSERT_EQ(wide.angle[k], baseline.angle[k]);  // the angle is advanced alike
    double s, c;
    ::sincos(baseline.angle[k], &s, &c);
    EXPECT_EQ(baseline.cosAngle[k], c);
    EXPECT_EQ(baseline.sinAngle[k], s);
    const double turn = wide.spin[k] * kStep;
    if (std::abs(turn) <= kMaxIncrementalTurn) {
      double cs = store.cosAngle[k], sn = store.sinAngle[k];
      rotateIncrementally(cs, sn, turn);
      EXPECT_EQ(wide.cosAngle[k], cs);
      EXPECT_EQ(wide.sinAngle[k], sn);
      EXPECT_TRUE(wide.cosAngle[k] != c || wide.sinAngle[k] != s) << "the start off the circle shows in the bits";
      // and to rounding the same rotation: the start's 2^-50 off the circle and 16 u of the turn
      EXPECT_NEAR(wide.cosAngle[k], c, 0x1p-49 + 16 * kUnit);
      EXPECT_NEAR(wide.sinAngle[k], s, 0x1p-49 + 16 * kUnit);
      ++bySeries;
    } else {
      EXPECT_EQ(wide.cosAngle[k], c);
      EXPECT_EQ(wide.sinAngle[k], s);
    }
  }
  EXPECT_EQ(bySeries, 3);
}

}  // namespace
}  // namespace grainlab

// A disc or a polygon on a wall: static overlap, sliding to rolling, sticking and sliding
// on an incline.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/world_helpers.hpp"

namespace grainlab {
namespace {

using test::box;
using test::disc;

TEST(WallContact, DiscRestsAtOverlapMgOverK) {
  const double r = 0.002, kn = 1e7, g = 9.81;
  World world(test::material(kn, 0.3, 0.5));
  world.addWall({Vec2(0, 0), Vec2(0, 1)});
  world.addParticle(disc(r, {0, r}));
  world.setGravity({0, -g});
  for (int k = 0; k < 200000; ++k) world.step();
  const double expected = world.masses()[0] * g / kn;
  const double overlap = r - world.positions()[0].y();
  // At rest the spring alone carries the weight: exact up to the residual oscillation.
  EXPECT_NEAR(overlap, expected, 1e-4 * expected);
  EXPECT_LT(std::abs(world.velocities()[0].y()), 1e-6);
}

TEST(WallContact, SlidingDiscEndsRollingAtTwoThirdsSpeed) {
  const double r = 0.002, kn = 1e7, g = 9.81, v0 = 0.5;
  World world(test::material(kn, 0.3, 0.3));
  world.addWall({Vec2(0, 0), Vec2(0, 1)});
  const double m = 2650 * kPi * r * r;
  world.addParticle(disc(r, {0, r - m * g / kn}, {v0, 0}, 0.0));
  world.setGravity({0, -g});
  // Friction decelerates the slide by μg and spins the disc up by 2μg/r: they roll after
  // v0 / (3μg) = 0.057 s. Run well past it.
  for (double t = 0; t < 0.3;) {
    world.step();
    t = world.time();
  }
  const double v = world.velocities()[0].x(), w = world.spins()[0];
  EXPECT_NEAR(v, 2.0 / 3.0 * v0, 0.01 * v0);
  EXPECT_NEAR(-w * r, v, 0.01 * v0);  // rolling without slip: v = −ω r
}

double blockDisplacementOnIncline(double inclineDeg, double mu, double seconds) {
  // The incline is the wall y = 0 with gravity tilted by the incline angle: the same thing.
  const double kn = 1e7, g = 9.81, side = 0.004, t = radians(inclineDeg);
  World world(test::material(kn, 0.3, mu));
  world.addWall({Vec2(0, 0), Vec2(0, 1)});
  const double m = 2650 * side * side;
  world.addParticle(box(side, side, {0, side / 2 - m * g * std::cos(t) / kn}));
  world.setGravity({g * std::sin(t), -g * std::cos(t)});
  const double x0 = world.positions()[0].x();
  while (world.time() < seconds) world.step();
  return world.positions()[0].x() - x0;
}

TEST(WallContact, PolygonSticksBelowFrictionAngle) {
  // atan(0.5) = 26.6°: at 20° static friction holds; only the tangential spring's elastic
  // set (m g sinθ / k_t ≈ 1e-8 m) may show.
  EXPECT_LT(std::abs(blockDisplacementOnIncline(20, 0.5, 0.2)), 1e-6);
}

TEST(WallContact, PolygonSlidesAboveFrictionAngleWithCoulombAcceleration) {
  const double theta = radians(35), g = 9.81, mu = 0.5, t = 0.2;
  const double expected = 0.5 * g * (std::sin(theta) - mu * std::cos(theta)) * t * t;
  EXPECT_NEAR(blockDisplacementOnIncline(35, mu, t), expected, 0.02 * expected);
}

}  // namespace
}  // namespace grainlab

// Two equal discs head-on: the closed forms of a linear spring-dashpot collision.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/world_helpers.hpp"

namespace grainlab {
namespace {

using test::disc;

struct Collision {
  double reboundSpeed;   // relative speed after separation
  double duration;       // s in contact
  Vec2 v0, v1;           // final velocities
};

Collision collide(double e, double speed) {
  const double r = 0.002, kn = 1e8;
  World world(test::material(kn, e, 0.0));
  world.addParticle(disc(r, {-r - 1e-5, 0}, {speed / 2, 0}));
  world.addParticle(disc(r, {r + 1e-5, 0}, {-speed / 2, 0}));
  world.setTimestep(1e-3 * std::sqrt(world.masses()[0] / 2 / kn));  // resolve the contact finely
  std::vector<ContactRecord> contacts;
  double firstTouch = -1, lastTouch = -1;
  for (int k = 0; k < 200000; ++k) {
    world.step();
    world.contacts(contacts);
    if (!contacts.empty()) {
      if (firstTouch < 0) firstTouch = world.time();
      lastTouch = world.time();
    } else if (firstTouch >= 0) {
      break;
    }
  }
  const auto v = world.velocities();
  return {(v[1] - v[0]).x(), lastTouch - firstTouch + world.timestep(), v[0], v[1]};
}

TEST(BinaryCollision, ElasticExchangesVelocities) {
  const Collision c = collide(1.0, 0.2);
  EXPECT_NEAR(c.v0.x(), -0.1, 0.01 * 0.1);
  EXPECT_NEAR(c.v1.x(), 0.1, 0.01 * 0.1);
  EXPECT_NEAR(c.v0.y(), 0.0, 1e-12);
}

TEST(BinaryCollision, ReboundIsRestitutionTimesApproach) {
  for (double e : {0.9, 0.5, 0.2}) {
    const Collision c = collide(e, 0.2);
    EXPECT_NEAR(c.reboundSpeed, e * 0.2, 0.01 * e * 0.2) << "e = " << e;
  }
}

TEST(BinaryCollision, ContactLastsHalfAPeriod) {
  const double r = 0.002, kn = 1e8;
  const double m = 2650 * kPi * r * r, mEff = m / 2;
  const Collision elastic = collide(1.0, 0.2);
  EXPECT_NEAR(elastic.duration, kPi * std::sqrt(mEff / kn), 0.02 * kPi * std::sqrt(mEff / kn));
  // Damped: half a period of the damped oscillator, π / √(k/m* − (c/2m*)²).
  const double e = 0.5, l = std::log(e), zeta = -l / std::sqrt(kPi * kPi + l * l);
  const double omega = std::sqrt(kn / mEff) * std::sqrt(1 - zeta * zeta);
  EXPECT_NEAR(collide(e, 0.2).duration, kPi / omega, 0.02 * kPi / omega);
}

}  // namespace
}  // namespace grainlab

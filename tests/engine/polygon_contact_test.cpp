// Two overlapping polygons: forces equal and opposite along the face normal, torques from
// the contact point, overlap equal to the geometric one (no Box2D skin).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/world_helpers.hpp"

namespace grainlab {
namespace {

using test::box;

TEST(PolygonContact, FaceContactForceIsOverlapTimesStiffness) {
  const double kn = 1e8, side = 0.004, overlap = 2e-6;
  World world(test::material(kn, 1.0, 0.0));
  world.addParticle(box(side, side, {0, 0}));
  world.addParticle(box(side, side, {side - overlap, 0.001}));  // offset: a partial face contact
  world.setTimestep(1e-12);  // forces at (practically) the initial positions
  world.step();
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  ASSERT_EQ(contacts.size(), 1u);
  const ContactRecord& c = contacts[0];
  EXPECT_NEAR(c.normal.x(), 1.0, 1e-6);
  EXPECT_NEAR(c.normal.y(), 0.0, 1e-6);
  // Box2D works in single precision on shapes scaled to ~1 unit: 1e-6 of the size at most.
  EXPECT_NEAR(c.overlap, overlap, 1e-6 * side);
  EXPECT_NEAR(c.fn, kn * overlap, 1e-6 * side * kn);
  // The contact point is the middle of the shared stretch of face, y in [−0.001, 0.002].
  EXPECT_NEAR(c.point.y(), 0.5 * (-side / 2 + 0.001 + side / 2), 1e-6 * side);
}

TEST(PolygonContact, ForcesEqualOppositeAlongNormalWithTheirTorques) {
  const double kn = 1e8, side = 0.004;
  World world(test::material(kn, 1.0, 0.5));
  world.addParticle(box(side, side * 0.6, {0, 0}, 0.3));
  world.addParticle(box(side, side * 0.8, {0.0035, 0.0012}, -0.2));
  world.setTimestep(1e-12);
  world.step();
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  ASSERT_EQ(contacts.size(), 1u);
  const ContactRecord& c = contacts[0];
  const auto f = world.forces();
  const auto tau = world.torques();
  const auto x = world.positions();
  const double scale = std::max(f[0].norm(), 1e-30);
  EXPECT_GT(c.fn, 0);
  EXPECT_NEAR((f[0] + f[1]).norm(), 0.0, 1e-12 * scale);
  // Frictionless at the first touch (no tangential history yet): along the normal.
  const Vec2 onJ = c.fn * c.normal + c.ft * perp(c.normal);
  EXPECT_NEAR((f[1] - onJ).norm(), 0.0, 1e-9 * scale);
  EXPECT_NEAR(std::abs(cross(f[1].normalized(), c.normal)), 0.0, 1e-6);
  EXPECT_NEAR(tau[1], cross(c.point - x[1], f[1]), 1e-9 * scale * side);
  EXPECT_NEAR(tau[0], cross(c.point - x[0], f[0]), 1e-9 * scale * side);
  // The normal is one polygon's face normal.
  const double a0 = world.angles()[0], a1 = world.angles()[1];
  double best = 1;
  for (double a : {a0, a0 + kPi / 2, a1, a1 + kPi / 2}) {
    best = std::min(best, std::abs(cross(Vec2(std::cos(a), std::sin(a)), c.normal)));
  }
  EXPECT_LT(best, 1e-6);
}

// Face against face with unequal depths, by hand. A is a 4 mm square at the origin (right face
// x = 2 mm, normal +x); B a 2 mm square turned by α = 2 mrad, so the two corners of its left face
// (half-side h = 1 mm) sit at x = cx − h cos α ∓ h sin α, y = −h sin α ± h cos α: both inside A's
// face, the upper one deeper by 2h sin α = 4 µm. With cx putting the lower corner 1 µm deep, the
// depths are 5 µm and 1 µm. The rule (contact_geometry.hpp): overlap = the deeper depth (5 µm,
// not the mean 3 µm nor the shallower 1 µm), point = the depth-weighted mean of the manifold
// points, each midway between its corner and A's face.
TEST(PolygonContact, UnequalDepthsTakeTheDeepestAndTheDepthWeightedPoint) {
  const double kn = 1e8, side = 0.004, h = 0.001, alpha = 0.002, shallow = 1e-6;
  const double cx = side / 2 + h * (std::cos(alpha) - std::sin(alpha)) - shallow;
  World world(test::material(kn, 1.0, 0.0));
  world.addParticle(box(side, side, {0, 0}));
  world.addParticle(box(2 * h, 2 * h, {cx, 0}, alpha));
  world.setTimestep(1e-12);
  world.step();
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  ASSERT_EQ(contacts.size(), 1u);
  const ContactRecord& c = contacts[0];
  const double deep = side / 2 - (cx - h * std::cos(alpha) - h * std::sin(alpha));
  ASSERT_NEAR(deep, 5e-6, 1e-11);  // the construction: 2h sin α = 4 µm less 2hα³/6 = 2.7 pm
  const double yDeep = -h * std::sin(alpha) + h * std::cos(alpha), yShallow = -h * std::sin(alpha) - h * std::cos(alpha);
  EXPECT_NEAR(std::abs(c.normal.x()), 1.0, 1e-6);
  // Box2D's single precision on shapes scaled to ~1 unit: 1e-6 of the size, 4 nm, against the
  // 2 µm between the deepest depth and the mean.
  const double tol = 1e-6 * side;
  EXPECT_NEAR(c.overlap, deep, tol) << "the mean depth would be " << 0.5 * (deep + shallow);
  EXPECT_NEAR(c.fn, kn * deep, tol * kn);
  const double weighted = (deep * yDeep + shallow * yShallow) / (deep + shallow);
  EXPECT_NEAR(c.point.y(), weighted, tol) << "unweighted midpoint " << 0.5 * (yDeep + yShallow);
  const double xMid = (deep * (side / 2 - deep / 2) + shallow * (side / 2 - shallow / 2)) / (deep + shallow);
  EXPECT_NEAR(c.point.x(), xMid, tol);
}

}  // namespace
}  // namespace grainlab

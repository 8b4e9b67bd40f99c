// A clump's area, centroid and polar moment are those of the union of its discs, exactly:
// checked against closed forms (the lens of two equal discs, the parallel-axis theorem) and an
// independent quadrature, on cases where a wrong union (overlap counted twice, a covered
// member counted) would be off by a large amount.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "grainlab/clump.hpp"
#include "grainlab/shape.hpp"

namespace grainlab {
namespace {

// The lens shared by two discs of radius r whose centres are d apart, about its centre (the
// midpoint): area and polar moment by Simpson's rule. Its right half is bounded by the left
// disc's circle, x + d/2 = r cos φ, y = ±r sin φ, for φ from 0 to acos(d/2r): in φ the
// integrands are smooth (trigonometric polynomials), so 4000 intervals leave an error far
// below 1e-12 of the values (in x or y they have a square-root end point Simpson cannot
// resolve).
struct Lens {
  double area = 0, polar = 0;
};
Lens lensBySimpson(double r, double d) {
  const double end = std::acos(d / (2 * r));
  const int n = 4000;
  const double h = end / n;
  Lens lens;
  for (int k = 0; k <= n; ++k) {
    const double phi = k * h;
    const double x = r * std::cos(phi) - 0.5 * d, y = r * std::sin(phi);
    const double dx = r * std::sin(phi);  // |dx/dφ|
    const double weight = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    lens.area += weight * 2 * y * dx;
    lens.polar += weight * (2 * y * x * x + 2 * y * y * y / 3) * dx;
  }
  lens.area *= 2 * h / 3;  // both halves
  lens.polar *= 2 * h / 3;
  return lens;
}

TEST(ClumpMass, OneDiscIsTheDiscBitForBit) {
  const ClumpMember m{{0.3, -0.2}, 0.7};
  Vec2 centroid;
  const Clump c = makeClump(std::span(&m, 1), &centroid);
  EXPECT_EQ(c.area, discArea(0.7));
  EXPECT_EQ(c.polarMoment, 0.5 * discArea(0.7) * 0.7 * 0.7);
  EXPECT_EQ(centroid, Vec2(0.3, -0.2));
  EXPECT_EQ(c.members[0].centre, Vec2::Zero());
  EXPECT_EQ(c.circumradius, 0.7);
  // The general union formula agrees with the disc's.
  const DiscUnionMoments u = discUnionMoments(std::span(&m, 1));
  EXPECT_NEAR(u.area, kPi * 0.49, 1e-15);
  EXPECT_NEAR(u.polarMoment, 0.5 * kPi * 0.49 * 0.49 + kPi * 0.49 * 0.13, 1e-14);
}

TEST(ClumpMass, TwoEqualDiscsLoseTheirLens) {
  const double r = 0.5;
  for (double d : {0.05, 0.3, 0.5, 0.9, 0.99}) {
    const std::vector<ClumpMember> members{{{1.0, 2.0}, r}, {{1.0 + d * 0.6, 2.0 + d * 0.8}, r}};
    Vec2 centroid;
    const Clump c = makeClump(members, &centroid);
    const double lensArea = 2 * r * r * std::acos(d / (2 * r)) - 0.5 * d * std::sqrt(4 * r * r - d * d);
    const Lens lens = lensBySimpson(r, d);
    ASSERT_NEAR(lens.area, lensArea, 1e-12);  // the quadrature is as good as claimed
    const double area = 2 * discArea(r) - lensArea;
    EXPECT_NEAR(c.area, area, 1e-14) << d;
    // Each disc about the midpoint (parallel axis), less the lens counted twice.
    const double polar = 2 * (0.5 * discArea(r) * r * r + discArea(r) * 0.25 * d * d) - lens.polar;
    EXPECT_NEAR(c.polarMoment, polar, 1e-13) << d;
    EXPECT_NEAR(centroid.x(), 1.0 + 0.3 * d, 1e-14);
    EXPECT_NEAR(centroid.y(), 2.0 + 0.4 * d, 1e-14);
    EXPECT_NEAR(c.circumradius, r + 0.5 * d, 1e-14);
  }
}

TEST(ClumpMass, ApartDiscsAddByTheParallelAxisTheorem) {
  const std::vector<ClumpMember> members{{{-1.0, 0.5}, 0.3}, {{2.0, 0.25}, 0.6}};
  const DiscUnionMoments u = discUnionMoments(members);
  const double a1 = discArea(0.3), a2 = discArea(0.6);
  EXPECT_NEAR(u.area, a1 + a2, 1e-14);
  EXPECT_NEAR(u.firstMoment.x(), -a1 + 2 * a2, 1e-14);
  EXPECT_NEAR(u.firstMoment.y(), 0.5 * a1 + 0.25 * a2, 1e-14);
  EXPECT_NEAR(u.polarMoment, 0.5 * a1 * 0.09 + a1 * 1.25 + 0.5 * a2 * 0.36 + a2 * (4 + 0.0625), 1e-13);
  // A rigid clump must be one body.
  EXPECT_THROW(makeClump(members), std::invalid_argument);
}

TEST(ClumpMass, ADiscInsideTheUnionOfTwoOthersAddsNothing) {
  // The small disc lies inside neither big disc alone (0.9 + 0.4 > 1) but inside their
  // union (every point of its circle is within √0.97 of a big centre): its circle is wholly
  // covered by two overlapping intervals.
  const std::vector<ClumpMember> two{{{-0.9, 0}, 1.0}, {{0.9, 0}, 1.0}};
  const std::vector<ClumpMember> three{{{-0.9, 0}, 1.0}, {{0.0, 0.0}, 0.4}, {{0.9, 0}, 1.0}};
  Vec2 c2, c3;
  const Clump a = makeClump(two, &c2), b = makeClump(three, &c3);
  EXPECT_NEAR(b.area, a.area, 1e-14);
  EXPECT_NEAR(b.polarMoment, a.polarMoment, 1e-14);
  EXPECT_NEAR((c3 - c2).norm(), 0, 1e-15);
  // And a member wholly inside one other, and a repeated one.
  const std::vector<ClumpMember> nested{{{-0.9, 0}, 1.0}, {{-0.8, 0.1}, 0.5}, {{0.9, 0}, 1.0}, {{0.9, 0}, 1.0}};
  const Clump n = makeClump(nested);
  EXPECT_NEAR(n.area, a.area, 1e-14);
  EXPECT_NEAR(n.polarMoment, a.polarMoment, 1e-14);
}

TEST(ClumpMass, ThreeDiscsInALineMatchQuadrature) {
  // Three overlapping discs of unequal radii, checked against a midpoint-rule quadrature of
  // the union's indicator on a 4000² grid: the boundary cells are the only error, at most the
  // boundary length × cell size (a few 1e-4 of the area here), bounded below.
  const std::vector<ClumpMember> m{{{0, 0}, 0.5}, {{0.6, 0.1}, 0.4}, {{1.1, -0.05}, 0.45}};
  Vec2 centroid;
  const Clump c = makeClump(m, &centroid);
  const double lo = -0.6, hi = 1.6, ylo = -0.6, yhi = 0.6;
  const int nx = 4000, ny = 2200;
  const double hx = (hi - lo) / nx, hy = (yhi - ylo) / ny;
  double area = 0, sx = 0, sy = 0, sxx = 0;
  for (int i = 0; i < nx; ++i) {
    const double x = lo + (i + 0.5) * hx;
    for (int j = 0; j < ny; ++j) {
      const double y = ylo + (j + 0.5) * hy;
      bool in = false;
      for (const ClumpMember& d : m) in = in || (Vec2(x, y) - d.centre).squaredNorm() <= d.radius * d.radius;
      if (!in) continue;
      area += 1;
      sx += x;
      sy += y;
      sxx += x * x + y * y;
    }
  }
  const double cell = hx * hy;
  area *= cell;
  const Vec2 g(sx * cell / area, sy * cell / area);
  const double polar = sxx * cell - area * g.squaredNorm();
  const double perimeter = 2 * kPi * (0.5 + 0.4 + 0.45);  // more than the union's
  const double areaBound = perimeter * std::max(hx, hy);
  EXPECT_NEAR(c.area, area, areaBound);
  EXPECT_NEAR(centroid.x(), g.x(), areaBound / area * 1.2);
  EXPECT_NEAR(centroid.y(), g.y(), areaBound / area * 1.2);
  EXPECT_NEAR(c.polarMoment, polar, areaBound * 1.2 * 1.2);  // |r| ≤ 1.2 from the centroid
  // Sanity of the scale of the check: overlaps counted twice would be far outside it.
  const double sum = discArea(0.5) + discArea(0.4) + discArea(0.45);
  ASSERT_GT(sum - c.area, 20 * areaBound);
}

TEST(ClumpMass, RefusesBadMembersByName) {
  const std::vector<ClumpMember> zero{{{0, 0}, 0.5}, {{0.5, 0}, 0.0}};
  try {
    makeClump(zero);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("member 1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(makeClump(std::vector<ClumpMember>{}), std::invalid_argument);
}

}  // namespace
}  // namespace grainlab

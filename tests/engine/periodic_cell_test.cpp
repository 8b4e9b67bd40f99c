// The periodic cell's geometry: its area and widths, wrapping into the cell, the true nearest
// image (checked by brute force, also in a strongly tilted cell), and the reduction of a tilted
// basis to an equivalent one.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "grainlab/periodic_cell.hpp"

namespace grainlab {
namespace {

using Mat2 = PeriodicCell::Mat2;

Mat2 edges(double h11, double h12, double h21, double h22) {
  Mat2 h;
  h << h11, h12, h21, h22;
  return h;
}

// The shortest d + h n over |n1|, |n2| <= 40: the reference for the nearest image.
Vec2 bruteForceNearest(const PeriodicCell& cell, const Vec2& d) {
  Vec2 best = d;
  for (int a = -40; a <= 40; ++a) {
    for (int b = -40; b <= 40; ++b) {
      const Vec2 c = d + cell.shift({a, b});
      if (c.squaredNorm() < best.squaredNorm()) best = c;
    }
  }
  return best;
}

TEST(PeriodicCell, AreaAndWidthsOfAParallelogram) {
  // Edges (2, 0) and (1.5, 0.5): area 2 × 0.5 = 1; the distance between two parallel edges is
  // the area over their length.
  const PeriodicCell cell(edges(2, 1.5, 0, 0.5));
  EXPECT_DOUBLE_EQ(cell.area(), 1.0);
  EXPECT_DOUBLE_EQ(cell.width(0), 0.5);                      // edges parallel to (2, 0)
  EXPECT_DOUBLE_EQ(cell.width(1), 1.0 / std::hypot(1.5, 0.5));  // edges parallel to (1.5, 0.5)
}

TEST(PeriodicCell, RefusesADegenerateOrClockwiseCell) {
  EXPECT_THROW(PeriodicCell(edges(1, 2, 1, 2)), std::invalid_argument);   // parallel edges
  EXPECT_THROW(PeriodicCell(edges(0, 1, 1, 0)), std::invalid_argument);   // clockwise
  EXPECT_THROW(PeriodicCell(edges(std::nan(""), 0, 0, 1)), std::invalid_argument);
}

TEST(PeriodicCell, WrapPutsAPointInsideByAWholeShift) {
  const PeriodicCell cell(edges(1.0, 0.7, 0.1, 0.9));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int k = 0; k < 1000; ++k) {
    const Vec2 x(u(rng), u(rng));
    const Vec2 w = cell.wrap(x);
    const Vec2 s = cell.fractional(w);
    EXPECT_GE(s.x(), -1e-12);
    EXPECT_LT(s.x(), 1 + 1e-12);
    EXPECT_GE(s.y(), -1e-12);
    EXPECT_LT(s.y(), 1 + 1e-12);
    // w − x is a lattice vector: whole fractional coordinates.
    const Vec2 n = cell.fractional(w - x);
    EXPECT_NEAR(n.x(), std::round(n.x()), 1e-9);
    EXPECT_NEAR(n.y(), std::round(n.y()), 1e-9);
  }
}

// A cell sheared by 3.7 and 6.2 edge lengths (simple shear γ = 3.7, then a tilt of the other
// edge): rounding the fractional coordinates picks a far image here, the nearest-image search
// must not.
TEST(PeriodicCell, MinimumImageIsTheTrueNearestImageInAStronglyTiltedCell) {
  for (const Mat2& h : {edges(1, 3.7, 0, 1), edges(1, -6.2, 0.05, 0.8), edges(0.5, 4.1, -0.2, 0.4)}) {
    const PeriodicCell cell(h);
    ASSERT_GT(cell.area(), 0);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-3, 3);
    int naiveWrong = 0;
    for (int k = 0; k < 2000; ++k) {
      const Vec2 d(u(rng), u(rng));
      const Vec2 m = cell.minimumImage(d);
      const Vec2 ref = bruteForceNearest(cell, d);
      EXPECT_NEAR(m.norm(), ref.norm(), 1e-12) << "d = " << d.transpose();
      // The image differs from d by a lattice vector.
      const Vec2 n = cell.fractional(m - d);
      EXPECT_NEAR(n.x(), std::round(n.x()), 1e-9);
      EXPECT_NEAR(n.y(), std::round(n.y()), 1e-9);
      // What plain rounding of the fractional coordinates would give.
      const Vec2 s = cell.fractional(d);
      const Vec2 naive = d - cell.shift({static_cast<int>(std::lround(s.x())), static_cast<int>(std::lround(s.y()))});
      if (naive.norm() > ref.norm() + 1e-12) ++naiveWrong;
    }
    EXPECT_GT(naiveWrong, 100) << "the test cell is not tilted enough to tell the two apart";
  }
}

// nearestImage returns at once for a separation shorter than half the smaller width (every
// lattice vector is at least that width long): just inside that bound, in tilted cells and in
// every direction, the separation must be its own nearest image by the brute-force search.
TEST(PeriodicCell, ASeparationUnderHalfTheSmallerWidthIsItsOwnNearestImage) {
  for (const Mat2& h : {edges(1, 3.7, 0, 1), edges(1, -6.2, 0.05, 0.8), edges(0.5, 4.1, -0.2, 0.4), edges(1, 0.5, 0, 1)}) {
    const PeriodicCell cell(h);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> angle(0, 2 * kPi), length(0.95, 0.999999), spread(0, 1);
    for (int k = 0; k < 2000; ++k) {
      const double t = angle(rng), r = 0.5 * cell.minWidth() * length(rng);
      const Vec2 d(r * std::cos(t), r * std::sin(t));
      EXPECT_EQ(cell.nearestImage(d), ImageShift{}) << "d = " << d.transpose();
      EXPECT_GE(bruteForceNearest(cell, d).norm(), d.norm() - 1e-15) << "d = " << d.transpose();
      // Past the bound the search decides: up to the larger width, where a shortcut taken
      // too far would keep a d that has a nearer image.
      const double far = 0.5 * cell.minWidth() + (std::max(cell.width(0), cell.width(1)) - 0.5 * cell.minWidth()) * spread(rng);
      const Vec2 e(far * std::cos(t), far * std::sin(t));
      EXPECT_NEAR(cell.minimumImage(e).norm(), bruteForceNearest(cell, e).norm(), 1e-12) << "e = " << e.transpose();
    }
  }
}

TEST(PeriodicCell, ReduceKeepsTheLatticeAndAreaAndMakesTheBasisNearlyOrthogonal) {
  PeriodicCell cell(edges(1, 3.7, 0, 1));  // simple shear γ = 3.7: LAMMPS would flip xy by 4
  ASSERT_TRUE(cell.needsReduction());
  const PeriodicCell before = cell;
  ASSERT_TRUE(cell.reduce());
  EXPECT_FALSE(cell.needsReduction());
  EXPECT_FALSE(cell.reduce());
  EXPECT_NEAR(cell.area(), before.area(), 1e-15);
  // As LAMMPS's flip: the second edge loses four of the first: tilt 3.7 − 4 = −0.3.
  EXPECT_NEAR(cell.edges()(0, 1), -0.3, 1e-15);
  EXPECT_DOUBLE_EQ(cell.edges()(1, 1), 1.0);
  // Each new edge is a whole combination of the old ones, and the reverse.
  for (int k = 0; k < 2; ++k) {
    const Vec2 a = before.fractional(cell.edges().col(k)), b = cell.fractional(before.edges().col(k));
    EXPECT_NEAR(a.x(), std::round(a.x()), 1e-12);
    EXPECT_NEAR(a.y(), std::round(a.y()), 1e-12);
    EXPECT_NEAR(b.x(), std::round(b.x()), 1e-12);
    EXPECT_NEAR(b.y(), std::round(b.y()), 1e-12);
  }
  EXPECT_GT(cell.minWidth(), before.minWidth());
  // The deformation gradient is not the basis: the remap leaves it alone.
  EXPECT_EQ(cell.deformation(), Mat2::Identity());
}

TEST(PeriodicCell, AdvanceFollowsTheVelocityGradient) {
  PeriodicCell cell(edges(1, 0, 0, 1));
  Mat2 L;
  L << 0, 2, 0, 0;  // simple shear γ̇ = 2 /s
  cell.setVelocityGradient(L);
  for (int k = 0; k < 1000; ++k) cell.advance(1e-3);
  // ḣ = L h with L nilpotent: h(t) = (I + L t) h0 exactly, and Euler steps are exact too.
  EXPECT_NEAR(cell.edges()(0, 1), 2.0, 1e-12);
  EXPECT_NEAR(cell.deformation()(0, 1), 2.0, 1e-12);
  EXPECT_NEAR(cell.area(), 1.0, 1e-12);
  EXPECT_EQ(cell.affineVelocity(Vec2(0, 1)), Vec2(2, 0));
}

}  // namespace
}  // namespace grainlab

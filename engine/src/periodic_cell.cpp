#include "grainlab/periodic_cell.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "grainlab/state_archive.hpp"

namespace grainlab {
namespace {

// The integer nearest to a projection ratio; 0 while |ratio| <= 1/2 (no change at exactly a
// half, so a cell tilted by half an edge stays as it is).
// (0.49)²: a branch shorter than 0.49 of the smaller width is its own nearest image.
constexpr double kShortBranch2 = 0.49 * 0.49;

int nearestMultiple(double ratio) { return std::abs(ratio) > 0.5 ? static_cast<int>(std::lround(ratio)) : 0; }

}  // namespace

PeriodicCell::PeriodicCell(const Mat2& h) : h_(h) {
  if (!h.allFinite() || !(h(0, 0) * h(1, 1) - h(0, 1) * h(1, 0) > 0)) {
    throw std::invalid_argument("the periodic cell's edges must be finite and counter-clockwise with a positive area");
  }
}

double PeriodicCell::width(int k) const { return area() / h_.col(k).norm(); }

Vec2 PeriodicCell::fractional(const Vec2& x) const {
  // h⁻¹ by cofactors: the same rounding wherever it is used.
  const double det = area();
  return {(h_(1, 1) * x.x() - h_(0, 1) * x.y()) / det, (-h_(1, 0) * x.x() + h_(0, 0) * x.y()) / det};
}

ImageShift PeriodicCell::wrapShift(const Vec2& x) const {
  const Vec2 s = fractional(x);
  return {-static_cast<int>(std::floor(s.x())), -static_cast<int>(std::floor(s.y()))};
}

Vec2 PeriodicCell::wrap(const Vec2& x) const {
  const ImageShift n = wrapShift(x);
  return n == ImageShift{} ? x : Vec2(x + shift(n));
}

ImageShift PeriodicCell::nearestImage(const Vec2& d) const {
  // Every lattice vector h n (n ≠ 0) is at least the smaller width w long, so a d shorter than
  // half of it is strictly the nearest of its images: most branch vectors of the stress sums
  // (the cell's servo measures them every few steps) are, and skip the search below. The test
  // takes no root or quotient (w_k = A / |h_k|, so |d| < c w_k is d² |h_k|² < c² A²) and keeps
  // a margin against rounding (c = 0.49).
  const double longest2 = std::max(h_.col(0).squaredNorm(), h_.col(1).squaredNorm());
  const double a = area();
  if (d.squaredNorm() * longest2 < kShortBranch2 * (a * a)) return {};
  // In a reduced basis the nearest lattice point to −d is within one step of the rounded
  // fractional coordinates; in a tilted one it can be many steps away. Reduce a copy (h M),
  // search there, and map the answer back (n = M m).
  PeriodicCell reduced(*this);
  Eigen::Matrix2i M = Eigen::Matrix2i::Identity();
  for (bool changed = true; changed;) {
    changed = false;
    Mat2& b = reduced.h_;
    if (const int k = nearestMultiple(b.col(0).dot(b.col(1)) / b.col(0).squaredNorm())) {
      b.col(1) -= k * b.col(0);
      M.col(1) -= k * M.col(0);
      changed = true;
    }
    if (const int k = nearestMultiple(b.col(0).dot(b.col(1)) / b.col(1).squaredNorm())) {
      b.col(0) -= k * b.col(1);
      M.col(0) -= k * M.col(1);
      changed = true;
    }
  }
  const Vec2 s = reduced.fractional(d);
  const int r1 = -static_cast<int>(std::lround(s.x())), r2 = -static_cast<int>(std::lround(s.y()));
  double best = std::numeric_limits<double>::infinity();
  ImageShift m;
  for (int a = r1 - 1; a <= r1 + 1; ++a) {
    for (int b = r2 - 1; b <= r2 + 1; ++b) {
      const double d2 = (d + reduced.shift({a, b})).squaredNorm();
      if (d2 < best) {
        best = d2;
        m = {a, b};
      }
    }
  }
  return {M(0, 0) * m.n1 + M(0, 1) * m.n2, M(1, 0) * m.n1 + M(1, 1) * m.n2};
}

bool PeriodicCell::needsReduction() const {
  const double dot = h_.col(0).dot(h_.col(1));
  return nearestMultiple(dot / h_.col(0).squaredNorm()) != 0 || nearestMultiple(dot / h_.col(1).squaredNorm()) != 0;
}

bool PeriodicCell::reduce() {
  bool any = false;
  for (bool changed = true; changed;) {
    changed = false;
    if (const int k = nearestMultiple(h_.col(0).dot(h_.col(1)) / h_.col(0).squaredNorm())) {
      h_.col(1) -= k * h_.col(0);
      changed = any = true;
    }
    if (const int k = nearestMultiple(h_.col(0).dot(h_.col(1)) / h_.col(1).squaredNorm())) {
      h_.col(0) -= k * h_.col(1);
      changed = any = true;
    }
  }
  return any;
}

void PeriodicCell::advance(double dt) {
  h_ += (L_ * h_) * dt;
  F_ += (L_ * F_) * dt;
}

void PeriodicCell::persist(StateArchive& a) {
  a.section("periodic cell");
  a.bitwise(h_);
  a.bitwise(L_);
  a.bitwise(F_);
  a.require(h_.allFinite() && area() > 0, "the periodic cell's edges are degenerate");
}

}  // namespace grainlab

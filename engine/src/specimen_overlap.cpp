#include "specimen_overlap.hpp"

#include <algorithm>

namespace grainlab::specimen {
namespace {

// Whether some edge of `a` has all of `b` on or beyond its line. The normal is not
// normalised: only its sign matters, and skipping the square root keeps the test exact
// up to the rounding of the products.
bool edgeSeparates(std::span<const Vec2> a, std::span<const Vec2> b) {
  const std::size_t n = a.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 edge = a[(k + 1) % n] - a[k];
    bool allBeyond = true;
    // For a counter-clockwise polygon the outside of edge k is where cross(edge, p − a_k) < 0.
    for (const Vec2& p : b) {
      if (cross(edge, p - a[k]) > 0) {
        allBeyond = false;
        break;
      }
    }
    if (allBeyond) return true;
  }
  return false;
}

double segmentDistanceSquared(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).squaredNorm();
}

}  // namespace

bool discsOverlap(const Vec2& centreA, double radiusA, const Vec2& centreB, double radiusB) {
  const double reach = radiusA + radiusB;
  return (centreA - centreB).squaredNorm() < reach * reach;
}

bool discPolygonOverlap(const Vec2& centre, double radius, std::span<const Vec2> polygon) {
  const std::size_t n = polygon.size();
  bool inside = true;
  double nearest = INFINITY;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& a = polygon[k];
    const Vec2& b = polygon[(k + 1) % n];
    if (cross(b - a, centre - a) < 0) inside = false;
    nearest = std::min(nearest, segmentDistanceSquared(centre, a, b));
  }
  return inside || nearest < radius * radius;
}

bool polygonsOverlap(std::span<const Vec2> a, std::span<const Vec2> b) {
  return !edgeSeparates(a, b) && !edgeSeparates(b, a);
}

}  // namespace grainlab::specimen

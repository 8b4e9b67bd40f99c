#include "grainlab/shape.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace grainlab {

Polygon makePolygon(std::span<const Vec2> input, Vec2* centroidOffset) {
  const int n = static_cast<int>(input.size());
  if (n < 3 || n > kMaxPolygonVertices) {
    throw std::invalid_argument("a polygon needs 3 to " + std::to_string(kMaxPolygonVertices) +
                                " vertices, got " + std::to_string(n));
  }
  // Order the vertices counter-clockwise about their mean so that any input order works.
  Vec2 mean = Vec2::Zero();
  for (const Vec2& v : input) mean += v;
  mean /= n;
  std::vector<Vec2> v(input.begin(), input.end());
  std::sort(v.begin(), v.end(), [&](const Vec2& a, const Vec2& b) {
    return std::atan2(a.y() - mean.y(), a.x() - mean.x()) < std::atan2(b.y() - mean.y(), b.x() - mean.x());
  });

  double scale = 0;
  for (const Vec2& p : v) scale = std::max(scale, (p - mean).norm());
  if (!(scale > 0) || !std::isfinite(scale)) throw std::invalid_argument("polygon vertices are degenerate");

  // Area and centroid by the shoelace formula, about the mean for accuracy.
  double area2 = 0;
  Vec2 c = Vec2::Zero();
  for (int k = 0; k < n; ++k) {
    const Vec2 a = v[k] - mean, b = v[(k + 1) % n] - mean;
    const double w = cross(a, b);
    // Strict convexity: every turn is to the left by a margin relative to the size.
    const Vec2 e1 = b - a, e2 = v[(k + 2) % n] - v[(k + 1) % n];
    if (cross(e1, e2) <= 1e-9 * scale * scale) {
      throw std::invalid_argument("polygon is not strictly convex (or has repeated vertices)");
    }
    area2 += w;
    c += w * (a + b);
  }
  if (area2 <= 0) throw std::invalid_argument("polygon has no area");
  c /= 3.0 * area2;
  const Vec2 centroid = mean + c;

  Polygon poly;
  poly.count = n;
  poly.area = 0.5 * area2;
  double j = 0;
  for (int k = 0; k < n; ++k) poly.vertices[k] = v[k] - centroid;
  for (int k = 0; k < n; ++k) {
    const Vec2& a = poly.vertices[k];
    const Vec2& b = poly.vertices[(k + 1) % n];
    const double w = cross(a, b);
    // ∫ r² dA of the triangle (origin, a, b).
    j += w * (a.squaredNorm() + a.dot(b) + b.squaredNorm()) / 12.0;
    const Vec2 edge = b - a;
    poly.normals[k] = Vec2(edge.y(), -edge.x()).normalized();
    poly.circumradius = std::max(poly.circumradius, a.norm());
  }
  poly.polarMoment = j;
  if (centroidOffset) *centroidOffset = centroid;
  return poly;
}

}  // namespace grainlab

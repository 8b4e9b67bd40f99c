#include "specimen_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace grainlab::specimen {

std::vector<Vec2> ellipsePolygon(double longAxis, double aspectRatio, int vertexCount) {
  if (vertexCount < 3 || vertexCount > 8) throw std::invalid_argument("ellipsePolygon: 3..8 vertices");
  const int n = vertexCount;
  const double a = 0.5 * longAxis, b = a / aspectRatio;
  std::vector<Vec2> v(static_cast<std::size_t>(n));
  // Compute the upper half once and mirror it, so the symmetries hold bit for bit (cos and
  // sin of 2πk/n are not exactly symmetric in floating point): the long-axis ends are
  // exactly (±a, 0).
  for (int k = 0; 2 * k <= n; ++k) {
    const double t = 2.0 * kPi * k / n;
    Vec2 p(a * std::cos(t), b * std::sin(t));
    if (k == 0) p = Vec2(a, 0);
    if (2 * k == n) p = Vec2(-a, 0);
    if (4 * k == n) p = Vec2(0, b);
    if (n % 2 == 0 && 2 * k > n / 2 && 2 * k < n) {
      // Second quadrant of an even polygon: the mirror of the first (x → −x).
      const Vec2& q = v[static_cast<std::size_t>(n / 2 - k)];
      p = Vec2(-q.x(), q.y());
    }
    v[static_cast<std::size_t>(k)] = p;
    if (k > 0 && 2 * k != n) v[static_cast<std::size_t>(n - k)] = Vec2(p.x(), -p.y());
  }
  return v;
}

std::vector<ClumpMember> lineClump(double longAxis, double aspectRatio, int count) {
  if (count < 1) throw std::invalid_argument("lineClump: at least one disc");
  const double r = 0.5 * longAxis / aspectRatio;
  const double end = 0.5 * longAxis - r;  // the outer centres
  std::vector<ClumpMember> members(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    // Mirrored pairs computed once, so the line is symmetric to the bit about the origin.
    const int mirror = count - 1 - k;
    const double x = k <= mirror ? -end + (count > 1 ? 2 * end * k / (count - 1) : end) : -members[static_cast<std::size_t>(mirror)].centre.x();
    members[static_cast<std::size_t>(k)] = {Vec2(2 * k + 1 == count ? 0.0 : x, 0), r};
  }
  return members;
}

double polygonArea(std::span<const Vec2> vertices) {
  double twice = 0;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    twice += cross(vertices[k], vertices[(k + 1) % vertices.size()]);
  }
  return 0.5 * twice;
}

double polygonMinWidth(std::span<const Vec2> vertices) {
  const std::size_t n = vertices.size();
  double width = INFINITY;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 edge = vertices[(k + 1) % n] - vertices[k];
    const double length = edge.norm();
    double farthest = 0;
    for (const Vec2& p : vertices) farthest = std::max(farthest, std::abs(cross(edge, p - vertices[k])) / length);
    width = std::min(width, farthest);
  }
  return width;
}

double polygonReach(std::span<const Vec2> vertices) {
  double reach = 0;
  for (const Vec2& p : vertices) reach = std::max(reach, p.norm());
  return reach;
}

}  // namespace grainlab::specimen

#pragma once
// Narrow phase: where two shapes touch. Pure functions of the two shapes and their poses.
#include <algorithm>
#include <cmath>

#include "grainlab/math.hpp"
#include "grainlab/shape.hpp"
#include "grainlab/wall.hpp"

namespace grainlab {

/// One contact between two bodies, reduced to a single point.
/// A manifold of two points (face against face) becomes one contact whose overlap is the
/// deeper point's and whose point is the depth-weighted mean: both are continuous as a
/// point's depth goes to zero, so the force never jumps when a face lifts off.
struct ContactGeometry {
  Vec2 normal = Vec2::Zero();  ///< unit, from body A to body B
  Vec2 point = Vec2::Zero();   ///< m, midway between the two surfaces
  double overlap = -1;         ///< m, > 0 when touching
};

/// A touching pair's geometry and the pair's index in the neighbour list.
struct TouchingContact {
  ContactGeometry geometry;
  int pair = 0;
};

/// Up to two manifold points (Box2D's limit) reduced as described above.
struct ManifoldPoints {
  int count = 0;
  Vec2 points[2];
  double depths[2] = {0, 0};
};
inline ContactGeometry reduceManifold(const Vec2& normal, const ManifoldPoints& m) {
  ContactGeometry g;
  double deepest = 0, weight = 0;
  Vec2 point = Vec2::Zero();
  for (int k = 0; k < m.count; ++k) {
    if (m.depths[k] <= 0) continue;
    deepest = std::max(deepest, m.depths[k]);
    weight += m.depths[k];
    point += m.depths[k] * m.points[k];
  }
  if (weight <= 0) return g;
  g.normal = normal;
  g.overlap = deepest;
  g.point = point / weight;
  return g;
}

inline ContactGeometry collideDiscs(const Vec2& xa, double ra, const Vec2& xb, double rb) {
  ContactGeometry g;
  const Vec2 d = xb - xa;
  const double dist2 = d.squaredNorm();
  const double reach = ra + rb;
  if (dist2 >= reach * reach || dist2 == 0.0) return g;
  const double dist = std::sqrt(dist2);
  g.normal = d / dist;
  g.overlap = reach - dist;
  g.point = xa + g.normal * (ra - 0.5 * g.overlap);
  return g;
}

inline ContactGeometry collideDiscWall(const Vec2& x, double r, const Wall& wall) {
  ContactGeometry g;
  const double s = (x - wall.point).dot(wall.normal);
  if (s >= r) return g;
  g.normal = -wall.normal;
  g.overlap = r - s;
  g.point = x - wall.normal * (0.5 * (r + s));
  return g;
}

/// Polygon (body frame `poly`, centre x, rotation cos c and sin s) against a half-plane: the
/// deepest two vertices.
ContactGeometry collidePolygonWall(const Polygon& poly, const Vec2& x, double c, double s, const Wall& wall);

}  // namespace grainlab

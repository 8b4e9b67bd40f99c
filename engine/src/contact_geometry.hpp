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

/// A disc's contact, reduced to what its force needs. The contact point lies on the line of
/// centres, `armI` from i's centre along the normal and `armJ` from j's against it, so a
/// spin moves the point only along the tangent and the normal force exerts no torque: the
/// force needs neither the point nor the lever vectors.
struct DiscContact {
  Vec2 normal = Vec2::Zero();  ///< unit, from disc i to disc j (or into the wall)
  double overlap = -1;         ///< m, > 0 when touching
  double armI = 0;             ///< m, from i's centre to the contact point
  double armJ = 0;             ///< m, from j's centre to the contact point (0 for a wall)
};

/// A touching disc pair's contact and the pair's index in the neighbour list.
struct TouchingDiscs {
  DiscContact contact;
  int pair = 0;
};

/// A touching pair's contact, whatever the shapes, and the pair's index in the neighbour list.
struct TouchingShapes {
  ContactGeometry contact;
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

inline DiscContact touchDiscs(const Vec2& xa, double ra, const Vec2& xb, double rb) {
  DiscContact c;
  const Vec2 d = xb - xa;
  const double dist2 = d.squaredNorm();
  const double reach = ra + rb;
  if (dist2 >= reach * reach || dist2 == 0.0) return c;
  const double dist = std::sqrt(dist2);
  c.normal = d / dist;
  c.overlap = reach - dist;
  c.armI = ra - 0.5 * c.overlap;
  c.armJ = rb - 0.5 * c.overlap;
  return c;
}

inline DiscContact touchDiscWall(const Vec2& x, double r, const Wall& wall) {
  DiscContact c;
  const double s = (x - wall.point).dot(wall.normal);
  if (s >= r) return c;
  c.normal = -wall.normal;
  c.overlap = r - s;
  c.armI = 0.5 * (r + s);
  return c;
}

/// The full geometry of a disc contact: its point is `armI` along the normal from xa.
inline ContactGeometry pointOf(const DiscContact& c, const Vec2& xa) {
  ContactGeometry g;
  if (c.overlap <= 0) return g;
  g.normal = c.normal;
  g.overlap = c.overlap;
  g.point = xa + c.normal * c.armI;
  return g;
}

inline ContactGeometry collideDiscs(const Vec2& xa, double ra, const Vec2& xb, double rb) {
  return pointOf(touchDiscs(xa, ra, xb, rb), xa);
}

inline ContactGeometry collideDiscWall(const Vec2& x, double r, const Wall& wall) {
  return pointOf(touchDiscWall(x, r, wall), x);
}

/// Polygon (body frame `poly`, centre x, rotation cos c and sin s) against a half-plane: the
/// deepest two vertices.
ContactGeometry collidePolygonWall(const Polygon& poly, const Vec2& x, double c, double s, const Wall& wall);

}  // namespace grainlab

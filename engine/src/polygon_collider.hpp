#pragma once
// Polygon-polygon and polygon-disc contacts through Box2D's manifold functions
// (b2CollidePolygons, b2CollidePolygonAndCircle), with its three traps handled:
//  - skin: b2PolygonShape carries b2_polygonRadius (0.01 units) of rounding that would
//    inflate every overlap; we zero m_radius after Set() so the geometry is the true polygon.
//  - scale and precision: Box2D is single precision and tuned for bodies of 0.1-10 units,
//    so shapes are scaled to about one unit, and every pair is collided in a frame centred
//    on its first body (positions differenced in double first), so float rounding is
//    relative to the particle size, not to the specimen's coordinates.
//  - Set() may reorder vertices: we only use the Box2D copy for collisions.
#include <vector>

#include <box2d/b2_polygon_shape.h>

#include "contact_geometry.hpp"

namespace grainlab {

/// Where a body is: centre and the cosine and sine of its angle (computed once per step).
struct Pose {
  Vec2 x;
  double c, s;
};

class PolygonCollider {
 public:
  /// `lengthScale` (1/m) maps metres to Box2D units: choose it so particles are about 1 unit.
  explicit PolygonCollider(double lengthScale) : scale_(lengthScale) {}
  double lengthScale() const { return scale_; }

  /// Registers a polygon's body-frame geometry; returns its shape index.
  int add(const Polygon& poly);

  /// Contact of polygon a with polygon b; normal from a to b.
  ContactGeometry collidePolygons(int a, const Pose& pa, int b, const Pose& pb) const;
  /// Contact of polygon a with a disc of radius rb at xb; normal from the polygon to the disc.
  ContactGeometry collidePolygonDisc(int a, const Pose& pa, const Vec2& xb, double rb) const;

  /// Separating-axis cache for a pair that is apart: an axis is an edge of either polygon
  /// (code = edge + kMaxPolygonVertices × owner, owner 0 for a, 1 for b). Pairs in a packing
  /// stay apart along the same edge for many steps, so one edge test usually settles them
  /// without the full collision.
  bool separatedAlong(int axis, int a, const Pose& pa, int b, const Pose& pb) const;
  /// The edge along which a and b are most apart, or -1 if they overlap.
  int separatingAxis(int a, const Pose& pa, int b, const Pose& pb) const;

 private:
  // Separation of polygon `other` from edge k of polygon `ref`, both in world poses.
  double edgeSeparation(const Polygon& ref, const Pose& pr, int k, const Polygon& other, const Pose& po) const;

  double scale_;
  std::vector<b2PolygonShape> shapes_;
  std::vector<Polygon> polygons_;
};

}  // namespace grainlab

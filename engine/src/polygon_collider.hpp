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

class PolygonCollider {
 public:
  /// `lengthScale` (1/m) maps metres to Box2D units: choose it so particles are about 1 unit.
  explicit PolygonCollider(double lengthScale) : scale_(lengthScale) {}
  double lengthScale() const { return scale_; }

  /// Registers a polygon's body-frame geometry; returns its Box2D shape index.
  int add(const Polygon& poly);

  /// Contact of shape a (pose xa, angle aa) with shape b; normal from a to b.
  ContactGeometry collidePolygons(int a, const Vec2& xa, double aa, int b, const Vec2& xb,
                                  double ab) const;
  /// Contact of polygon a with a disc of radius rb at xb; normal from the polygon to the disc.
  ContactGeometry collidePolygonDisc(int a, const Vec2& xa, double aa, const Vec2& xb,
                                     double rb) const;

 private:
  double scale_;
  std::vector<b2PolygonShape> shapes_;
};

}  // namespace grainlab

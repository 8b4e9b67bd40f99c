#pragma once
// Polygon-polygon and polygon-disc contacts through Box2D's manifold functions
// (b2CollidePolygons, b2CollidePolygonAndCircle), with its traps handled:
//  - skin: b2PolygonShape carries b2_polygonRadius (0.01 units) of rounding that would
//    inflate every overlap. We never use Box2D's depths (see below).
//  - scale and precision: Box2D is single precision and tuned for bodies of 0.1-10 units,
//    so shapes are scaled to about one unit, and every pair is collided in a frame centred
//    on its first body (positions differenced in double first), so float rounding is
//    relative to the particle size, not to the specimen's coordinates.
//  - Set() may reorder vertices: we only use the Box2D copy for collisions.
//
// Features from Box2D, depths in double. Box2D decides whether a pair touches and which
// face is the reference (its separating-axis test, with its own tolerance); the clipping of
// the incident edge against that face, the depths and the points are then done here in
// double precision on the true polygons.
//
// Reuse. Those features change only at discrete events (a face comes into contact, the
// reference face switches), so each pair keeps them and calls Box2D again only once the pair
// has moved, relative to itself, more than a slack; every step still clips and measures the
// kept features afresh, so depths and points move continuously with the bodies.
//  - Touching or nearly touching pairs: Box2D is asked with a speculative margin (faces up to
//    kMarginUnits apart count), and its answer is kept for a relative motion up to that
//    margin, so no contact can begin unseen.
//  - Pairs apart: kept (as apart) while they have moved less than their gap.
// The margin is a tenth of Box2D's own reference-face tolerance (0.1 b2_linearSlop), so a
// feature switch delayed by the cache changes a depth by less than Box2D's own choice does.
#include <atomic>
#include <vector>

#include <box2d/b2_polygon_shape.h>

#include "contact_geometry.hpp"

namespace grainlab {

/// Where a body is: centre and the cosine and sine of its angle (computed once per step).
struct Pose {
  Vec2 x;
  double c, s;
};

/// One pair's features from its last Box2D answer, and the poses they were found at.
struct CachedContact {
  enum class Kind : unsigned char { None, Apart, FaceA, FaceB, VertexDisc };
  Kind kind = Kind::None;  ///< None: nothing cached yet
  int reference = 0;       ///< the reference face (FaceA/B) or the vertex (VertexDisc)
  int incident = 0;        ///< the other polygon's incident edge (polygon pairs)
  double slack = 0;        ///< m: relative motion the features tolerate
  Vec2 offset;             ///< x_B − x_A when found
  double ca = 1, sa = 0, cb = 1, sb = 0;  ///< both rotations when found
};

class PolygonCollider {
 public:
  /// `lengthScale` (1/m) maps metres to Box2D units: choose it so particles are about 1 unit.
  explicit PolygonCollider(double lengthScale) : scale_(lengthScale) {}
  double lengthScale() const { return scale_; }
  /// The speculative margin in Box2D units (see above).
  static constexpr float kMarginUnits = 0.01f * b2_linearSlop;

  /// Registers a polygon's body-frame geometry; returns its shape index.
  int add(const Polygon& poly);

  /// Contact of polygon a with polygon b; normal from a to b. With a cache, Box2D is called
  /// only when the cached answer no longer holds; the answer is the same either way to
  /// within the margin's error bound (tested).
  ContactGeometry collidePolygons(int a, const Pose& pa, int b, const Pose& pb, CachedContact* cache = nullptr) const;
  /// Contact of polygon a with a disc of radius rb at xb; normal from the polygon to the disc.
  ContactGeometry collidePolygonDisc(int a, const Pose& pa, const Vec2& xb, double rb,
                                     CachedContact* cache = nullptr) const;

  /// Box2D calls made so far (manifold refreshes), for the profile.
  long long box2dCalls() const { return calls_.load(std::memory_order_relaxed); }

 private:
  // Cached features measured at the given poses, without asking Box2D: polygon a with
  // polygon b, or (b < 0) with a disc of radius rb centred at pb.x.
  ContactGeometry evaluate(const CachedContact& cache, int a, const Pose& pa, int b, const Pose& pb, double rb) const;
  bool stillHolds(const CachedContact& cache, double ra, const Pose& pa, double rb, const Pose& pb) const;
  void anchor(CachedContact& cache, const Pose& pa, const Pose& pb) const;
  // The widest gap between a and b along an edge normal of either (<= 0 if they overlap).
  double gap(int a, const Pose& pa, int b, const Pose& pb) const;

  double scale_;
  std::vector<b2PolygonShape> shapes_;
  std::vector<Polygon> polygons_;
  mutable std::atomic<long long> calls_{0};  // a statistic: counted, never read by the physics
};

}  // namespace grainlab

#pragma once
// Polygon-polygon and polygon-disc contacts, in double precision, for the DEM loop.
//
// Two parts with different costs:
//  - Features (polygon_features.hpp): which face is the reference, which edge is incident,
//    or that the pair is apart. A separating-axis test over every face of both polygons;
//    it makes Box2D's decisions without Box2D's float rounding or skin.
//  - Measurement (here, inline): the kept features clipped and measured every step, so
//    depths and points move continuously with the bodies.
//
// Features change only at discrete events (a face comes into contact, the reference face
// switches), so each pair keeps them with the poses they were found at, and searches again
// only once the pair has moved, relative to itself, more than a slack:
//  - Touching or nearly touching pairs: features are found with a speculative margin (faces up
//    to 2 × margin apart count) and kept for a relative motion up to the margin, so no contact
//    can begin unseen. The wide path, which measures kept features every step, keeps them
//    until a face or edge choice could change, in reach or not (SlackGuards).
//  - Pairs apart: kept while they move less than their separation beyond the margin; then
//    the separating face found last time is tried first (a few dot products), and only if it
//    no longer separates are all faces searched.
// The margin is a tenth of Box2D's own reference-face tolerance, so a feature switch delayed
// by the cache changes a depth by less than Box2D's own choice of face does.
#include <atomic>
#include <vector>

#include "contact_geometry.hpp"
#include "polygon_features.hpp"

namespace grainlab {

class PolygonCollider {
 public:
  /// `lengthScale` (1/m) maps metres to the units in which Box2D's tolerances are taken:
  /// choose it so that particles are about 1 unit.
  explicit PolygonCollider(double lengthScale)
      : scale_(lengthScale), tolerances_(FeatureTolerances::atScale(lengthScale)) {}
  double lengthScale() const { return scale_; }
  const FeatureTolerances& tolerances() const { return tolerances_; }

  /// Registers a polygon's body-frame geometry; returns its shape index.
  int add(const Polygon& poly);
  const Polygon& polygon(int k) const { return polygons_[static_cast<size_t>(k)]; }

  /// Contact of polygon a with polygon b; normal from a to b. With a cache, the features are
  /// searched only when the kept ones no longer hold; the answer is the same either way to
  /// within the margin's error bound (tested).
  ContactGeometry collidePolygons(int a, const Pose& pa, int b, const Pose& pb, CachedContact* cache = nullptr) const {
    CachedContact fresh;
    CachedContact& k = cache ? *cache : fresh;
    if (!cache || !stillHolds(k, pa, pb)) refreshPolygons(a, pa, b, pb, k);
    return measurePolygons(k, a, pa, b, pb);
  }
  /// Contact of polygon a with a disc of radius rb at xb; normal from the polygon to the disc.
  /// The wide path's features guard their choices only (SlackGuards), as its face pairs' do.
  ContactGeometry collidePolygonDisc(int a, const Pose& pa, const Vec2& xb, double rb, CachedContact* cache = nullptr,
                                     SlackGuards guards = SlackGuards::EveryDecision) const {
    CachedContact fresh;
    CachedContact& k = cache ? *cache : fresh;
    const Pose pb{xb, 1.0, 0.0};
    if (!cache || !stillHolds(k, pa, pb)) refreshDisc(a, pa, xb, rb, k, guards);
    return measureDisc(k, a, pa, xb, rb);
  }

  /// The wide path (polygon_face_batch.hpp): keeps the pair's features or searches again, as
  /// collidePolygons does, without measuring them; true if they are a face against an edge,
  /// which the face kernel measures (to measurePolygons' bits). Otherwise they do not touch.
  /// Its slack guards the feature choices only (SlackGuards): the face kernel measures the
  /// kept features every step, and a pair gone out of reach measures no overlap.
  bool keepPolygonFeatures(int a, const Pose& pa, int b, const Pose& pb, CachedContact& k) const {
    if (!stillHolds(k, pa, pb)) refreshPolygons(a, pa, b, pb, k, SlackGuards::FeatureChoices);
    return k.kind == CachedContact::Kind::FaceA || k.kind == CachedContact::Kind::FaceB;
  }
  /// The face kernel's shape tables (polygon_face_kernel.hpp), a record per corner
  /// (polygon × kMaxPolygonVertices + corner): each face's n_x n_y lo hi front, each edge's
  /// two ends.
  const double* faceTable() const { return faceTable_.data(); }
  const double* edgeTable() const { return edgeTable_.data(); }

  /// Full feature searches so far (the rest of the pair-steps reused their features), for
  /// the profile.
  long long featureSearches() const { return searches_.load(std::memory_order_relaxed); }
  /// Continues the count from a checkpoint.
  void setFeatureSearches(long long n) { searches_.store(n, std::memory_order_relaxed); }

 private:
  // A face's span and height in its polygon's body frame: t·v1, t·v2 and n·v1, with t the
  // face's direction (counter-clockwise) and n its outward normal.
  struct FaceSpan {
    double lo, hi, front;
  };

  static bool stillHolds(const CachedContact& k, const Pose& pa, const Pose& pb) {
    return k.kind != CachedContact::Kind::None && relativeMotion(k, pa, pb) < k.slack;
  }
  static void anchor(CachedContact& k, const Pose& pa, double ra, const Pose& pb, double rb) {
    k.offset = pb.x - pa.x;
    k.lever = std::abs(k.offset.x()) + std::abs(k.offset.y()) + ra + rb;
    k.ca = pa.c;
    k.sa = pa.s;
    k.cb = pb.c;
    k.sb = pb.s;
  }
  // Out of line: the rare path.
  void refreshPolygons(int a, const Pose& pa, int b, const Pose& pb, CachedContact& k,
                       SlackGuards guards = SlackGuards::EveryDecision) const;
  void refreshDisc(int a, const Pose& pa, const Vec2& xb, double rb, CachedContact& k, SlackGuards guards) const;

  // The kept features measured at the given poses.
  ContactGeometry measurePolygons(const CachedContact& k, int a, const Pose& pa, int b, const Pose& pb) const;
  ContactGeometry measureDisc(const CachedContact& k, int a, const Pose& pa, const Vec2& xb, double rb) const;

  double scale_;
  FeatureTolerances tolerances_;
  std::vector<Polygon> polygons_;
  std::vector<PolygonFeatureTable> featureTables_;  // the feature search's view of each polygon
  std::vector<FaceSpan> spans_;  // kMaxPolygonVertices per polygon
  std::vector<double> faceTable_, edgeTable_;
  mutable std::atomic<long long> searches_{0};  // a statistic: counted, never read by the physics
};

// Face against edge: the incident edge, in the reference polygon's frame, clipped to the
// face's span; each end's depth below the face; reduced to one contact as reduceManifold
// does (overlap the deeper depth, point the depth-weighted mean of the two ends' midpoints
// between the surfaces). Box2D's clipping, in double, in about half the operations of doing
// it in the world frame: the face's span and height are body-frame constants.
inline ContactGeometry PolygonCollider::measurePolygons(const CachedContact& k, int a, const Pose& pa, int b,
                                                        const Pose& pb) const {
  using Kind = CachedContact::Kind;
  if (k.kind != Kind::FaceA && k.kind != Kind::FaceB) return {};
  const bool faceA = k.kind == Kind::FaceA;
  const int r = faceA ? a : b;
  const Polygon& R = polygon(r);
  const Polygon& I = polygon(faceA ? b : a);
  const Pose& pr = faceA ? pa : pb;
  const Pose& pi = faceA ? pb : pa;
  const FaceSpan& span = spans_[static_cast<size_t>(r) * kMaxPolygonVertices + static_cast<size_t>(k.reference)];
  // The incident polygon seen from the reference one: u ↦ d + R u.
  const Vec2 dx = pi.x - pr.x;
  const double dX = pr.c * dx.x() + pr.s * dx.y(), dY = -pr.s * dx.x() + pr.c * dx.y();
  const double c = pr.c * pi.c + pr.s * pi.s, s = pr.c * pi.s - pr.s * pi.c;
  const Vec2& u0 = I.vertices[k.incident];
  const Vec2& u1 = I.vertices[k.incident + 1 < I.count ? k.incident + 1 : 0];
  const double x0 = dX + c * u0.x() - s * u0.y(), y0 = dY + s * u0.x() + c * u0.y();
  const double x1 = dX + c * u1.x() - s * u1.y(), y1 = dY + s * u1.x() + c * u1.y();
  const Vec2& n = R.normals[k.reference];  // t = perp(n) = (−n_y, n_x)
  const double s0 = n.x() * y0 - n.y() * x0, s1 = n.x() * y1 - n.y() * x1;  // along the face
  const double h0 = n.x() * x0 + n.y() * y0, h1 = n.x() * x1 + n.y() * y1;  // above its line
  // The incident edge runs against the face (s1 < s0); if it has slid past the face's span,
  // the features no longer touch.
  if (!(s1 < s0) || s0 <= span.lo || s1 >= span.hi) return {};
  // Each clipped end's depth, times the edge's extent along the face D = s0 − s1 > 0, so that
  // one division serves both the clipping and the weighted mean.
  const double D = s0 - s1, rise = h1 - h0;
  const double sa = std::min(s0, span.hi), sb = std::max(s1, span.lo);
  const double Da = D * (span.front - h0) + (sa - s0) * rise, Db = D * (span.front - h0) + (sb - s0) * rise;
  const double wa = Da > 0 ? Da : 0, wb = Db > 0 ? Db : 0, weight = wa + wb;
  if (weight <= 0) return {};
  const double q = 1 / (D * weight);
  // The point midway between the surfaces at each end is (s, front − d/2) in the face's (t, n).
  const double ps = (wa * sa + wb * sb) * (D * q), ph = span.front - 0.5 * (wa * Da + wb * Db) * q;
  const double lx = ps * -n.y() + ph * n.x(), ly = ps * n.x() + ph * n.y();
  ContactGeometry g;
  g.point = Vec2(pr.x.x() + pr.c * lx - pr.s * ly, pr.x.y() + pr.s * lx + pr.c * ly);
  const Vec2 normal(pr.c * n.x() - pr.s * n.y(), pr.s * n.x() + pr.c * n.y());
  g.normal = faceA ? normal : Vec2(-normal);
  g.overlap = std::max(Da, Db) * (weight * q);
  return g;
}

inline ContactGeometry PolygonCollider::measureDisc(const CachedContact& k, int a, const Pose& pa, const Vec2& xb,
                                                    double rb) const {
  using Kind = CachedContact::Kind;
  const Polygon& A = polygon(a);
  ContactGeometry g;
  if (k.kind == Kind::VertexDisc) {
    const Vec2& u = A.vertices[k.reference];
    const Vec2 vertex(pa.x.x() + pa.c * u.x() - pa.s * u.y(), pa.x.y() + pa.s * u.x() + pa.c * u.y());
    const Vec2 d = xb - vertex;
    const double dist = d.norm();
    if (dist == 0 || dist >= rb) return g;
    g.normal = d / dist;
    g.overlap = rb - dist;
    g.point = vertex + (0.5 * (dist - rb)) * g.normal;
  } else if (k.kind == Kind::FaceA) {
    // The disc's centre below the face: depth rb − (n·(x_b − x_a) − front).
    const FaceSpan& span = spans_[static_cast<size_t>(a) * kMaxPolygonVertices + static_cast<size_t>(k.reference)];
    const Vec2& m = A.normals[k.reference];
    const Vec2 n(pa.c * m.x() - pa.s * m.y(), pa.s * m.x() + pa.c * m.y());
    const double depth = rb - (n.dot(xb - pa.x) - span.front);
    if (depth <= 0) return g;
    g.normal = n;
    g.overlap = depth;
    g.point = xb + (0.5 * depth - rb) * n;
  }
  return g;
}

}  // namespace grainlab

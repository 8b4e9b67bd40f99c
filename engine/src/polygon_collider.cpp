#include "polygon_collider.hpp"

#include "polygon_face_kernel.hpp"

namespace grainlab {

int PolygonCollider::add(const Polygon& poly) {
  polygons_.push_back(poly);
  featureTables_.push_back(PolygonFeatureTable::of(poly));
  for (int e = 0; e < kMaxPolygonVertices; ++e) {
    FaceSpan span{0, 0, 0};
    if (e < poly.count) {
      const Vec2& n = poly.normals[e];
      const Vec2 t = perp(n);
      span = {t.dot(poly.vertices[e]), t.dot(poly.vertices[(e + 1) % poly.count]), n.dot(poly.vertices[e])};
    }
    spans_.push_back(span);
    const Vec2 n = e < poly.count ? poly.normals[e] : Vec2::Zero();
    const Vec2 u0 = e < poly.count ? poly.vertices[e] : Vec2::Zero();
    const Vec2 u1 = e < poly.count ? poly.vertices[(e + 1) % poly.count] : Vec2::Zero();
    const double face[kFaceRecord] = {n.x(), n.y(), span.lo, span.hi, span.front};
    const double edge[kEdgeRecord] = {u0.x(), u0.y(), u1.x(), u1.y()};
    faceTable_.insert(faceTable_.end(), face, face + kFaceRecord);
    edgeTable_.insert(edgeTable_.end(), edge, edge + kEdgeRecord);
  }
  return static_cast<int>(polygons_.size()) - 1;
}

void PolygonCollider::refreshPolygons(int a, const Pose& pa, int b, const Pose& pb, CachedContact& k,
                                      SlackGuards guards) const {
  const PolygonFeatureTable& ta = featureTables_[static_cast<size_t>(a)];
  const PolygonFeatureTable& tb = featureTables_[static_cast<size_t>(b)];
  if (k.kind == CachedContact::Kind::Apart) {
    // The face that separated the pair last time usually still does.
    const double reach = 2 * tolerances_.margin;
    if (const double separation = separationAlongAxis(ta, pa, tb, pb, k); separation > reach) {
      k.slack = separation - reach;
      anchor(k, pa, ta.circumradius, pb, tb.circumradius);
      return;
    }
  }
  findPolygonFeatures(ta, pa, tb, pb, tolerances_, k, guards);
  searches_.fetch_add(1, std::memory_order_relaxed);
  anchor(k, pa, ta.circumradius, pb, tb.circumradius);
}

void PolygonCollider::refreshDisc(int a, const Pose& pa, const Vec2& xb, double rb, CachedContact& k,
                                  SlackGuards guards) const {
  findDiscFeatures(polygon(a), pa, xb, rb, tolerances_, k, guards);
  searches_.fetch_add(1, std::memory_order_relaxed);
  anchor(k, pa, polygon(a).circumradius, Pose{xb, 1.0, 0.0}, 0.0);
}

}  // namespace grainlab

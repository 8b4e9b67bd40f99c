#include "polygon_collider.hpp"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>

#include <stdexcept>

namespace grainlab {
namespace {

b2Rot rotation(const Pose& p) {
  b2Rot r;
  r.s = static_cast<float>(p.s);
  r.c = static_cast<float>(p.c);
  return r;
}

// Both bodies' transforms in a frame whose origin is body A's centre.
void relativeTransforms(const Pose& pa, const Pose& pb, double scale, b2Transform& ta, b2Transform& tb) {
  ta.p.SetZero();
  ta.q = rotation(pa);
  const Vec2 d = (pb.x - pa.x) * scale;
  tb.p.Set(static_cast<float>(d.x()), static_cast<float>(d.y()));
  tb.q = rotation(pb);
}

ContactGeometry fromManifold(const b2Manifold& m, const b2Transform& ta, float ra,
                             const b2Transform& tb, float rb, const Vec2& origin, double scale) {
  if (m.pointCount == 0) return {};
  b2WorldManifold wm;
  wm.Initialize(&m, ta, ra, tb, rb);
  ManifoldPoints points;
  const double inv = 1.0 / scale;
  for (int k = 0; k < m.pointCount; ++k) {
    points.points[k] = origin + Vec2(wm.points[k].x, wm.points[k].y) * inv;
    points.depths[k] = -static_cast<double>(wm.separations[k]) * inv;
  }
  points.count = m.pointCount;
  return reduceManifold(Vec2(wm.normal.x, wm.normal.y).normalized(), points);
}

}  // namespace

int PolygonCollider::add(const Polygon& poly) {
  b2Vec2 v[b2_maxPolygonVertices];
  for (int k = 0; k < poly.count; ++k) {
    v[k].Set(static_cast<float>(poly.vertices[k].x() * scale_),
             static_cast<float>(poly.vertices[k].y() * scale_));
  }
  b2PolygonShape shape;
  shape.Set(v, poly.count);
  if (shape.m_count != poly.count) {
    throw std::invalid_argument("polygon has vertices too close together for the collision geometry");
  }
  shape.m_radius = 0.0f;  // no skin: contacts see the true polygon
  shapes_.push_back(shape);
  polygons_.push_back(poly);
  return static_cast<int>(shapes_.size()) - 1;
}

ContactGeometry PolygonCollider::collidePolygons(int a, const Pose& pa, int b, const Pose& pb) const {
  b2Transform ta, tb;
  relativeTransforms(pa, pb, scale_, ta, tb);
  b2Manifold m;
  b2CollidePolygons(&m, &shapes_[static_cast<size_t>(a)], ta, &shapes_[static_cast<size_t>(b)], tb);
  return fromManifold(m, ta, 0.0f, tb, 0.0f, pa.x, scale_);
}

ContactGeometry PolygonCollider::collidePolygonDisc(int a, const Pose& pa, const Vec2& xb, double rb) const {
  b2Transform ta, tb;
  relativeTransforms(pa, Pose{xb, 1.0, 0.0}, scale_, ta, tb);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(rb * scale_);
  circle.m_p.SetZero();
  b2Manifold m;
  b2CollidePolygonAndCircle(&m, &shapes_[static_cast<size_t>(a)], ta, &circle, tb);
  return fromManifold(m, ta, 0.0f, tb, circle.m_radius, pa.x, scale_);
}

double PolygonCollider::edgeSeparation(const Polygon& ref, const Pose& pr, int k, const Polygon& other,
                                       const Pose& po) const {
  // Work in ref's body frame: other's vertices are d + R w with d = Rrᵀ(xo − xr), R = Rrᵀ Ro.
  const Vec2 dx = po.x - pr.x;
  const Vec2 d(pr.c * dx.x() + pr.s * dx.y(), -pr.s * dx.x() + pr.c * dx.y());
  const double c = pr.c * po.c + pr.s * po.s, s = pr.c * po.s - pr.s * po.c;
  const Vec2& n = ref.normals[k];
  const double offset = n.dot(ref.vertices[k]);
  double least = 1e300;
  for (int v = 0; v < other.count; ++v) {
    const Vec2& w = other.vertices[v];
    const Vec2 q(d.x() + c * w.x() - s * w.y(), d.y() + s * w.x() + c * w.y());
    least = std::min(least, n.dot(q) - offset);
  }
  return least;
}

bool PolygonCollider::separatedAlong(int axis, int a, const Pose& pa, int b, const Pose& pb) const {
  const int edge = axis % kMaxPolygonVertices;
  const Polygon& A = polygons_[static_cast<size_t>(a)];
  const Polygon& B = polygons_[static_cast<size_t>(b)];
  return axis < kMaxPolygonVertices ? edgeSeparation(A, pa, edge, B, pb) > 0 : edgeSeparation(B, pb, edge, A, pa) > 0;
}

int PolygonCollider::separatingAxis(int a, const Pose& pa, int b, const Pose& pb) const {
  const Polygon& A = polygons_[static_cast<size_t>(a)];
  const Polygon& B = polygons_[static_cast<size_t>(b)];
  int best = -1;
  double widest = 0;
  for (int k = 0; k < A.count; ++k) {
    const double sep = edgeSeparation(A, pa, k, B, pb);
    if (sep > widest) { widest = sep; best = k; }
  }
  for (int k = 0; k < B.count; ++k) {
    const double sep = edgeSeparation(B, pb, k, A, pa);
    if (sep > widest) { widest = sep; best = k + kMaxPolygonVertices; }
  }
  return best;
}

}  // namespace grainlab

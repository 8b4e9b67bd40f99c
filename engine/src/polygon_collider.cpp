#include "polygon_collider.hpp"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>

#include <stdexcept>

namespace grainlab {
namespace {

b2Rot rotation(double angle) {
  b2Rot r;
  r.s = static_cast<float>(std::sin(angle));
  r.c = static_cast<float>(std::cos(angle));
  return r;
}

// Both bodies' transforms in a frame whose origin is body A's centre.
void relativeTransforms(const Vec2& xa, double aa, const Vec2& xb, double ab, double scale,
                        b2Transform& ta, b2Transform& tb) {
  ta.p.SetZero();
  ta.q = rotation(aa);
  const Vec2 d = (xb - xa) * scale;
  tb.p.Set(static_cast<float>(d.x()), static_cast<float>(d.y()));
  tb.q = rotation(ab);
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
  return static_cast<int>(shapes_.size()) - 1;
}

ContactGeometry PolygonCollider::collidePolygons(int a, const Vec2& xa, double aa, int b,
                                                 const Vec2& xb, double ab) const {
  b2Transform ta, tb;
  relativeTransforms(xa, aa, xb, ab, scale_, ta, tb);
  b2Manifold m;
  b2CollidePolygons(&m, &shapes_[static_cast<size_t>(a)], ta, &shapes_[static_cast<size_t>(b)], tb);
  return fromManifold(m, ta, 0.0f, tb, 0.0f, xa, scale_);
}

ContactGeometry PolygonCollider::collidePolygonDisc(int a, const Vec2& xa, double aa,
                                                    const Vec2& xb, double rb) const {
  b2Transform ta, tb;
  relativeTransforms(xa, aa, xb, 0.0, scale_, ta, tb);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(rb * scale_);
  circle.m_p.SetZero();
  b2Manifold m;
  b2CollidePolygonAndCircle(&m, &shapes_[static_cast<size_t>(a)], ta, &circle, tb);
  return fromManifold(m, ta, 0.0f, tb, circle.m_radius, xa, scale_);
}

}  // namespace grainlab

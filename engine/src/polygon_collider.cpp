#include "polygon_collider.hpp"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>

#include <algorithm>
#include <cmath>
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

Vec2 toWorld(const Pose& p, const Vec2& local) {
  return Vec2(p.x.x() + p.c * local.x() - p.s * local.y(), p.x.y() + p.s * local.x() + p.c * local.y());
}
Vec2 turn(const Pose& p, const Vec2& local) {
  return Vec2(p.c * local.x() - p.s * local.y(), p.s * local.x() + p.c * local.y());
}

// The polygon's own face whose normal is nearest Box2D's (float) reference normal: Box2D's
// Set() may have reordered the vertices, so its edge index is not ours.
int faceAlong(const Polygon& poly, const b2Vec2& boxNormal) {
  const Vec2 n(boxNormal.x, boxNormal.y);
  int best = 0;
  for (int e = 1; e < poly.count; ++e) {
    if (poly.normals[e].dot(n) > poly.normals[best].dot(n)) best = e;
  }
  return best;
}

// The incident polygon's edge most anti-parallel to the reference normal (world frame), as
// Box2D's b2FindIncidentEdge picks it.
int incidentEdge(const Polygon& inc, const Pose& pose, const Vec2& referenceNormal) {
  int best = 0;
  double least = 1e300;
  for (int e = 0; e < inc.count; ++e) {
    const double d = turn(pose, inc.normals[e]).dot(referenceNormal);
    if (d < least) { least = d; best = e; }
  }
  return best;
}

int nearestVertex(const Polygon& poly, const Vec2& p) {
  int best = 0;
  for (int k = 1; k < poly.count; ++k) {
    if ((poly.vertices[k] - p).squaredNorm() < (poly.vertices[best] - p).squaredNorm()) best = k;
  }
  return best;
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
  // Box2D's radius only widens which points the manifold keeps (the speculative margin);
  // depths are computed here on the true polygon, so no skin enters a force.
  shape.m_radius = kMarginUnits;
  shapes_.push_back(shape);
  polygons_.push_back(poly);
  return static_cast<int>(shapes_.size()) - 1;
}

bool PolygonCollider::stillHolds(const CachedContact& k, double ra, const Pose& pa, double rb, const Pose& pb) const {
  if (k.kind == CachedContact::Kind::None) return false;
  // Upper bound on how far any point of B has moved relative to A (|v|₁ ≥ |v|₂; a turn by
  // Δθ moves a point at radius r by the chord r·|(c, s) − (c0, s0)|).
  const Vec2 d = (pb.x - pa.x) - k.offset;
  const double motion = std::abs(d.x()) + std::abs(d.y()) + ra * (std::abs(pa.c - k.ca) + std::abs(pa.s - k.sa)) +
                        rb * (std::abs(pb.c - k.cb) + std::abs(pb.s - k.sb));
  return motion < k.slack;
}

void PolygonCollider::anchor(CachedContact& k, const Pose& pa, const Pose& pb) const {
  k.offset = pb.x - pa.x;
  k.ca = pa.c;
  k.sa = pa.s;
  k.cb = pb.c;
  k.sb = pb.s;
}

ContactGeometry PolygonCollider::evaluate(const CachedContact& k, int a, const Pose& pa, int b, const Pose& pb,
                                          double rb) const {
  using Kind = CachedContact::Kind;
  const Polygon& A = polygons_[static_cast<size_t>(a)];
  ManifoldPoints m;
  Vec2 normal;
  switch (k.kind) {
    case Kind::None:
    case Kind::Apart:
      return {};
    case Kind::VertexDisc: {
      const Vec2 vertex = toWorld(pa, A.vertices[k.reference]);
      const Vec2 d = pb.x - vertex;
      const double dist = d.norm();
      if (dist == 0) return {};
      normal = d / dist;
      m.count = 1;
      m.depths[0] = rb - dist;
      m.points[0] = vertex + (0.5 * (dist - rb)) * normal;
      break;
    }
    case Kind::FaceA:
    case Kind::FaceB: {
      const bool faceA = k.kind == Kind::FaceA;
      const Polygon& R = faceA ? A : polygons_[static_cast<size_t>(b)];
      const Pose& pr = faceA ? pa : pb;
      const Pose& pi = faceA ? pb : pa;
      const Vec2 n = turn(pr, R.normals[k.reference]);
      const Vec2 v1 = toWorld(pr, R.vertices[k.reference]);
      const Vec2 v2 = toWorld(pr, R.vertices[(k.reference + 1) % R.count]);
      normal = faceA ? n : Vec2(-n);
      if (b < 0) {  // a disc against face A: its centre's depth below the face
        m.count = 1;
        m.depths[0] = rb - (pb.x - v1).dot(n);
        m.points[0] = pb.x + (0.5 * m.depths[0] - rb) * n;
        break;
      }
      // Box2D's clipping, in double: the incident edge cut to the reference face's span.
      const Polygon& I = faceA ? polygons_[static_cast<size_t>(b)] : A;
      Vec2 w[2] = {toWorld(pi, I.vertices[k.incident]), toWorld(pi, I.vertices[(k.incident + 1) % I.count])};
      const Vec2 t = perp(n);  // along the face, from v1 to v2 (counter-clockwise polygon)
      const double lo = t.dot(v1), hi = t.dot(v2);
      const double s0 = t.dot(w[0]), s1 = t.dot(w[1]);
      // The incident edge runs against the face (s1 < s0); if it has slid past the face's
      // span, the features no longer touch.
      if (!(s1 < s0) || s0 <= lo || s1 >= hi) return {};
      const Vec2 w0 = w[0], edge = w[1] - w[0];
      w[0] = w0 + edge * ((std::min(s0, hi) - s0) / (s1 - s0));
      w[1] = w0 + edge * ((std::max(s1, lo) - s0) / (s1 - s0));
      for (int q = 0; q < 2; ++q) {
        m.depths[q] = n.dot(v1 - w[q]);
        m.points[q] = w[q] + (0.5 * m.depths[q]) * n;
      }
      m.count = 2;
      break;
    }
  }
  return reduceManifold(normal, m);
}

ContactGeometry PolygonCollider::collidePolygons(int a, const Pose& pa, int b, const Pose& pb, CachedContact* cache) const {
  const Polygon& A = polygons_[static_cast<size_t>(a)];
  const Polygon& B = polygons_[static_cast<size_t>(b)];
  CachedContact local;
  CachedContact& k = cache ? *cache : local;
  if (cache && stillHolds(k, A.circumradius, pa, B.circumradius, pb)) return evaluate(k, a, pa, b, pb, 0.0);

  b2Transform ta, tb;
  relativeTransforms(pa, pb, scale_, ta, tb);
  b2Manifold manifold;
  b2CollidePolygons(&manifold, &shapes_[static_cast<size_t>(a)], ta, &shapes_[static_cast<size_t>(b)], tb);
  calls_.fetch_add(1, std::memory_order_relaxed);
  anchor(k, pa, pb);
  if (manifold.pointCount == 0) {
    // Apart (or a degenerate clip): reusable while the pair moves less than its gap.
    k.kind = CachedContact::Kind::Apart;
    k.slack = std::max(0.0, gap(a, pa, b, pb));
    return {};
  }
  const bool faceA = manifold.type == b2Manifold::e_faceA;
  k.kind = faceA ? CachedContact::Kind::FaceA : CachedContact::Kind::FaceB;
  k.reference = faceAlong(faceA ? A : B, manifold.localNormal);
  const Pose& pr = faceA ? pa : pb;
  k.incident = incidentEdge(faceA ? B : A, faceA ? pb : pa, turn(pr, (faceA ? A : B).normals[k.reference]));
  k.slack = kMarginUnits / scale_;
  return evaluate(k, a, pa, b, pb, 0.0);
}

ContactGeometry PolygonCollider::collidePolygonDisc(int a, const Pose& pa, const Vec2& xb, double rb,
                                                    CachedContact* cache) const {
  const Polygon& A = polygons_[static_cast<size_t>(a)];
  const Pose pb{xb, 1.0, 0.0};
  CachedContact local;
  CachedContact& k = cache ? *cache : local;
  if (cache && stillHolds(k, A.circumradius, pa, 0.0, pb)) return evaluate(k, a, pa, -1, pb, rb);

  b2Transform ta, tb;
  relativeTransforms(pa, pb, scale_, ta, tb);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(rb * scale_);
  circle.m_p.SetZero();
  b2Manifold manifold;
  b2CollidePolygonAndCircle(&manifold, &shapes_[static_cast<size_t>(a)], ta, &circle, tb);
  calls_.fetch_add(1, std::memory_order_relaxed);
  anchor(k, pa, pb);
  if (manifold.pointCount == 0) {
    // Apart: the disc is farther than rb + margin from the polygon. Its centre's distance
    // beyond the best face plane bounds the gap from below.
    k.kind = CachedContact::Kind::Apart;
    const Vec2 c = xb - pa.x;
    const Vec2 local(pa.c * c.x() + pa.s * c.y(), -pa.s * c.x() + pa.c * c.y());
    double widest = -1e300;
    for (int e = 0; e < A.count; ++e) widest = std::max(widest, A.normals[e].dot(local - A.vertices[e]));
    k.slack = std::max(0.0, widest - rb);
    return {};
  }
  // Box2D 2.4 reports a vertex region as e_faceA too, with the vertex as its localPoint (a
  // face region's localPoint is the face's middle, never near a vertex).
  const double inv = 1.0 / scale_;
  const Vec2 at(manifold.localPoint.x * inv, manifold.localPoint.y * inv);
  const int vertex = nearestVertex(A, at);
  if ((A.vertices[vertex] - at).norm() < 1e-4 * A.circumradius) {
    k.kind = CachedContact::Kind::VertexDisc;
    k.reference = vertex;
  } else {
    k.kind = CachedContact::Kind::FaceA;
    k.reference = faceAlong(A, manifold.localNormal);
  }
  k.slack = kMarginUnits * inv;
  return evaluate(k, a, pa, -1, pb, rb);
}

double PolygonCollider::gap(int a, const Pose& pa, int b, const Pose& pb) const {
  const Polygon& A = polygons_[static_cast<size_t>(a)];
  const Polygon& B = polygons_[static_cast<size_t>(b)];
  // Separation of `other` from each edge of `ref`, in ref's body frame: other's vertices are
  // d + R w with d = Rrᵀ(xo − xr), R = Rrᵀ Ro.
  auto widest = [](const Polygon& ref, const Pose& pr, const Polygon& other, const Pose& po) {
    const Vec2 dx = po.x - pr.x;
    const Vec2 d(pr.c * dx.x() + pr.s * dx.y(), -pr.s * dx.x() + pr.c * dx.y());
    const double c = pr.c * po.c + pr.s * po.s, s = pr.c * po.s - pr.s * po.c;
    Vec2 w[kMaxPolygonVertices];
    for (int v = 0; v < other.count; ++v) {
      const Vec2& q = other.vertices[v];
      w[v] = Vec2(d.x() + c * q.x() - s * q.y(), d.y() + s * q.x() + c * q.y());
    }
    double best = -1e300;
    for (int e = 0; e < ref.count; ++e) {
      const Vec2& n = ref.normals[e];
      const double offset = n.dot(ref.vertices[e]);
      double least = 1e300;
      for (int v = 0; v < other.count; ++v) least = std::min(least, n.dot(w[v]) - offset);
      best = std::max(best, least);
    }
    return best;
  };
  return std::max(widest(A, pa, B, pb), widest(B, pb, A, pa));
}

}  // namespace grainlab

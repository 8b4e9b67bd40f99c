// grainlab's polygon narrow phase against Box2D, its reference (engine/src/polygon_features.hpp
// and polygon_collider.hpp): on 100,000+ random polygon-polygon and polygon-disc pairs
// (random placements, near-parallel faces, vertex against vertex, deep overlaps):
//  - the features (apart, which body's face is the reference, which face, which vertex) are
//    Box2D's, except where Box2D's float arithmetic decides a near tie: such a disagreement
//    must vanish when the poses are moved by float-rounding amounts (1e-6 of the size);
//  - with the same features, the contact measured by the collider equals the contact
//    computed from Box2D's features by an independent clipping in the world frame (the
//    definition in docs/polygon-contacts.md): normal within 1e-9 rad, depth within 1e-12 of
//    the particle size.
#include <gtest/gtest.h>

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

#include "polygon_collider.hpp"
#include "polygon_features.hpp"

namespace grainlab {
namespace {

constexpr double kSize = 0.0025;         // m: circumradius of the typical polygon
constexpr double kScale = 1.0 / kSize;   // Box2D units per metre, as the World chooses it
using Kind = CachedContact::Kind;

Pose pose(const Vec2& x, double angle) { return {x, std::cos(angle), std::sin(angle)}; }
Vec2 toWorld(const Pose& p, const Vec2& u) {
  return Vec2(p.x.x() + p.c * u.x() - p.s * u.y(), p.x.y() + p.s * u.x() + p.c * u.y());
}
Vec2 turned(const Pose& p, const Vec2& u) { return Vec2(p.c * u.x() - p.s * u.y(), p.s * u.x() + p.c * u.y()); }

// What a pair's features are, in a comparable form.
struct Features {
  Kind kind = Kind::None;
  int reference = -1;
  bool operator==(const Features&) const = default;
};

// ---- Box2D, as the reference ----
b2PolygonShape boxShape(const Polygon& p, float margin) {
  b2Vec2 v[b2_maxPolygonVertices];
  for (int k = 0; k < p.count; ++k) {
    v[k].Set(static_cast<float>(p.vertices[k].x() * kScale), static_cast<float>(p.vertices[k].y() * kScale));
  }
  b2PolygonShape s;
  s.Set(v, p.count);
  s.m_radius = margin;
  return s;
}
// Both bodies' transforms in a frame centred on A (positions differenced in double first).
void transforms(const Pose& pa, const Pose& pb, b2Transform& ta, b2Transform& tb) {
  ta.p.SetZero();
  ta.q.c = static_cast<float>(pa.c);
  ta.q.s = static_cast<float>(pa.s);
  const Vec2 d = (pb.x - pa.x) * kScale;
  tb.p.Set(static_cast<float>(d.x()), static_cast<float>(d.y()));
  tb.q.c = static_cast<float>(pb.c);
  tb.q.s = static_cast<float>(pb.s);
}
// Box2D's Set() may reorder vertices: our face is the one whose normal is nearest Box2D's.
int faceAlong(const Polygon& p, const b2Vec2& n) {
  int best = 0;
  for (int e = 1; e < p.count; ++e) {
    if (p.normals[e].dot(Vec2(n.x, n.y)) > p.normals[best].dot(Vec2(n.x, n.y))) best = e;
  }
  return best;
}

Features box2dPolygons(const Polygon& A, const Pose& pa, const Polygon& B, const Pose& pb, float margin) {
  const b2PolygonShape sa = boxShape(A, margin), sb = boxShape(B, margin);
  b2Transform ta, tb;
  transforms(pa, pb, ta, tb);
  b2Manifold m;
  b2CollidePolygons(&m, &sa, ta, &sb, tb);
  if (m.pointCount == 0) return {Kind::Apart, -1};
  const bool faceA = m.type == b2Manifold::e_faceA;
  return {faceA ? Kind::FaceA : Kind::FaceB, faceAlong(faceA ? A : B, m.localNormal)};
}

Features box2dDisc(const Polygon& A, const Pose& pa, const Vec2& xb, double rb, float margin) {
  const b2PolygonShape sa = boxShape(A, margin);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(rb * kScale);
  circle.m_p.SetZero();
  b2Transform ta, tb;
  transforms(pa, Pose{xb, 1, 0}, ta, tb);
  b2Manifold m;
  b2CollidePolygonAndCircle(&m, &sa, ta, &circle, tb);
  if (m.pointCount == 0) return {Kind::Apart, -1};
  // Box2D reports a vertex region as e_faceA with the vertex as its local point.
  const Vec2 at(m.localPoint.x / kScale, m.localPoint.y / kScale);
  for (int v = 0; v < A.count; ++v) {
    if ((A.vertices[v] - at).norm() < 1e-4 * A.circumradius) return {Kind::VertexDisc, v};
  }
  return {Kind::FaceA, faceAlong(A, m.localNormal)};
}

// ---- the independent measurement: the features clipped in the world frame ----
int incidentEdge(const Polygon& inc, const Pose& p, const Vec2& referenceNormal) {
  int best = 0;
  for (int e = 1; e < inc.count; ++e) {
    if (turned(p, inc.normals[e]).dot(referenceNormal) < turned(p, inc.normals[best]).dot(referenceNormal)) best = e;
  }
  return best;
}

ContactGeometry worldFrameContact(const Features& f, const Polygon& A, const Pose& pa, const Polygon& B, const Pose& pb) {
  const bool faceA = f.kind == Kind::FaceA;
  const Polygon& R = faceA ? A : B;
  const Polygon& I = faceA ? B : A;
  const Pose& pr = faceA ? pa : pb;
  const Pose& pi = faceA ? pb : pa;
  const Vec2 n = turned(pr, R.normals[f.reference]);
  const Vec2 v1 = toWorld(pr, R.vertices[f.reference]), v2 = toWorld(pr, R.vertices[(f.reference + 1) % R.count]);
  const int q = incidentEdge(I, pi, n);
  Vec2 w[2] = {toWorld(pi, I.vertices[q]), toWorld(pi, I.vertices[(q + 1) % I.count])};
  const Vec2 t = perp(n);
  const double lo = t.dot(v1), hi = t.dot(v2), s0 = t.dot(w[0]), s1 = t.dot(w[1]);
  if (!(s1 < s0) || s0 <= lo || s1 >= hi) return {};
  const Vec2 w0 = w[0], edge = w[1] - w[0];
  w[0] = w0 + edge * ((std::min(s0, hi) - s0) / (s1 - s0));
  w[1] = w0 + edge * ((std::max(s1, lo) - s0) / (s1 - s0));
  ManifoldPoints m;
  m.count = 2;
  for (int k = 0; k < 2; ++k) {
    m.depths[k] = n.dot(v1 - w[k]);
    m.points[k] = w[k] + (0.5 * m.depths[k]) * n;
  }
  return reduceManifold(faceA ? n : Vec2(-n), m);
}

// ---- random pairs ----
struct Random {
  std::mt19937_64 rng{2026};
  double uniform(double a = 0, double b = 1) { return std::uniform_real_distribution<double>(a, b)(rng); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }

  // A convex polygon of 3-8 vertices about kSize across: an elongated hexagon (as in the
  // specimens) or vertices at random angles on a random ellipse (always convex).
  Polygon polygon() {
    std::vector<Vec2> v;
    const double a = kSize * uniform(0.7, 1.2), b = a / uniform(1.0, 2.0);
    if (uniform() < 0.4) {
      for (int k = 0; k < 6; ++k) v.emplace_back(a * std::cos(k * kPi / 3), b * std::sin(k * kPi / 3));
    } else {
      const int count = integer(3, 8);
      for (int k = 0; k < count; ++k) {
        const double angle = 2 * kPi * (k + uniform(-0.3, 0.3)) / count;
        v.emplace_back(a * std::cos(angle), b * std::sin(angle));
      }
    }
    return makePolygon(v);
  }
};

// Overlap of the pair as the narrow phase measures it (negative when apart).
double overlapOf(const PolygonCollider& c, int a, const Pose& pa, int b, const Pose& pb) {
  return c.collidePolygons(a, pa, b, pb).overlap;
}

// Moves B along `u` until its overlap with A is about `overlap` (bisection on the centre
// distance; a negative overlap leaves a gap of that size along u, roughly).
Pose placeAlong(const PolygonCollider& c, int a, const Pose& pa, int b, double angleB, const Vec2& u, double overlap) {
  double lo = 0, hi = 6 * kSize;  // overlapping at lo, apart at hi
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (overlapOf(c, a, pa, b, pose(pa.x + mid * u, angleB)) > std::max(overlap, 0.0) ? lo : hi) = mid;
  }
  const double d = overlap < 0 ? hi - overlap : hi;
  return pose(pa.x + d * u, angleB);
}

// Is Box2D's answer ours at some pose within float rounding of the given one?
template <class Ours>
bool withinRounding(Random& r, const Features& box2d, const Pose& pa, const Pose& pb, Ours&& ours) {
  const double shift = 1e-6 * kSize, turn = 1e-6;
  for (int trial = 0; trial < 64; ++trial) {
    const double angle = std::atan2(pb.s, pb.c) + turn * r.uniform(-1, 1);
    const Pose moved = pose(pb.x + Vec2(shift * r.uniform(-1, 1), shift * r.uniform(-1, 1)), angle);
    if (ours(pa, moved) == box2d) return true;
  }
  return false;
}

Features featuresOf(const CachedContact& k) {
  if (k.kind == Kind::Apart) return {Kind::Apart, -1};
  return {k.kind, k.reference};
}

TEST(PolygonFeatures, AgreeWithBox2DOnRandomPolygonPairs) {
  Random r;
  const int kPairs = 80000;
  int agreed = 0, nearTies = 0, touching = 0, deep = 0, nearParallel = 0, vertexVertex = 0;
  double worstAngle = 0, worstDepth = 0;
  for (int trial = 0; trial < kPairs; ++trial) {
    PolygonCollider collider(kScale);
    const FeatureTolerances tol = collider.tolerances();
    const float margin = static_cast<float>(tol.margin * kScale);
    const Polygon A = r.polygon(), B = r.polygon();
    const int a = collider.add(A), b = collider.add(B);
    const Pose pa = pose(Vec2(r.uniform(-1, 1), r.uniform(-1, 1)), r.uniform(0, 2 * kPi));
    Pose pb;
    const int scenario = trial % 4;
    if (scenario == 0 || scenario == 1) {
      // Random direction and angle; overlaps from a gap of 5% to a deep 30% of the size.
      const double dir = r.uniform(0, 2 * kPi);
      const double overlap = scenario == 0 ? kSize * r.uniform(-0.05, 0.05) : kSize * r.uniform(0.05, 0.3);
      pb = placeAlong(collider, a, pa, b, r.uniform(0, 2 * kPi), Vec2(std::cos(dir), std::sin(dir)), overlap);
      deep += scenario == 1;
    } else if (scenario == 2) {
      // Near-parallel faces: B's face q turned against A's face e, off by up to 1e-3 rad
      // (down to 1e-9), pressed along A's face normal.
      const int e = r.integer(0, A.count - 1), q = r.integer(0, B.count - 1);
      const Vec2 nA = turned(pa, A.normals[e]);
      const double target = std::atan2(-nA.y(), -nA.x());
      const double off = std::pow(10.0, r.uniform(-9, -3)) * (r.uniform() < 0.5 ? -1 : 1);
      const double angleB = target - std::atan2(B.normals[q].y(), B.normals[q].x()) + off;
      pb = placeAlong(collider, a, pa, b, angleB, nA, kSize * r.uniform(-0.01, 0.05));
      // Slide B along the face so the faces overlap partly or fully.
      const Vec2 slide = perp(nA) * (kSize * r.uniform(-0.8, 0.8));
      pb.x += slide;
      ++nearParallel;
    } else {
      // Vertex against vertex: B's vertex placed on A's vertex, nudged by up to 2% of the size.
      const int va = r.integer(0, A.count - 1), vb = r.integer(0, B.count - 1);
      const Vec2 tip = toWorld(pa, A.vertices[va]);
      const Vec2 out = (tip - pa.x).normalized();
      // B turned so that its vertex points back at A's.
      const Vec2 bv = B.vertices[vb];
      const double angleB = std::atan2(-out.y(), -out.x()) - std::atan2(bv.y(), bv.x()) + r.uniform(-0.3, 0.3);
      const Pose oriented = pose(Vec2::Zero(), angleB);
      const Vec2 nudge(kSize * r.uniform(-0.02, 0.02), kSize * r.uniform(-0.02, 0.02));
      pb = pose(tip - turned(oriented, bv) + nudge, angleB);
      ++vertexVertex;
    }

    auto ours = [&](const Pose& p, const Pose& q) {
      CachedContact k;
      findPolygonFeatures(A, p, B, q, tol, k);
      return featuresOf(k);
    };
    const Features mine = ours(pa, pb);
    const Features box2d = box2dPolygons(A, pa, B, pb, margin);
    if (!(mine == box2d)) {
      ASSERT_TRUE(withinRounding(r, box2d, pa, pb, ours))
          << "trial " << trial << " (scenario " << scenario << "): grainlab kind " << int(mine.kind) << " face "
          << mine.reference << ", Box2D kind " << int(box2d.kind) << " face " << box2d.reference
          << ", and no pose within float rounding gives Box2D's answer";
      ++nearTies;
      continue;
    }
    ++agreed;
    if (mine.kind == Kind::Apart) continue;
    // Same features: the collider's measurement against the world-frame definition.
    const ContactGeometry g = collider.collidePolygons(a, pa, b, pb);
    const ContactGeometry ref = worldFrameContact(box2d, A, pa, B, pb);
    ASSERT_EQ(g.overlap > 0, ref.overlap > 0) << "trial " << trial;
    if (ref.overlap <= 0) continue;
    ++touching;
    const double angle = std::abs(std::atan2(cross(g.normal, ref.normal), g.normal.dot(ref.normal)));
    worstAngle = std::max(worstAngle, angle);
    worstDepth = std::max(worstDepth, std::abs(g.overlap - ref.overlap) / kSize);
    ASSERT_LE(angle, 1e-9) << "trial " << trial;
    ASSERT_LE(std::abs(g.overlap - ref.overlap), 1e-12 * kSize) << "trial " << trial;
    // The point is a position (its rounding scales with the coordinates), and a mean
    // weighted by the two ends' depths: a depth's rounding (~1e-12 of the size) moves it
    // along the face (~the size) by that rounding over the depth.
    const double pointTolerance =
        16 * DBL_EPSILON * ref.point.norm() + 1e-12 * kSize * (1 + kSize / ref.overlap);
    ASSERT_LE((g.point - ref.point).norm(), pointTolerance) << "trial " << trial;
  }
  std::printf("polygon pairs: %d, same features as Box2D %d, near ties within float rounding %d; touching %d "
              "(deep %d, near-parallel %d, vertex-vertex %d); worst normal %.2g rad, worst depth %.2g of the size\n",
              kPairs, agreed, nearTies, touching, deep, nearParallel, vertexVertex, worstAngle, worstDepth);
  EXPECT_LT(nearTies, kPairs / 100) << "near ties must be rare events";
  EXPECT_GT(touching, kPairs / 3) << "most pairs must test a contact, not a gap";
}

TEST(PolygonFeatures, AgreeWithBox2DOnRandomPolygonDiscPairs) {
  Random r;
  const int kPairs = 40000;
  int agreed = 0, nearTies = 0, faces = 0, vertices = 0;
  for (int trial = 0; trial < kPairs; ++trial) {
    PolygonCollider collider(kScale);
    const FeatureTolerances tol = collider.tolerances();
    const float margin = static_cast<float>(tol.margin * kScale);
    const Polygon A = r.polygon();
    const int a = collider.add(A);
    const Pose pa = pose(Vec2(r.uniform(-1, 1), r.uniform(-1, 1)), r.uniform(0, 2 * kPi));
    const double rb = kSize * r.uniform(0.3, 1.2);
    // The disc's centre at a random direction, from a 5% gap to a 40% overlap of its radius;
    // half the time aimed at a vertex.
    Vec2 u;
    if (trial % 2) {
      const double dir = r.uniform(0, 2 * kPi);
      u = Vec2(std::cos(dir), std::sin(dir));
    } else {
      u = (toWorld(pa, A.vertices[r.integer(0, A.count - 1)]) - pa.x).normalized();
      u = Vec2(u.x() + r.uniform(-0.05, 0.05), u.y() + r.uniform(-0.05, 0.05)).normalized();
    }
    double lo = 0, hi = 4 * kSize;
    const double overlap = rb * r.uniform(-0.05, 0.4);
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (collider.collidePolygonDisc(a, pa, pa.x + mid * u, rb).overlap > std::max(overlap, 0.0) ? lo : hi) = mid;
    }
    const Vec2 xb = pa.x + (overlap < 0 ? hi - overlap : hi) * u;

    auto ours = [&](const Pose& p, const Pose& q) {
      CachedContact k;
      findDiscFeatures(A, p, q.x, rb, tol, k);
      return featuresOf(k);
    };
    const Features mine = ours(pa, Pose{xb, 1, 0});
    const Features box2d = box2dDisc(A, pa, xb, rb, margin);
    if (!(mine == box2d)) {
      ASSERT_TRUE(withinRounding(r, box2d, pa, Pose{xb, 1, 0}, ours)) << "trial " << trial;
      ++nearTies;
      continue;
    }
    ++agreed;
    if (mine.kind == Kind::Apart) continue;
    // The measured contact against the closest-point definition: for a face, the centre's
    // depth below the face's line; for a vertex, the distance from the vertex.
    const ContactGeometry g = collider.collidePolygonDisc(a, pa, xb, rb);
    double depth;
    Vec2 normal;
    if (mine.kind == Kind::VertexDisc) {
      ++vertices;
      const Vec2 d = xb - toWorld(pa, A.vertices[mine.reference]);
      depth = rb - d.norm();
      normal = d.normalized();
    } else {
      ++faces;
      normal = turned(pa, A.normals[mine.reference]);
      depth = rb - (xb - toWorld(pa, A.vertices[mine.reference])).dot(normal);
    }
    if (depth <= 0) {
      EXPECT_LE(g.overlap, 0);
      continue;
    }
    ASSERT_NEAR(g.overlap, depth, 1e-12 * kSize) << "trial " << trial;
    ASSERT_LE(std::abs(std::atan2(cross(g.normal, normal), g.normal.dot(normal))), 1e-9) << "trial " << trial;
  }
  std::printf("polygon-disc pairs: %d, same features as Box2D %d (face %d, vertex %d), near ties %d\n", kPairs,
              agreed, faces, vertices, nearTies);
  EXPECT_LT(nearTies, kPairs / 100);
  EXPECT_GT(vertices, kPairs / 20) << "the vertex regions must be exercised";
}

}  // namespace
}  // namespace grainlab

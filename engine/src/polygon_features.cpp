#include "polygon_features.hpp"

#include <algorithm>
#include <cfloat>
#include <limits>

namespace grainlab {
namespace {

// Box2D's constants, in its units (b2_common.h, v2.4): the features are decided as Box2D
// decides them, at the scale at which Box2D would see the particles.
constexpr double kLinearSlop = 0.005;
constexpr double kEpsilon = FLT_EPSILON;

// Another body's pose seen from `ref`'s body frame: a body-frame point u of the other body is
// at d + R u there.
struct Frame {
  Vec2 d;
  double c, s;
};

Frame relative(const Pose& ref, const Pose& other) {
  const Vec2 dx = other.x - ref.x;
  return {Vec2(ref.c * dx.x() + ref.s * dx.y(), -ref.s * dx.x() + ref.c * dx.y()), ref.c * other.c + ref.s * other.s,
          ref.c * other.s - ref.s * other.c};
}
Vec2 place(const Frame& f, const Vec2& u) {
  return Vec2(f.d.x() + f.c * u.x() - f.s * u.y(), f.d.y() + f.s * u.x() + f.c * u.y());
}
Vec2 turn(const Frame& f, const Vec2& u) { return Vec2(f.c * u.x() - f.s * u.y(), f.s * u.x() + f.c * u.y()); }

// Separation of the points w (in ref's frame) from ref's face e: the least signed distance
// beyond the face's line.
double faceSeparation(const Polygon& ref, int e, const Vec2* w, int count) {
  const Vec2& n = ref.normals[e];
  const double offset = n.dot(ref.vertices[e]);
  double least = std::numeric_limits<double>::infinity();
  for (int v = 0; v < count; ++v) least = std::min(least, n.dot(w[v]) - offset);
  return least;
}

// b2FindMaxSeparation: ref's face that separates the points w most, and by how much (the
// first of equals, as Box2D takes it); `runnerUp` receives the next best face's separation.
double maxSeparation(const Polygon& ref, const Vec2* w, int count, int& face, double& runnerUp) {
  double best = -std::numeric_limits<double>::infinity();
  runnerUp = best;
  face = 0;
  for (int e = 0; e < ref.count; ++e) {
    const double s = faceSeparation(ref, e, w, count);
    if (s > best) {
      runnerUp = best;
      best = s;
      face = e;
    } else if (s > runnerUp) {
      runnerUp = s;
    }
  }
  return best;
}

// b2ClipSegmentToLine: the part of segment `in` where n·p ≤ offset; false if less than a
// segment's two points remain (Box2D then reports no contact).
bool clipSegment(Vec2 (&seg)[2], const Vec2& n, double offset) {
  const double d0 = n.dot(seg[0]) - offset, d1 = n.dot(seg[1]) - offset;
  Vec2 out[2];
  int count = 0;
  if (d0 <= 0) out[count++] = seg[0];
  if (d1 <= 0) out[count++] = seg[1];
  if (d0 * d1 < 0) out[count++] = seg[0] + (d0 / (d0 - d1)) * (seg[1] - seg[0]);
  if (count < 2) return false;
  seg[0] = out[0];
  seg[1] = out[1];
  return true;
}

void setApart(CachedContact& k, bool axisOnB, int face, double separation, double reach) {
  k.kind = CachedContact::Kind::Apart;
  k.axisOnB = axisOnB;
  k.reference = face;
  k.slack = std::max(0.0, separation - reach);
}

}  // namespace

FeatureTolerances FeatureTolerances::atScale(double lengthScale) {
  // The margin is a tenth of Box2D's own reference-face tolerance (docs/polygon-contacts.md).
  return {0.01 * kLinearSlop / lengthScale, 0.1 * kLinearSlop / lengthScale, kEpsilon / lengthScale};
}

void findPolygonFeatures(const Polygon& A, const Pose& pa, const Polygon& B, const Pose& pb,
                         const FeatureTolerances& tol, CachedContact& k) {
  const double reach = 2 * tol.margin;  // both polygons' margins, as Box2D's totalRadius
  const Frame ba = relative(pa, pb), ab = relative(pb, pa);
  Vec2 wb[kMaxPolygonVertices], wa[kMaxPolygonVertices];  // each polygon in the other's frame
  for (int v = 0; v < B.count; ++v) wb[v] = place(ba, B.vertices[v]);
  int faceA = 0, faceB = 0;
  double runnerUpA, runnerUpB;
  const double separationA = maxSeparation(A, wb, B.count, faceA, runnerUpA);
  if (separationA > reach) return setApart(k, false, faceA, separationA, reach);
  for (int v = 0; v < A.count; ++v) wa[v] = place(ab, A.vertices[v]);
  const double separationB = maxSeparation(B, wa, A.count, faceB, runnerUpB);
  if (separationB > reach) return setApart(k, true, faceB, separationB, reach);

  const bool onB = separationB > separationA + tol.referenceTolerance;
  const Polygon& R = onB ? B : A;
  const Polygon& I = onB ? A : B;
  const Frame& f = onB ? ab : ba;  // I seen from R
  const Vec2* w = onB ? wa : wb;
  const int e = onB ? faceB : faceA;
  // b2FindIncidentEdge: I's face most anti-parallel to the reference normal.
  const Vec2& n = R.normals[e];
  int incident = 0;
  double least = std::numeric_limits<double>::infinity(), nextLeast = least;
  for (int q = 0; q < I.count; ++q) {
    const double d = n.dot(turn(f, I.normals[q]));
    if (d < least) {
      nextLeast = least;
      least = d;
      incident = q;
    } else if (d < nextLeast) {
      nextLeast = d;
    }
  }
  // Box2D's clipping: the incident edge cut to the face's sides widened by the reach; some
  // point left must lie within the reach of the face.
  const Vec2 t = perp(n);  // along the face, counter-clockwise
  const Vec2& v1 = R.vertices[e];
  const Vec2& v2 = R.vertices[(e + 1) % R.count];
  Vec2 seg[2] = {w[incident], w[(incident + 1) % I.count]};
  const bool spans = clipSegment(seg, -t, -t.dot(v1) + reach) && clipSegment(seg, t, t.dot(v2) + reach);
  const double front = n.dot(v1);
  if (!spans || std::min(n.dot(seg[0]), n.dot(seg[1])) - front > reach) {
    // Within the reach of a face's line but beside it (a corner passing a corner): apart,
    // asked again at the next step.
    return setApart(k, onB, e, reach, reach);
  }
  k.kind = onB ? CachedContact::Kind::FaceB : CachedContact::Kind::FaceA;
  k.reference = e;
  k.incident = incident;
  // While the pair moves by m (relativeMotion), every separation moves by at most m, and a
  // dot product of the two bodies' normals by at most the turn, m / lever. So a fresh search
  // answers the same while m stays below each decision's margin (halved where the decision
  // compares two moving values). Decisions tied closer than the speculative margin are kept
  // for that margin: a delayed switch then changes a depth by less than Box2D's own choice.
  const double lever = std::abs(pb.x.x() - pa.x.x()) + std::abs(pb.x.y() - pa.x.y()) + A.circumradius + B.circumradius;
  const double bestFace = 0.5 * ((onB ? separationB - runnerUpB : separationA - runnerUpA));
  const double reference = 0.5 * std::abs(separationB - separationA - tol.referenceTolerance);
  const double inReach = reach - std::max(separationA, separationB);
  const double incidentEdge = 0.5 * (nextLeast - least) * lever;
  k.slack = std::max(tol.margin, std::min({bestFace, reference, inReach, incidentEdge}));
}

void findDiscFeatures(const Polygon& A, const Pose& pa, const Vec2& xb, double rb, const FeatureTolerances& tol,
                      CachedContact& k) {
  const double reach = tol.margin + rb;
  const Vec2 dx = xb - pa.x;
  const Vec2 c(pa.c * dx.x() + pa.s * dx.y(), -pa.s * dx.x() + pa.c * dx.y());  // the centre in A's frame
  // b2CollidePolygonAndCircle: the face of greatest separation, or out at the first beyond reach.
  int face = 0;
  double separation = -std::numeric_limits<double>::infinity();
  for (int e = 0; e < A.count; ++e) {
    const double s = A.normals[e].dot(c - A.vertices[e]);
    if (s > reach) return setApart(k, false, e, s, reach);
    if (s > separation) {
      separation = s;
      face = e;
    }
  }
  k.slack = tol.margin;
  const Vec2& v1 = A.vertices[face];
  const int next = (face + 1) % A.count;
  const Vec2& v2 = A.vertices[next];
  auto faceContact = [&] {
    k.kind = CachedContact::Kind::FaceA;
    k.reference = face;
  };
  if (separation < tol.inside) return faceContact();  // the centre is inside the polygon
  // Past either end of the face, the disc meets a vertex (if it reaches it).
  auto vertexContact = [&](int vertex) {
    const double distance = (c - A.vertices[vertex]).norm();
    if (distance > reach) return setApart(k, false, face, distance, reach);
    k.kind = CachedContact::Kind::VertexDisc;
    k.reference = vertex;
  };
  if ((c - v1).dot(v2 - v1) <= 0) return vertexContact(face);
  if ((c - v2).dot(v1 - v2) <= 0) return vertexContact(next);
  if ((c - 0.5 * (v1 + v2)).dot(A.normals[face]) > reach) return setApart(k, false, face, separation, reach);
  faceContact();
}

double separationAlongAxis(const Polygon& A, const Pose& pa, const Polygon& B, const Pose& pb,
                           const CachedContact& k) {
  const Polygon& ref = k.axisOnB ? B : A;
  const Polygon& other = k.axisOnB ? A : B;
  const Frame f = k.axisOnB ? relative(pb, pa) : relative(pa, pb);
  Vec2 w[kMaxPolygonVertices];
  for (int v = 0; v < other.count; ++v) w[v] = place(f, other.vertices[v]);
  return faceSeparation(ref, k.reference, w, other.count);
}

}  // namespace grainlab

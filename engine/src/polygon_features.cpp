#include "polygon_features.hpp"

#include <algorithm>
#include <cfloat>
#include <limits>

#include "grainlab/simd_path.hpp"
#include "polygon_separation_kernel.hpp"

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

constexpr int kSlots = kMaxPolygonVertices;

// Every slot of `other`'s vertices placed by f (place(), slot by slot): x into wx, y into wy.
void placeSlots(const Frame& f, const PolygonFeatureTable& other, double* wx, double* wy) {
  for (int v = 0; v < kSlots; ++v) {
    wx[v] = f.d.x() + f.c * other.vx[v] - f.s * other.vy[v];
    wy[v] = f.d.y() + f.s * other.vx[v] + f.c * other.vy[v];
  }
}

// Separation of the points w (in ref's frame) from each of ref's first `faces` faces (rounded
// up to even: the slot past an odd count is padding): the least signed distance beyond the
// face's line, n·w − n·v_e. Two faces at a time, so that SSE2 takes them in one instruction;
// the least of a set does not depend on the order it is taken in.
void faceSeparations(const PolygonFeatureTable& ref, int faces, const double* wx, const double* wy, int count,
                     double* least) {
  for (int e = 0; e < faces; e += 2) {
    double l0 = std::numeric_limits<double>::infinity(), l1 = l0;
    for (int v = 0; v < count; ++v) {
      const double x = wx[v], y = wy[v];
      l0 = std::min(l0, ref.nx[e] * x + ref.ny[e] * y - ref.offset[e]);
      l1 = std::min(l1, ref.nx[e + 1] * x + ref.ny[e + 1] * y - ref.offset[e + 1]);
    }
    least[e] = l0;
    least[e + 1] = l1;
  }
}

// b2FindMaxSeparation over the faces' separations: the face that separates most, and by how
// much (the first of equals, as Box2D takes it); `runnerUp` receives the next best face's.
double maxSeparation(const double* separation, int count, int& face, double& runnerUp) {
  double best = -std::numeric_limits<double>::infinity();
  runnerUp = best;
  face = 0;
  for (int e = 0; e < count; ++e) {
    const double s = separation[e];
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

// b2FindMaxSeparation for ref's faces against `other` placed by f (its slots into wx, wy): the
// scalar loops above, or on the wide path the kernel that has their bits.
double bestSeparatingFace(bool wide, const Frame& f, const PolygonFeatureTable& ref, const PolygonFeatureTable& other,
                          double* wx, double* wy, int& face, double& runnerUp) {
  if (wide) return bestSeparatingFaceWide(ref, other, f.d.x(), f.d.y(), f.c, f.s, wx, wy, face, runnerUp);
  alignas(64) double separation[kSlots];
  placeSlots(f, other, wx, wy);
  faceSeparations(ref, ref.count, wx, wy, other.count, separation);
  return maxSeparation(separation, ref.count, face, runnerUp);
}

// b2FindIncidentEdge: I's face most anti-parallel to the reference normal n, I seen from the
// reference body by f (n·turn(f, m_q), every slot, then the first of equals and the runner-up in
// order), or on the wide path the kernel that has these bits.
int mostAntiParallelEdge(bool wide, const Vec2& n, const Frame& f, const PolygonFeatureTable& tI, double& least,
                         double& nextLeast) {
  if (wide) return mostAntiParallelEdgeWide(n.x(), n.y(), f.c, f.s, tI, least, nextLeast);
  alignas(64) double facing[kSlots];
  for (int q = 0; q < kSlots; ++q) {
    facing[q] = n.x() * (f.c * tI.nx[q] - f.s * tI.ny[q]) + n.y() * (f.s * tI.nx[q] + f.c * tI.ny[q]);
  }
  int incident = 0;
  least = std::numeric_limits<double>::infinity();
  nextLeast = least;
  for (int q = 0; q < tI.count; ++q) {
    const double d = facing[q];
    if (d < least) {
      nextLeast = least;
      least = d;
      incident = q;
    } else if (d < nextLeast) {
      nextLeast = d;
    }
  }
  return incident;
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

PolygonFeatureTable PolygonFeatureTable::of(const Polygon& p) {
  PolygonFeatureTable t{};
  for (int e = 0; e < p.count; ++e) {
    t.nx[e] = p.normals[e].x();
    t.ny[e] = p.normals[e].y();
    t.offset[e] = p.normals[e].dot(p.vertices[e]);
    t.vx[e] = p.vertices[e].x();
    t.vy[e] = p.vertices[e].y();
  }
  t.count = p.count;
  t.circumradius = p.circumradius;
  return t;
}

void findPolygonFeatures(const Polygon& A, const Pose& pa, const Polygon& B, const Pose& pb,
                         const FeatureTolerances& tol, CachedContact& k) {
  findPolygonFeatures(PolygonFeatureTable::of(A), pa, PolygonFeatureTable::of(B), pb, tol, k);
}

void findPolygonFeatures(const PolygonFeatureTable& ta, const Pose& pa, const PolygonFeatureTable& tb, const Pose& pb,
                         const FeatureTolerances& tol, CachedContact& k, SlackGuards guards) {
  const double reach = 2 * tol.margin;  // both polygons' margins, as Box2D's totalRadius
  const Frame ba = relative(pa, pb), ab = relative(pb, pa);
  // Each polygon in the other's frame, and each face's separation of the other polygon.
  alignas(64) double wbx[kSlots], wby[kSlots], wax[kSlots], way[kSlots];
  const bool wide = simdPath() == SimdPath::Wide;
  int faceA = 0, faceB = 0;
  double runnerUpA, runnerUpB;
  const double separationA = bestSeparatingFace(wide, ba, ta, tb, wbx, wby, faceA, runnerUpA);
  if (separationA > reach) return setApart(k, false, faceA, separationA, reach);
  const double separationB = bestSeparatingFace(wide, ab, tb, ta, wax, way, faceB, runnerUpB);
  if (separationB > reach) return setApart(k, true, faceB, separationB, reach);

  const bool onB = separationB > separationA + tol.referenceTolerance;
  const PolygonFeatureTable& tR = onB ? tb : ta;
  const PolygonFeatureTable& tI = onB ? ta : tb;
  const Frame& f = onB ? ab : ba;  // I seen from R
  const double* wx = onB ? wax : wbx;
  const double* wy = onB ? way : wby;
  const int e = onB ? faceB : faceA;
  const Vec2 n(tR.nx[e], tR.ny[e]);
  double least, nextLeast;
  const int incident = mostAntiParallelEdge(wide, n, f, tI, least, nextLeast);
  // Box2D's clipping: the incident edge cut to the face's sides widened by the reach; some
  // point left must lie within the reach of the face.
  const Vec2 t = perp(n);  // along the face, counter-clockwise
  const int after = (e + 1) % tR.count;
  const Vec2 v1(tR.vx[e], tR.vy[e]), v2(tR.vx[after], tR.vy[after]);
  const int next = (incident + 1) % tI.count;
  Vec2 seg[2] = {Vec2(wx[incident], wy[incident]), Vec2(wx[next], wy[next])};
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
  const double lever =
      std::abs(pb.x.x() - pa.x.x()) + std::abs(pb.x.y() - pa.x.y()) + ta.circumradius + tb.circumradius;
  const double bestFace = 0.5 * ((onB ? separationB - runnerUpB : separationA - runnerUpA));
  const double reference = 0.5 * std::abs(separationB - separationA - tol.referenceTolerance);
  const double inReach = guards == SlackGuards::EveryDecision ? reach - std::max(separationA, separationB)
                                                                   : std::numeric_limits<double>::infinity();
  const double incidentEdge = 0.5 * (nextLeast - least) * lever;
  k.slack = std::max(tol.margin, std::min({bestFace, reference, inReach, incidentEdge}));
}

void findDiscFeatures(const Polygon& A, const Pose& pa, const Vec2& xb, double rb, const FeatureTolerances& tol,
                      CachedContact& k, SlackGuards guards) {
  const double reach = tol.margin + rb;
  const Vec2 dx = xb - pa.x;
  const Vec2 c(pa.c * dx.x() + pa.s * dx.y(), -pa.s * dx.x() + pa.c * dx.y());  // the centre in A's frame
  // b2CollidePolygonAndCircle: the face of greatest separation, or out at the first beyond reach.
  int face = 0;
  double separation = -std::numeric_limits<double>::infinity(), runnerUp = separation;
  for (int e = 0; e < A.count; ++e) {
    const double s = A.normals[e].dot(c - A.vertices[e]);
    if (s > reach) return setApart(k, false, e, s, reach);
    if (s > separation) {
      runnerUp = separation;
      separation = s;
      face = e;
    } else if (s > runnerUp) {
      runnerUp = s;
    }
  }
  k.slack = tol.margin;
  const Vec2& v1 = A.vertices[face];
  const int next = (face + 1) % A.count;
  const Vec2& v2 = A.vertices[next];
  if (guards == SlackGuards::FeatureChoices) {
    // The centre moves by at most the pair's motion in A's frame, and so does each of these
    // decisions' value: the best face (against the runner-up: halved), inside or not, and
    // which side of each end of the face. Whether the disc is within reach is left to the
    // measure (a disc out of reach measures no overlap, as "apart" gives none).
    const Vec2 along = v2 - v1;
    const double length = along.norm();
    const double beyondV1 = (c - v1).dot(along) / length, beyondV2 = (v2 - c).dot(along) / length;
    k.slack = std::max(tol.margin, std::min({0.5 * (separation - runnerUp), std::abs(separation - tol.inside),
                                             std::abs(beyondV1), std::abs(beyondV2)}));
  }
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
  return separationAlongAxis(PolygonFeatureTable::of(A), pa, PolygonFeatureTable::of(B), pb, k);
}

double separationAlongAxis(const PolygonFeatureTable& ta, const Pose& pa, const PolygonFeatureTable& tb,
                           const Pose& pb, const CachedContact& k) {
  const PolygonFeatureTable& ref = k.axisOnB ? tb : ta;
  const PolygonFeatureTable& other = k.axisOnB ? ta : tb;
  const int count = other.count;
  const Frame f = k.axisOnB ? relative(pb, pa) : relative(pa, pb);
  // The one face's separation: n·w − n·v_e over the other polygon's vertices.
  const int e = k.reference;
  double least = std::numeric_limits<double>::infinity();
  for (int v = 0; v < count; ++v) {
    const double x = f.d.x() + f.c * other.vx[v] - f.s * other.vy[v];
    const double y = f.d.y() + f.s * other.vx[v] + f.c * other.vy[v];
    least = std::min(least, ref.nx[e] * x + ref.ny[e] * y - ref.offset[e]);
  }
  return least;
}

}  // namespace grainlab

#pragma once
// Which features of two convex polygons, or of a polygon and a disc, are in contact:
// grainlab's own separating-axis test, in double precision.
//
// It takes Box2D's decisions by Box2D's rules (b2CollidePolygons and
// b2CollidePolygonAndCircle, v2.4), so Box2D stays the reference it is tested against
// (tests/engine/polygon_features_test.cpp), but without float rounding and without Box2D's
// polygon skin:
//  - a pair is in contact if no face of either polygon separates them by more than the
//    speculative margin (`FeatureTolerances::reach`);
//  - the reference face is A's best separating face, unless B's separates by more than
//    `referenceTolerance` more (Box2D favours the first body's face by 0.1 b2_linearSlop);
//  - the incident edge is the other polygon's edge most anti-parallel to the reference normal;
//  - the incident edge, clipped to the reference face's span widened by the margin, must
//    come within the margin of the face.
// A disc touches a face, or (past a face's end) a vertex.
//
// What it returns are features, not forces: the collider (polygon_collider.hpp) measures the
// depths and points of those features every step.
#include <cmath>

#include "grainlab/math.hpp"
#include "grainlab/shape.hpp"

namespace grainlab {

/// Where a body is: centre and the cosine and sine of its angle (computed once per step).
struct Pose {
  Vec2 x;
  double c, s;
};

/// One pair's features, and the poses they were found at (so the collider can tell how far
/// the pair has moved since).
struct CachedContact {
  enum class Kind : unsigned char { None, Apart, FaceA, FaceB, VertexDisc };
  Kind kind = Kind::None;  ///< None: nothing found yet
  bool axisOnB = false;    ///< Apart: the separating face is B's (polygon pairs)
  int reference = 0;       ///< FaceA/B: the reference face; VertexDisc: the vertex; Apart: the separating face
  int incident = 0;        ///< the other polygon's incident edge (polygon pairs)
  double slack = 0;        ///< m: relative motion the features tolerate
  double lever = 0;        ///< m: |x_B − x_A|₁ + r_A + r_B when found (how far a turn moves a point)
  Vec2 offset;             ///< x_B − x_A when found
  double ca = 1, sa = 0, cb = 1, sb = 0;  ///< both rotations when found
};

/// Tolerances in metres: Box2D's, divided by the scale at which Box2D would see the particles.
struct FeatureTolerances {
  double margin;              ///< per polygon (Box2D's m_radius): a polygon pair reaches 2×, a disc rb + 1×
  double referenceTolerance;  ///< 0.1 b2_linearSlop: how much a B face must beat A's to be the reference
  double inside;              ///< b2_epsilon: a disc centre this close to a face counts as inside
  /// `lengthScale` (1/m) maps metres to Box2D units; 1 unit is about a particle's radius.
  static FeatureTolerances atScale(double lengthScale);
};

/// How far the pair has moved relative to itself since its features were found (the poses in
/// `k`): an upper bound on how far any point of either body has moved in the other's frame,
/// |Δ(x_B − x_A)| plus each turn's chord |Δ(c, s)| times the lever (L1 norms bound L2 ones).
inline double relativeMotion(const CachedContact& k, const Pose& pa, const Pose& pb) {
  const Vec2 d = (pb.x - pa.x) - k.offset;
  const double shift = std::abs(d.x()) + std::abs(d.y());
  const double turn = std::abs(pa.c - k.ca) + std::abs(pa.s - k.sa) + std::abs(pb.c - k.cb) + std::abs(pb.s - k.sb);
  return shift + (k.lever + shift) * turn;
}

/// A polygon's faces and vertices as the feature search reads them: structure of arrays,
/// padded to kMaxPolygonVertices slots (zeros past `count`), with each face's offset n·v_e
/// computed once (the expression the search used to evaluate per face per search, so its bits).
/// It carries what else the search reads of a polygon (its corner count and circumradius), so
/// that a search touches only the two tables: a search comes at a pair's rare event, when its
/// polygons' records are seldom in cache.
struct alignas(64) PolygonFeatureTable {
  double nx[kMaxPolygonVertices], ny[kMaxPolygonVertices], offset[kMaxPolygonVertices];
  double vx[kMaxPolygonVertices], vy[kMaxPolygonVertices];
  int count;
  double circumradius;
  static PolygonFeatureTable of(const Polygon& p);
};

/// Which decisions a contact's slack must guard. A fresh search also decides whether the pair
/// is still within reach; kept features answer that themselves where they are measured every
/// step, since a pair moved out of reach then measures no overlap, as a fresh search's "apart"
/// gives none. So the wide path (PolygonCollider::keepPolygonFeatures) leaves the reach out of
/// the slack and searches a touching pair again only when a face or edge choice could change.
enum class SlackGuards { EveryDecision, FeatureChoices };

/// Features of polygon A against polygon B (normal from A to B). Fills every field of `k`
/// except the poses (the caller anchors them), with a slack: how far the pair may move
/// (relativeMotion) before a fresh search could answer otherwise. For a pair apart, that is
/// its separation beyond the margin. For a contact, it is the smallest of the margins by which
/// each decision was taken (best face against the runner-up, A's face against B's, in reach
/// or not, which edge is incident), halved where both sides of a decision move; at least the
/// speculative margin, where Box2D's own tolerance takes over. With FeatureChoices the reach
/// is left out (SlackGuards).
void findPolygonFeatures(const Polygon& A, const Pose& pa, const Polygon& B, const Pose& pb,
                         const FeatureTolerances& tol, CachedContact& k);
/// The same search from both polygons' tables (PolygonCollider keeps them): the same answer,
/// bit for bit, without building them.
void findPolygonFeatures(const PolygonFeatureTable& ta, const Pose& pa, const PolygonFeatureTable& tb, const Pose& pb,
                         const FeatureTolerances& tol, CachedContact& k,
                         SlackGuards guards = SlackGuards::EveryDecision);

/// Features of polygon A against a disc of radius rb centred at xb.
/// Its slack: the speculative margin (every decision, the baseline), or with FeatureChoices the
/// smallest margin of the best face, of inside or not, and of the face's two ends, at least
/// the speculative margin.
void findDiscFeatures(const Polygon& A, const Pose& pa, const Vec2& xb, double rb, const FeatureTolerances& tol,
                      CachedContact& k, SlackGuards guards = SlackGuards::EveryDecision);

/// An Apart polygon pair's separation along its cached separating face now (temporal
/// coherence: a pair that stays apart is re-checked with one face instead of all of both).
double separationAlongAxis(const Polygon& A, const Pose& pa, const Polygon& B, const Pose& pb,
                           const CachedContact& k);
/// The same, from the polygons' tables.
double separationAlongAxis(const PolygonFeatureTable& ta, const Pose& pa, const PolygonFeatureTable& tb,
                           const Pose& pb, const CachedContact& k);

}  // namespace grainlab

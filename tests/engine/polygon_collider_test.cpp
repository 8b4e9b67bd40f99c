// The polygon narrow phase's reuse of Box2D's features (engine/src/polygon_collider.hpp):
// a kept answer must agree with a fresh one as long as the pair has moved less than the
// slack the answer carries, and a pair must be asked of Box2D again once it moves more.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "polygon_collider.hpp"

namespace grainlab {
namespace {

// An elongated hexagon inscribed in an ellipse of aspect ratio 1.5, as in the specimens.
Polygon hexagon(double longAxis) {
  std::vector<Vec2> v;
  const double a = 0.5 * longAxis, b = a / 1.5;
  for (int k = 0; k < 6; ++k) v.emplace_back(a * std::cos(k * kPi / 3), b * std::sin(k * kPi / 3));
  return makePolygon(v);
}

Pose pose(Vec2 x, double angle) { return {x, std::cos(angle), std::sin(angle)}; }

struct Fixture {
  Polygon A = hexagon(0.005), B = hexagon(0.0045);
  PolygonCollider collider{1.0 / 0.0025};
  int a = collider.add(A), b = collider.add(B);
};

// B placed against A along a random direction, overlapping by `overlap` (or apart by −overlap)
// to within the bisection's resolution.
Pose touching(Fixture& f, const Pose& pa, double angleB, double direction, double overlap) {
  const Vec2 u(std::cos(direction), std::sin(direction));
  double lo = 0, hi = 0.01;  // centre distance: overlapping at lo, apart at hi
  for (int it = 0; it < 80; ++it) {
    const double mid = 0.5 * (lo + hi);
    const bool overlapping = f.collider.collidePolygons(f.a, pa, f.b, pose(pa.x + mid * u, angleB)).overlap > 0;
    (overlapping ? lo : hi) = mid;
  }
  return pose(pa.x + (lo - overlap) * u, angleB);
}

// B moved from pb by a random translation and turn, scaled so that the pair's motion
// (relativeMotion, which the cache uses) is `fraction` of the kept slack.
Pose movedWithin(const CachedContact& kept, const Pose& pa, const Pose& pb, double fraction, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double dir = 2 * kPi * unit(rng), share = unit(rng), sign = unit(rng) < 0.5 ? -1 : 1;
  const double angle = std::atan2(pb.s, pb.c);
  auto at = [&](double scale) {
    // A turn of 1 rad and a shift of one lever, mixed by `share`, times `scale`.
    return pose(pb.x + scale * (1 - share) * kept.lever * Vec2(std::cos(dir), std::sin(dir)),
                angle + sign * scale * share);
  };
  double lo = 0, hi = 1;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (relativeMotion(kept, pa, at(mid)) < fraction * kept.slack ? lo : hi) = mid;
  }
  return at(lo);
}

TEST(PolygonCollider, KeptFeaturesAgreeWithFreshOnesWithinTheSlack) {
  Fixture f;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0, identical = 0, decided = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Pose pa = pose(Vec2(0.1, -0.05), 2 * kPi * unit(rng));
    const double overlap = 1e-6 * (0.5 + 9.5 * unit(rng));  // 1e-4 .. 2e-3 of the size
    const Pose pb = touching(f, pa, 2 * kPi * unit(rng), 2 * kPi * unit(rng), overlap);
    CachedContact kept;
    const ContactGeometry first = f.collider.collidePolygons(f.a, pa, f.b, pb, &kept);
    ASSERT_GT(first.overlap, 0);
    const Pose moved = movedWithin(kept, pa, pb, 0.99, rng);
    const long long before = f.collider.featureSearches();
    const ContactGeometry reused = f.collider.collidePolygons(f.a, pa, f.b, moved, &kept);
    EXPECT_EQ(f.collider.featureSearches(), before) << "within the slack, the features must not be searched again";
    const ContactGeometry fresh = f.collider.collidePolygons(f.a, pa, f.b, moved);
    const bool same = reused.overlap == fresh.overlap && reused.point == fresh.point && reused.normal == fresh.normal;
    if (kept.slack > f.collider.tolerances().margin) {
      // The slack came from the decisions' own margins: a fresh search must decide the same.
      ++decided;
      EXPECT_TRUE(same) << "trial " << trial << ": kept " << reused.overlap << ", fresh " << fresh.overlap;
      continue;
    }
    // Decisions tied within the speculative margin: the features can differ only where a
    // fresh search would now switch faces; the depth then differs by at most Box2D's own face
    // tolerance plus twice the motion.
    ++compared;
    const double tolerance = f.collider.tolerances().referenceTolerance + 2 * kept.slack;
    EXPECT_LE(std::abs(std::max(reused.overlap, 0.0) - std::max(fresh.overlap, 0.0)), tolerance);
    identical += same;
  }
  // Most contacts are decided by margins wider than the speculative one, and among the rest
  // feature switches are rare events.
  EXPECT_GT(decided, 1000);
  EXPECT_GE(identical, 0.98 * compared);
}

// The wide path keeps a touching pair's features until a face or edge choice could change
// (SlackGuards::FeatureChoices), not until the pair could leave the speculative reach: the
// kept features are measured every step, and a pair moved out of reach must measure no
// contact, as a fresh search's "apart" gives none. Within that longer slack the kept answer
// must still be a fresh one's, bit for bit, touching or not.
TEST(PolygonCollider, FeaturesKeptForTheirChoicesAloneMeasureAsFreshOnes) {
  Fixture f;
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int decided = 0, longer = 0, separated = 0, stillTouching = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Pose pa = pose(Vec2(0.1, -0.05), 2 * kPi * unit(rng));
    const double overlap = 1e-6 * (0.5 + 9.5 * unit(rng));
    const Pose pb = touching(f, pa, 2 * kPi * unit(rng), 2 * kPi * unit(rng), overlap);
    CachedContact everyDecision, kept;
    f.collider.collidePolygons(f.a, pa, f.b, pb, &everyDecision);
    ASSERT_TRUE(f.collider.keepPolygonFeatures(f.a, pa, f.b, pb, kept));
    // The same features; a slack at least as long, longer where the reach decided it.
    ASSERT_EQ(kept.kind, everyDecision.kind);
    ASSERT_EQ(kept.reference, everyDecision.reference);
    ASSERT_EQ(kept.incident, everyDecision.incident);
    ASSERT_GE(kept.slack, everyDecision.slack);
    if (kept.slack <= f.collider.tolerances().margin) continue;  // tied choices: the test above
    ++decided;
    longer += kept.slack > everyDecision.slack;
    const Pose moved = movedWithin(kept, pa, pb, 0.99, rng);
    const long long before = f.collider.featureSearches();
    const bool faceEdge = f.collider.keepPolygonFeatures(f.a, pa, f.b, moved, kept);
    EXPECT_EQ(f.collider.featureSearches(), before) << "within the slack, the features must not be searched again";
    EXPECT_TRUE(faceEdge);
    const ContactGeometry reused = f.collider.collidePolygons(f.a, pa, f.b, moved, &kept);
    const ContactGeometry fresh = f.collider.collidePolygons(f.a, pa, f.b, moved);
    EXPECT_EQ(reused.overlap, fresh.overlap) << "trial " << trial;
    EXPECT_EQ(reused.point, fresh.point) << "trial " << trial;
    EXPECT_EQ(reused.normal, fresh.normal) << "trial " << trial;
    (fresh.overlap > 0 ? stillTouching : separated) += 1;
  }
  // Most contacts' slack was set by the reach, and the longer one takes many pairs out of it.
  EXPECT_GT(decided, 1000);
  EXPECT_GT(longer, decided / 2);
  EXPECT_GT(separated, 100);
  EXPECT_GT(stillTouching, 100);
}

TEST(PolygonCollider, PairKeptApartCannotTouchWithinItsGap) {
  Fixture f;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const Pose pa = pose(Vec2(-0.2, 0.3), 2 * kPi * unit(rng));
    const double gap = 1e-6 * (0.1 + 50 * unit(rng));
    const Pose pb = touching(f, pa, 2 * kPi * unit(rng), 2 * kPi * unit(rng), -gap);
    CachedContact kept;
    ASSERT_LE(f.collider.collidePolygons(f.a, pa, f.b, pb, &kept).overlap, 0);
    // Within the speculative margin Box2D answers with features; this test is about the rest.
    if (kept.kind != CachedContact::Kind::Apart) continue;
    // The slack is the gap along the best separating axis: no larger than the distance.
    EXPECT_LE(kept.slack, gap * (1 + 1e-6) + 1e-12);
    // Move B toward A by just under the slack (in the L1 measure the cache uses): still apart,
    // without asking Box2D.
    const Vec2 d = pa.x - pb.x;
    const Vec2 toward = d / (std::abs(d.x()) + std::abs(d.y()));
    const Pose moved = pose(pb.x + 0.999 * kept.slack * toward, std::atan2(pb.s, pb.c));
    const long long before = f.collider.featureSearches();
    EXPECT_LE(f.collider.collidePolygons(f.a, pa, f.b, moved, &kept).overlap, 0);
    EXPECT_EQ(f.collider.featureSearches(), before);
    EXPECT_LE(f.collider.collidePolygons(f.a, pa, f.b, moved).overlap, 0) << "a fresh answer agrees";
  }
}

TEST(PolygonCollider, MovingBeyondTheSlackSearchesAgain) {
  Fixture f;
  const Pose pa = pose(Vec2(0, 0), 0.0);
  const Pose pb = touching(f, pa, 0.4, 0.1, 1e-6);
  CachedContact kept;
  f.collider.collidePolygons(f.a, pa, f.b, pb, &kept);
  const long long before = f.collider.featureSearches();
  const Pose moved = pose(pb.x + Vec2(1.01 * kept.slack, 0), 0.4);
  const ContactGeometry g = f.collider.collidePolygons(f.a, pa, f.b, moved, &kept);
  EXPECT_EQ(f.collider.featureSearches(), before + 1);
  const ContactGeometry fresh = f.collider.collidePolygons(f.a, pa, f.b, moved);
  EXPECT_EQ(g.overlap, fresh.overlap);
  EXPECT_EQ(g.point, fresh.point);
}

// The same for a disc against a polygon: the wide path's slack guards the best face, inside
// or not and which side of each end of the face the centre is, and leaves the reach to the
// measure. Within that slack the kept answer must be a fresh one's, bit for bit.
TEST(PolygonCollider, DiscFeaturesKeptForTheirChoicesAloneMeasureAsFreshOnes) {
  Fixture f;
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int decided = 0, longer = 0, separated = 0, onFace = 0, onVertex = 0, inside = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Pose pa = pose(Vec2(-0.03, 0.02), 2 * kPi * unit(rng));
    const double toward = 2 * kPi * unit(rng);
    const Vec2 dir(std::cos(toward), std::sin(toward));
    // Half the trials a disc just touching, as in a packing; half a larger one whose centre is
    // anywhere within the polygon's reach, inside it too (the nearest face decides there).
    const bool touchingDisc = trial % 2 == 0;
    const double rb = touchingDisc ? 0.0008 : 0.003;
    Vec2 xb;
    if (touchingDisc) {
      double lo = 0, hi = 0.01;  // centre distance: overlapping at lo, apart at hi
      for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        (f.collider.collidePolygonDisc(f.a, pa, pa.x + mid * dir, rb).overlap > 0 ? lo : hi) = mid;
      }
      xb = pa.x + (lo - 1e-6 * (0.5 + 9.5 * unit(rng))) * dir;
    } else {
      xb = pa.x + 0.003 * unit(rng) * dir;
    }
    CachedContact everyDecision, kept;
    f.collider.collidePolygonDisc(f.a, pa, xb, rb, &everyDecision);
    f.collider.collidePolygonDisc(f.a, pa, xb, rb, &kept, SlackGuards::FeatureChoices);
    ASSERT_EQ(kept.kind, everyDecision.kind);
    ASSERT_EQ(kept.reference, everyDecision.reference);
    ASSERT_GE(kept.slack, everyDecision.slack);
    if (kept.slack <= f.collider.tolerances().margin) continue;  // tied choices
    ++decided;
    longer += kept.slack > everyDecision.slack;
    // The disc moved within 99 % of the slack (its motion is the centre's, plus A's turn times
    // the lever), in a random direction: toward, along or away from the polygon.
    const double share = unit(rng), angle = std::atan2(pa.s, pa.c), direction = 2 * kPi * unit(rng);
    auto at = [&](double scale) {
      return std::pair{Vec2(xb + scale * (1 - share) * kept.lever * Vec2(std::cos(direction), std::sin(direction))),
                       pose(pa.x, angle + scale * share)};
    };
    double s0 = 0, s1 = 1;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (s0 + s1);
      const auto [x, p] = at(mid);
      (relativeMotion(kept, p, Pose{x, 1.0, 0.0}) < 0.99 * kept.slack ? s0 : s1) = mid;
    }
    const auto [xm, pm] = at(s0);
    const long long before = f.collider.featureSearches();
    const ContactGeometry reused = f.collider.collidePolygonDisc(f.a, pm, xm, rb, &kept, SlackGuards::FeatureChoices);
    EXPECT_EQ(f.collider.featureSearches(), before) << "within the slack, the features must not be searched again";
    const ContactGeometry fresh = f.collider.collidePolygonDisc(f.a, pm, xm, rb);
    EXPECT_EQ(reused.overlap, fresh.overlap) << "trial " << trial;
    EXPECT_EQ(reused.point, fresh.point) << "trial " << trial;
    EXPECT_EQ(reused.normal, fresh.normal) << "trial " << trial;
    if (fresh.overlap <= 0) ++separated;
    else (kept.kind == CachedContact::Kind::VertexDisc ? onVertex : onFace) += 1;
    inside += fresh.overlap > rb;  // the centre inside the polygon
  }
  EXPECT_GT(decided, 2000);
  EXPECT_GT(longer, decided / 2);
  EXPECT_GT(separated, 100);
  EXPECT_GT(onFace, 100);
  EXPECT_GT(onVertex, 20);
  EXPECT_GT(inside, 100);
}

TEST(PolygonCollider, DiscAgainstFaceAndVertexMatchesTheGeometry) {
  Fixture f;
  const Pose pa = pose(Vec2(0, 0), 0.0);
  const double r = 0.002, overlap = 3e-6;
  // Face: the hexagon's top face is at y = b sin 60° (b = a / 1.5) for |x| < a/2.
  const double top = 0.0025 / 1.5 * std::sin(kPi / 3);
  ContactGeometry g = f.collider.collidePolygonDisc(f.a, pa, Vec2(0.0003, top + r - overlap), r);
  EXPECT_NEAR(g.overlap, overlap, 1e-12);
  EXPECT_NEAR(g.normal.y(), 1.0, 1e-12);
  // Vertex: the hexagon's tip at (a, 0), the disc beyond it along +x.
  g = f.collider.collidePolygonDisc(f.a, pa, Vec2(0.0025 + r - overlap, 0), r);
  EXPECT_NEAR(g.overlap, overlap, 1e-12);
  EXPECT_NEAR(g.normal.x(), 1.0, 1e-9);
  EXPECT_NEAR(g.point.x(), 0.0025 - 0.5 * overlap, 1e-12);
}

}  // namespace
}  // namespace grainlab

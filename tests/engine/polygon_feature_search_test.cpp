// The feature search made cheaper must answer exactly as it did (engine/src/polygon_features.hpp):
// which step a near tie is decided at decides a run's bits, so every field of the CachedContact
// it returns (kind, axisOnB, reference, incident, slack) must equal, bit for bit, what the
// search of grainlab 465684a returned (copied below as the reference), on random polygon pairs
// and polygon-disc pairs: overlapping, touching, near-touching (on either side of the speculative
// margin), apart, and exact ties (parallel faces, symmetric placements of regular polygons at
// angles whose cosine and sine are exact). Both contact paths (GRAINLAB_SIMD) are checked, the
// wide one (whose scans run several faces per instruction) on every instruction set.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "polygon_collider.hpp"
#include "polygon_features.hpp"
#include "wide_path_support.hpp"

namespace grainlab {
namespace {

// ---- the reference: polygon_features.cpp as of 465684a, unchanged but for its namespace ----
namespace reference {

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
double faceSeparation(const Polygon& ref, int e, const Vec2* w, int count) {
  const Vec2& n = ref.normals[e];
  const double offset = n.dot(ref.vertices[e]);
  double least = std::numeric_limits<double>::infinity();
  for (int v = 0; v < count; ++v) least = std::min(least, n.dot(w[v]) - offset);
  return least;
}
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

void findPolygonFeatures(const Polygon& A, const Pose& pa, const Polygon& B, const Pose& pb,
                         const FeatureTolerances& tol, CachedContact& k) {
  const double reach = 2 * tol.margin;
  const Frame ba = relative(pa, pb), ab = relative(pb, pa);
  Vec2 wb[kMaxPolygonVertices], wa[kMaxPolygonVertices];
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
  const Frame& f = onB ? ab : ba;
  const Vec2* w = onB ? wa : wb;
  const int e = onB ? faceB : faceA;
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
  const Vec2 t = perp(n);
  const Vec2& v1 = R.vertices[e];
  const Vec2& v2 = R.vertices[(e + 1) % R.count];
  Vec2 seg[2] = {w[incident], w[(incident + 1) % I.count]};
  const bool spans = clipSegment(seg, -t, -t.dot(v1) + reach) && clipSegment(seg, t, t.dot(v2) + reach);
  const double front = n.dot(v1);
  if (!spans || std::min(n.dot(seg[0]), n.dot(seg[1])) - front > reach) {
    return setApart(k, onB, e, reach, reach);
  }
  k.kind = onB ? CachedContact::Kind::FaceB : CachedContact::Kind::FaceA;
  k.reference = e;
  k.incident = incident;
  const double lever = std::abs(pb.x.x() - pa.x.x()) + std::abs(pb.x.y() - pa.x.y()) + A.circumradius + B.circumradius;
  const double bestFace = 0.5 * ((onB ? separationB - runnerUpB : separationA - runnerUpA));
  const double referenceMargin = 0.5 * std::abs(separationB - separationA - tol.referenceTolerance);
  const double inReach = reach - std::max(separationA, separationB);
  const double incidentEdge = 0.5 * (nextLeast - least) * lever;
  k.slack = std::max(tol.margin, std::min({bestFace, referenceMargin, inReach, incidentEdge}));
}

void findDiscFeatures(const Polygon& A, const Pose& pa, const Vec2& xb, double rb, const FeatureTolerances& tol,
                      CachedContact& k) {
  const double reach = tol.margin + rb;
  const Vec2 dx = xb - pa.x;
  const Vec2 c(pa.c * dx.x() + pa.s * dx.y(), -pa.s * dx.x() + pa.c * dx.y());
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
  if (separation < tol.inside) return faceContact();
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

}  // namespace reference

// ---- the comparison ----
constexpr double kSize = 0.0025;  // m: circumradius of the typical polygon
constexpr double kScale = 1.0 / kSize;
using Kind = CachedContact::Kind;

Pose pose(const Vec2& x, double angle) { return {x, std::cos(angle), std::sin(angle)}; }

// A contact filled with values no search writes, so that a field one search leaves alone and
// the other sets shows up.
CachedContact blank() {
  CachedContact k;
  k.kind = Kind::None;
  k.axisOnB = true;
  k.reference = -7;
  k.incident = -9;
  k.slack = -3.25;
  return k;
}

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// Every field a search writes, bit for bit; a message naming the first that differs.
::testing::AssertionResult sameContact(const CachedContact& got, const CachedContact& want) {
  if (got.kind != want.kind) return ::testing::AssertionFailure() << "kind " << int(got.kind) << " vs " << int(want.kind);
  if (got.axisOnB != want.axisOnB) return ::testing::AssertionFailure() << "axisOnB " << got.axisOnB << " vs " << want.axisOnB;
  if (got.reference != want.reference)
    return ::testing::AssertionFailure() << "reference " << got.reference << " vs " << want.reference;
  if (got.incident != want.incident)
    return ::testing::AssertionFailure() << "incident " << got.incident << " vs " << want.incident;
  if (bits(got.slack) != bits(want.slack))
    return ::testing::AssertionFailure() << "slack " << got.slack << " vs " << want.slack;
  return ::testing::AssertionSuccess();
}

struct Random {
  std::mt19937_64 rng{32};
  double uniform(double a = 0, double b = 1) { return std::uniform_real_distribution<double>(a, b)(rng); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }
  // 3-8 vertices: an elongated hexagon (as in the specimens), a regular polygon (exact
  // symmetries), or vertices at random angles on a random ellipse.
  Polygon polygon() {
    const double u = uniform();
    if (u < 0.3) return test::ellipseHexagon(2 * kSize * uniform(0.7, 1.2));
    if (u < 0.5) return test::regularPolygon(integer(3, 8), kSize * uniform(0.7, 1.2));
    std::vector<Vec2> v;
    const double a = kSize * uniform(0.7, 1.2), b = a / uniform(1.0, 2.0);
    const int count = integer(3, 8);
    for (int k = 0; k < count; ++k) {
      const double angle = 2 * kPi * (k + uniform(-0.3, 0.3)) / count;
      v.emplace_back(a * std::cos(angle), b * std::sin(angle));
    }
    return makePolygon(v);
  }
  // An angle, a third of the time one whose cosine and sine are exact (multiples of 90°), so
  // faces are exactly parallel and separations tie exactly.
  Pose pose(const Vec2& x) {
    if (uniform() < 0.33) {
      static const double c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
      const int q = integer(0, 3);
      return {x, c[q], s[q]};
    }
    return grainlab::pose(x, uniform(0, 2 * kPi));
  }
};

// Calls f(label) on each path the search can take: the baseline and, where built, the wide one
// with every instruction set Highway compiled that this CPU has (its scans run several faces per
// instruction: vectors of 1, 2, 4 and 8 doubles).
template <class F>
void onEveryPath(const F& f) {
  overrideSimdPath(SimdPath::Baseline);
  f(std::string("baseline"));
  overrideSimdPath(std::nullopt);
  if (test::wideSimdBuilt()) test::onEveryWideTarget([&](const std::string& target) { f("wide " + target); });
}

struct Counts {
  int apart = 0, faceA = 0, faceB = 0, vertex = 0, besideFace = 0;
  void add(const CachedContact& k, double reach) {
    apart += k.kind == Kind::Apart;
    faceA += k.kind == Kind::FaceA;
    faceB += k.kind == Kind::FaceB;
    vertex += k.kind == Kind::VertexDisc;
    besideFace += k.kind == Kind::Apart && k.slack == 0 && reach > 0;
  }
};

// The pair through every entry point (every path and instruction set, with and without the
// collider's tables), against the reference; for an apart pair, separationAlongAxis too.
class Checker {
 public:
  Checker() : collider_(kScale), tol_(collider_.tolerances()) {}
  const FeatureTolerances& tol() const { return tol_; }

  ::testing::AssertionResult polygons(const Polygon& A, const Pose& pa, const Polygon& B, const Pose& pb,
                                      CachedContact* found = nullptr) {
    CachedContact want = blank();
    reference::findPolygonFeatures(A, pa, B, pb, tol_, want);
    const PolygonFeatureTable ta = PolygonFeatureTable::of(A), tb = PolygonFeatureTable::of(B);
    ::testing::AssertionResult result = ::testing::AssertionSuccess();
    onEveryPath([&](const std::string& path) {
      if (!result) return;
      CachedContact got = blank();
      findPolygonFeatures(ta, pa, tb, pb, tol_, got);
      CachedContact viaPolygons = blank();
      findPolygonFeatures(A, pa, B, pb, tol_, viaPolygons);
      if (auto r = sameContact(got, want); !r) {
        result = r << " (tables, " << path << ")";
      } else if (auto q = sameContact(viaPolygons, want); !q) {
        result = q << " (polygons, " << path << ")";
      } else if (want.kind == Kind::Apart) {
        const double s = separationAlongAxis(ta, pa, tb, pb, want);
        const double r = reference::separationAlongAxis(A, pa, B, pb, want);
        if (bits(s) != bits(r)) {
          result = ::testing::AssertionFailure() << "separationAlongAxis " << s << " vs " << r << " (" << path << ")";
        }
      }
    });
    if (!result) return result;
    if (found) *found = want;
    return ::testing::AssertionSuccess();
  }

  ::testing::AssertionResult disc(const Polygon& A, const Pose& pa, const Vec2& xb, double rb,
                                  CachedContact* found = nullptr) {
    CachedContact want = blank();
    reference::findDiscFeatures(A, pa, xb, rb, tol_, want);
    ::testing::AssertionResult result = ::testing::AssertionSuccess();
    onEveryPath([&](const std::string& path) {
      CachedContact got = blank();
      findDiscFeatures(A, pa, xb, rb, tol_, got);
      if (auto r = sameContact(got, want); !r && result) result = r << " (" << path << ")";
    });
    if (!result) return result;
    if (found) *found = want;
    return ::testing::AssertionSuccess();
  }

 private:
  PolygonCollider collider_;
  FeatureTolerances tol_;
};

// The centre distance along u at which the reference's answer turns from a contact to apart
// (bisection), so that pairs can be placed just either side of the speculative margin.
double contactEdge(const std::function<bool(double)>& touches) {
  double lo = 0, hi = 8 * kSize;
  for (int it = 0; it < 70; ++it) {
    const double mid = 0.5 * (lo + hi);
    (touches(mid) ? lo : hi) = mid;
  }
  return lo;
}

TEST(PolygonFeatureSearch, EqualsTheReferenceOnRandomPolygonPairs) {
  Random r;
  Checker check;
  Counts counts;
  const double reach = 2 * check.tol().margin;
  for (int trial = 0; trial < 60000; ++trial) {
    const Polygon A = r.polygon(), B = r.polygon();
    const Pose pa = r.pose(Vec2(r.uniform(-1, 1), r.uniform(-1, 1)));
    const Pose orientation = r.pose(Vec2::Zero());
    const double dir = r.uniform(0, 2 * kPi);
    const Vec2 u(std::cos(dir), std::sin(dir));
    auto at = [&](double distance) { return Pose{pa.x + distance * u, orientation.c, orientation.s}; };
    double distance;
    switch (trial % 3) {
      case 0:  // anywhere from deep overlap to well apart
        distance = kSize * r.uniform(0.2, 3.0);
        break;
      default: {  // within 1e-12 to 1e-2 of the size of where the contact begins, either side
        const double edge = contactEdge([&](double d) {
          CachedContact k;
          reference::findPolygonFeatures(A, pa, B, at(d), check.tol(), k);
          return k.kind != Kind::Apart;
        });
        distance = edge + kSize * std::pow(10.0, r.uniform(-12, -2)) * (r.uniform() < 0.5 ? -1 : 1);
      }
    }
    CachedContact k;
    ASSERT_TRUE(check.polygons(A, pa, B, at(distance), &k)) << "trial " << trial;
    counts.add(k, reach);
  }
  std::printf("random polygon pairs: apart %d (beside a face %d), face A %d, face B %d\n", counts.apart,
              counts.besideFace, counts.faceA, counts.faceB);
  EXPECT_GT(counts.faceA, 10000);
  EXPECT_GT(counts.faceB, 3000);
  EXPECT_GT(counts.apart, 10000);
}

// Exact ties: regular polygons at right angles (exact cosines and sines) on a grid of exact
// offsets, where faces are exactly parallel and separations exactly equal: the first face of
// equals, the runner-up equal to the best, A's face against B's decided by the tolerance alone.
TEST(PolygonFeatureSearch, EqualsTheReferenceOnExactTies) {
  Checker check;
  Counts counts;
  int tiedBest = 0;
  const double reach = 2 * check.tol().margin;
  for (int na = 3; na <= 8; ++na) {
    for (int nb = 3; nb <= 8; ++nb) {
      const Polygon A = test::regularPolygon(na, kSize), B = test::regularPolygon(nb, kSize);
      for (int qa = 0; qa < 4; ++qa) {
        for (int qb = 0; qb < 4; ++qb) {
          static const double c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
          const Pose pa{Vec2(0.25, -0.5), c[qa], s[qa]};
          for (int ix = -8; ix <= 8; ++ix) {
            for (int iy = -8; iy <= 8; ++iy) {
              // Offsets of a quarter of the size: exact in binary, touching, overlapping, apart.
              const Pose pb{pa.x + Vec2(ix * kSize / 4, iy * kSize / 4), c[qb], s[qb]};
              CachedContact k;
              ASSERT_TRUE(check.polygons(A, pa, B, pb, &k)) << na << " " << nb << " " << qa << qb << " " << ix << iy;
              counts.add(k, reach);
              ASSERT_TRUE(check.polygons(B, pb, A, pa)) << nb << " " << na << " " << qb << qa << " " << ix << iy;
              tiedBest += k.kind != Kind::Apart && k.kind != Kind::None && k.slack == check.tol().margin;
            }
          }
        }
      }
    }
  }
  std::printf("exact ties: apart %d, face A %d, face B %d, kept at the margin %d\n", counts.apart, counts.faceA,
              counts.faceB, tiedBest);
  EXPECT_GT(counts.faceA + counts.faceB, 1000);
}

TEST(PolygonFeatureSearch, EqualsTheReferenceOnRandomPolygonDiscPairs) {
  Random r;
  Checker check;
  Counts counts;
  for (int trial = 0; trial < 40000; ++trial) {
    const Polygon A = r.polygon();
    const Pose pa = r.pose(Vec2(r.uniform(-1, 1), r.uniform(-1, 1)));
    const double rb = kSize * r.uniform(0.3, 1.2);
    Vec2 u;
    if (trial % 2) {
      const double dir = r.uniform(0, 2 * kPi);
      u = Vec2(std::cos(dir), std::sin(dir));
    } else {  // aimed near a vertex, or exactly along a face normal (ties between regions)
      const int v = r.integer(0, A.count - 1);
      const Vec2 toward = trial % 4 ? A.vertices[v] : A.normals[v];
      u = Vec2(pa.c * toward.x() - pa.s * toward.y(), pa.s * toward.x() + pa.c * toward.y()).normalized();
    }
    double distance;
    if (trial % 3 == 0) {
      distance = kSize * r.uniform(0, 3.0);
    } else {
      const double edge = contactEdge([&](double d) {
        CachedContact k;
        reference::findDiscFeatures(A, pa, pa.x + d * u, rb, check.tol(), k);
        return k.kind != Kind::Apart;
      });
      distance = edge + kSize * std::pow(10.0, r.uniform(-12, -2)) * (r.uniform() < 0.5 ? -1 : 1);
    }
    CachedContact k;
    ASSERT_TRUE(check.disc(A, pa, pa.x + distance * u, rb, &k)) << "trial " << trial;
    counts.add(k, 0);
  }
  std::printf("random polygon-disc pairs: apart %d, face %d, vertex %d\n", counts.apart, counts.faceA, counts.vertex);
  EXPECT_GT(counts.vertex, 2000);
  EXPECT_GT(counts.faceA, 5000);
  EXPECT_GT(counts.apart, 5000);
}

}  // namespace
}  // namespace grainlab

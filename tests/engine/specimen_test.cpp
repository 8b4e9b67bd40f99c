// The specimen generator against the paper's Section 4 and the geometry: tolerances come
// from the shapes and from double rounding, never from what the code happened to print.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/errors.hpp"
#include "grainlab/specimen.hpp"
#include "neighbour_index_gaps.hpp"
// Private to the engine, reached by path: the grading solve and the ring condition are the
// generator's own functions, and this test is theirs too.
#include "../../engine/src/specimen_grading.hpp"
#include "../../engine/src/specimen_ring.hpp"

namespace grainlab {
namespace {

using Recipe = SpecimenRecipe;

// The paper's long axes, m, written as the recipe's defaults are (4.5 * 1e-3 is not 0.0045).
const std::vector<double> kPaperAxes{0.0045, 0.0050, 0.0070};

Recipe discs(double diameter = 0.160) {
  Recipe r;
  r.specimenDiameter = diameter;
  return r;
}

Recipe elongated(double diameter = 0.160, Recipe::Orientation o = Recipe::Orientation::Random, double alphaDeg = 0) {
  Recipe r;
  r.shape = Recipe::Shape::Elongated;
  r.specimenDiameter = diameter;
  r.orientation = o;
  r.beddingAngle = radians(alphaDeg);
  return r;
}

std::span<const ParticleSpec> specimenOf(const Specimen& s) {
  return std::span<const ParticleSpec>(s.particles).first(static_cast<std::size_t>(s.specimenCount));
}
std::span<const ParticleSpec> ringOf(const Specimen& s) {
  return std::span<const ParticleSpec>(s.particles).subspan(static_cast<std::size_t>(s.specimenCount));
}

std::vector<Vec2> worldVertices(const ParticleSpec& p) {
  std::vector<Vec2> out;
  for (const Vec2& v : p.vertices) out.push_back(p.position + rotate(v, p.angle));
  return out;
}

// The longest vertex-to-vertex distance of a polygon: its long axis L for an even count.
double longestDiagonal(const std::vector<Vec2>& v) {
  double d = 0;
  for (const Vec2& a : v) {
    for (const Vec2& b : v) d = std::max(d, (a - b).norm());
  }
  return d;
}

// --- An overlap test of its own, unlike the generator's separating axes: two convex
// polygons overlap iff an edge of one properly crosses an edge of the other or a vertex of
// one lies strictly inside the other. Touching is not overlapping.
int side(const Vec2& a, const Vec2& b, const Vec2& p) {
  const double c = cross(b - a, p - a);
  return (c > 0) - (c < 0);
}
bool strictlyInside(const Vec2& p, const std::vector<Vec2>& poly) {
  for (std::size_t k = 0; k < poly.size(); ++k) {
    if (side(poly[k], poly[(k + 1) % poly.size()], p) <= 0) return false;
  }
  return true;
}
bool properlyCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  return side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0;
}
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (a + t * (b - a) - p).norm();
}
bool overlap(const ParticleSpec& a, const ParticleSpec& b) {
  const bool discA = a.shape == ShapeKind::Disc, discB = b.shape == ShapeKind::Disc;
  if (discA && discB) return (a.position - b.position).norm() < a.radius + b.radius;
  if (discA != discB) {
    const ParticleSpec& d = discA ? a : b;
    const std::vector<Vec2> poly = worldVertices(discA ? b : a);
    if (strictlyInside(d.position, poly)) return true;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      if (distanceToSegment(d.position, poly[k], poly[(k + 1) % poly.size()]) < d.radius) return true;
    }
    return false;
  }
  const std::vector<Vec2> pa = worldVertices(a), pb = worldVertices(b);
  for (const Vec2& v : pa) if (strictlyInside(v, pb)) return true;
  for (const Vec2& v : pb) if (strictlyInside(v, pa)) return true;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    for (std::size_t j = 0; j < pb.size(); ++j) {
      if (properlyCross(pa[i], pa[(i + 1) % pa.size()], pb[j], pb[(j + 1) % pb.size()])) return true;
    }
  }
  return false;
}
double reachOf(const ParticleSpec& p) {
  if (p.shape == ShapeKind::Disc) return p.radius;
  double r = 0;
  for (const Vec2& v : p.vertices) r = std::max(r, v.norm());
  return r;
}
// Farthest point of the particle's outline from the origin (the specimen centre).
double outerReach(const ParticleSpec& p) {
  if (p.shape == ShapeKind::Disc) return p.position.norm() + p.radius;
  double r = 0;
  for (const Vec2& v : worldVertices(p)) r = std::max(r, v.norm());
  return r;
}

void expectNoOverlap(std::span<const ParticleSpec> a, std::span<const ParticleSpec> b, bool samePool) {
  int overlaps = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = samePool ? i + 1 : 0; j < b.size(); ++j) {
      const double reach = reachOf(a[i]) + reachOf(b[j]);
      if ((a[i].position - b[j].position).norm() >= reach) continue;
      if (overlap(a[i], b[j])) ++overlaps;
    }
  }
  EXPECT_EQ(overlaps, 0);
}

// --- The grading ---------------------------------------------------------------------

// The grading curve as the generator's header states it, written out again: (0, 0), then
// (L_i, cumulative fraction), linear between.
double finerSize(const std::vector<double>& axes, const std::vector<double>& f, double x) {
  std::vector<double> sizes{0}, finer{0};
  double cum = 0;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    cum += f[i];
    sizes.push_back(axes[i]);
    finer.push_back(cum);
  }
  for (std::size_t i = 1; i < sizes.size(); ++i) {
    if (finer[i] >= x) return sizes[i - 1] + (sizes[i] - sizes[i - 1]) * (x - finer[i - 1]) / (finer[i] - finer[i - 1]);
  }
  return sizes.back();
}

TEST(SpecimenGrading, SolvedFractionsMeetThePapersCoefficients) {
  const auto f = specimen::solveCountFractions(kPaperAxes);
  ASSERT_TRUE(f.has_value());
  ASSERT_EQ(f->size(), 3u);
  EXPECT_NEAR((*f)[0] + (*f)[1] + (*f)[2], 1.0, 1e-15);
  for (double x : *f) EXPECT_GT(x, 0.0);

  const double d10 = finerSize(kPaperAxes, *f, 0.1), d30 = finerSize(kPaperAxes, *f, 0.3),
               d60 = finerSize(kPaperAxes, *f, 0.6);
  // The solve stops when both residuals are below 1e-13.
  EXPECT_NEAR(d60 / d10, 1.35, 1e-12);
  EXPECT_NEAR(d30 * d30 / (d10 * d60), 1.2, 1e-12);

  // Closed form for the segments they fall on (D10 below 4.5 mm, D30 and D60 between 4.5
  // and 5.0): with k = √(Cu·Cc), D10 = L1(1 − (Cu − k)/3)/(2k − Cu), F1 = 0.1·L1/D10,
  // and the 4.5-5.0 segment climbs 0.3 over D60 − D30 = (Cu − k)·D10.
  const double cu = 1.35, k = std::sqrt(1.35 * 1.2), l1 = kPaperAxes[0];
  const double D10 = l1 * (1 - (cu - k) / 3) / (2 * k - cu);
  const double F1 = 0.1 * l1 / D10;
  const double F2 = F1 + 0.3 * (kPaperAxes[1] - l1) / ((cu - k) * D10);
  EXPECT_NEAR((*f)[0], F1, 1e-10);
  EXPECT_NEAR((*f)[1], F2 - F1, 1e-10);
  EXPECT_NEAR((*f)[2], 1 - F2, 1e-10);
  EXPECT_NEAR(d10, D10, 1e-12);
  EXPECT_LT(d10, l1);
  EXPECT_GT(d30, l1);
  EXPECT_LT(d60, kPaperAxes[1]);
}

TEST(SpecimenGrading, ImpossibleGradingIsNotSolved) {
  // Sizes within 1 % of each other: D30 and D60 fall on them, so Cc ≈ Cu·(D30/D60)² ≈ 1.35.
  EXPECT_FALSE(specimen::solveCountFractions(std::vector<double>{5.0, 5.01, 5.02}).has_value());
  EXPECT_FALSE(specimen::solveCountFractions(std::vector<double>{4.5, 7.0}).has_value());
}

TEST(SpecimenGrading, GeneratedCountsFollowTheFractions) {
  const Specimen s = generateSpecimen(elongated(), 3);
  const auto f = *specimen::solveCountFractions(kPaperAxes);
  std::vector<int> counts(3, 0);
  for (const ParticleSpec& p : specimenOf(s)) {
    const double l = longestDiagonal(p.vertices);
    const auto it = std::find_if(kPaperAxes.begin(), kPaperAxes.end(), [&](double a) { return std::abs(a - l) < 1e-15; });
    ASSERT_NE(it, kPaperAxes.end()) << "long axis " << l;
    ++counts[static_cast<std::size_t>(it - kPaperAxes.begin())];
  }
  // Largest-remainder rounding: each count within one particle of its share.
  for (std::size_t i = 0; i < 3; ++i) EXPECT_LE(std::abs(counts[i] - f[i] * s.specimenCount), 1.0);
}

// --- Shapes ----------------------------------------------------------------------------

TEST(SpecimenShape, PolygonsAreConvexAndInscribedInTheEllipse) {
  for (int n = 3; n <= 8; ++n) {
    Recipe r = elongated(0.05);
    r.vertices = n;
    r.particleCount = 40;
    const Specimen s = generateSpecimen(r, 5);
    for (const ParticleSpec& p : specimenOf(s)) {
      ASSERT_EQ(p.shape, ShapeKind::Polygon);
      ASSERT_EQ(static_cast<int>(p.vertices.size()), n);
      // The first vertex is the +x end of the long axis, L/2 from the centre exactly.
      const double a = p.vertices[0].x();
      EXPECT_EQ(p.vertices[0].y(), 0.0);
      EXPECT_TRUE(std::any_of(kPaperAxes.begin(), kPaperAxes.end(), [&](double l) { return l == 2 * a; })) << a;
      // Every vertex on the ellipse of semi-axes L/2 and L/3 (aspect 1.5).
      for (const Vec2& v : p.vertices) {
        EXPECT_NEAR(std::pow(v.x() / a, 2) + std::pow(v.y() / (a / 1.5), 2), 1.0, 1e-14);
      }
      // Strictly convex and counter-clockwise: every turn is to the left.
      double twiceArea = 0;
      Vec2 centroid = Vec2::Zero();
      for (int k = 0; k < n; ++k) {
        const Vec2& p0 = p.vertices[static_cast<std::size_t>(k)];
        const Vec2& p1 = p.vertices[static_cast<std::size_t>((k + 1) % n)];
        const Vec2& p2 = p.vertices[static_cast<std::size_t>((k + 2) % n)];
        EXPECT_GT(cross(p1 - p0, p2 - p1), 0.0);
        twiceArea += cross(p0, p1);
        centroid += cross(p0, p1) * (p0 + p1);
      }
      // Position is the centroid: the body-frame centroid is the origin, to rounding.
      centroid /= 3 * twiceArea;
      EXPECT_LT(centroid.norm(), 1e-15 * a);
      if (n % 2 == 0) {
        // Even counts: both ends of the long axis are vertices, exactly L apart.
        EXPECT_EQ(p.vertices[static_cast<std::size_t>(n / 2)], Vec2(-a, 0.0));
        EXPECT_EQ(longestDiagonal(p.vertices), 2 * a);
      }
    }
  }
}

TEST(SpecimenShape, DefaultHexagonHasTheExpectedArea) {
  Recipe r = elongated(0.05);
  r.particleCount = 50;
  const Specimen s = generateSpecimen(r, 2);
  for (const ParticleSpec& p : specimenOf(s)) {
    const double l = longestDiagonal(p.vertices);
    double twice = 0;
    for (std::size_t k = 0; k < 6; ++k) twice += cross(p.vertices[k], p.vertices[(k + 1) % 6]);
    // The affine image of a regular hexagon of unit circumradius (area 3√3/2) by (L/2, L/3).
    EXPECT_NEAR(0.5 * twice, 1.5 * std::sqrt(3.0) * (l / 2) * (l / 3), 1e-15 * l * l);
  }
}

TEST(SpecimenShape, DiscsHaveTheRecipeRadius) {
  const Specimen s = generateSpecimen(discs(0.07), 1);
  for (const ParticleSpec& p : specimenOf(s)) {
    EXPECT_EQ(p.shape, ShapeKind::Disc);
    EXPECT_EQ(p.radius, 0.002);
    EXPECT_TRUE(p.vertices.empty());
    EXPECT_EQ(p.motion, Motion::Dynamic);
    EXPECT_FALSE(p.boundary);
    EXPECT_EQ(p.velocity, Vec2::Zero());
  }
}

// --- Determinism -----------------------------------------------------------------------

bool identical(const Specimen& a, const Specimen& b) {
  if (a.specimenCount != b.specimenCount || a.initialRingRadius != b.initialRingRadius ||
      a.particles.size() != b.particles.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    const ParticleSpec& p = a.particles[i];
    const ParticleSpec& q = b.particles[i];
    if (p.shape != q.shape || p.radius != q.radius || p.position != q.position || p.angle != q.angle ||
        p.vertices != q.vertices || p.motion != q.motion || p.boundary != q.boundary) {
      return false;
    }
  }
  return true;
}

TEST(SpecimenDeterminism, SameSeedSameSpecimenDifferentSeedDifferent) {
  for (const Recipe& r : {discs(0.07), elongated(0.07), elongated(0.07, Recipe::Orientation::Bedding, 30)}) {
    const Specimen a = generateSpecimen(r, 42), b = generateSpecimen(r, 42), c = generateSpecimen(r, 43);
    EXPECT_TRUE(identical(a, b));
    EXPECT_FALSE(identical(a, c));
    // Not merely reordered: the first particle itself moves.
    EXPECT_NE(a.particles[0].position, c.particles[0].position);
  }
}

// --- Placement -------------------------------------------------------------------------

TEST(SpecimenPlacement, NoTwoParticlesOverlapAndAllAreInsideTheRing) {
  for (const Recipe& r : {discs(), elongated(), elongated(0.160, Recipe::Orientation::Bedding, 60),
                          elongated(0.07, Recipe::Orientation::Bedding, 90)}) {
    const Specimen s = generateSpecimen(r, 11);
    const auto spec = specimenOf(s);
    const auto ring = ringOf(s);
    expectNoOverlap(spec, spec, true);
    // No particle overlaps a ring disc, and each lies within the ring's inner edge.
    expectNoOverlap(spec, ring, false);
    const double ringDisc = ring[0].radius;
    for (const ParticleSpec& p : spec) EXPECT_LE(outerReach(p), s.initialRingRadius - ringDisc);
  }
}

// Numbered along space: each particle's nearest neighbour lies in its own band or the next,
// so their indices differ by at most two bands' worth of particles, 8 √(N/π) for N particles
// in bands two mean spacings tall across the circle. Numbered in the order of placement, the
// gaps would be about N/3.
TEST(SpecimenNumbering, NeighboursInSpaceAreNeighboursInIndex) {
  for (const Recipe& r : {discs(), elongated(), elongated(0.160, Recipe::Orientation::Bedding, 30)}) {
    const Specimen s = generateSpecimen(r, 5);
    const auto spec = specimenOf(s);
    const size_t n = spec.size();
    ASSERT_GT(n, 500u);
    const std::vector<double> gaps = test::sortedNeighbourIndexGaps(spec);
    const double twoBands = 8 * std::sqrt(n / kPi);
    EXPECT_LT(gaps[n / 2], twoBands) << n << " particles";
    EXPECT_LT(gaps[n * 9 / 10], twoBands) << n << " particles";
  }
}

TEST(SpecimenPlacement, TinyCountsStillPlace) {
  for (int n : {1, 2, 3, 7}) {
    for (Recipe r : {discs(), elongated()}) {
      r.particleCount = n;
      const Specimen s = generateSpecimen(r, 9);
      ASSERT_EQ(s.specimenCount, n);
      expectNoOverlap(specimenOf(s), specimenOf(s), true);
    }
  }
}

// --- Orientation -----------------------------------------------------------------------

TEST(SpecimenOrientation, BeddingLaysEveryLongAxisAtAlpha) {
  for (double alphaDeg : {0.0, 30.0, 60.0, 90.0}) {
    const Specimen s = generateSpecimen(elongated(0.07, Recipe::Orientation::Bedding, alphaDeg), 4);
    for (const ParticleSpec& p : specimenOf(s)) {
      EXPECT_EQ(p.angle, radians(alphaDeg));
      // From the world outline: the long axis joins vertices 0 and 3 of the hexagon.
      const std::vector<Vec2> w = worldVertices(p);
      const Vec2 axis = w[0] - w[3];
      EXPECT_NEAR(std::atan2(axis.y(), axis.x()), radians(alphaDeg), 1e-13);
    }
  }
}

TEST(SpecimenOrientation, RandomOrientationIsUniform) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Specimen s = generateSpecimen(elongated(), seed);
    const auto spec = specimenOf(s);
    // Second-order fabric of the long axes, φ_ij = <n_i n_j>: its principal difference
    // φ1 − φ2 = |<exp(2iθ)>|. For N uniform angles N·|<exp(2iθ)>|² is about exponential with
    // mean 1, so |<exp(2iθ)>| > 3/√N has probability e⁻⁹ ≈ 1e-4.
    std::complex<double> sum2 = 0, sum4 = 0;
    for (const ParticleSpec& p : spec) {
      EXPECT_GE(p.angle, 0.0);
      EXPECT_LT(p.angle, 2 * kPi);
      sum2 += std::polar(1.0, 2 * p.angle);
      sum4 += std::polar(1.0, 4 * p.angle);
    }
    const double n = static_cast<double>(spec.size());
    EXPECT_LT(std::abs(sum2) / n, 3 / std::sqrt(n));
    EXPECT_LT(std::abs(sum4) / n, 3 / std::sqrt(n));
  }
}

// --- Counts and sizes ------------------------------------------------------------------

double hexagonArea(double l) { return 1.5 * std::sqrt(3.0) * (l / 2) * (l / 3); }

int expectedElongatedCount(double diameter) {
  const auto f = *specimen::solveCountFractions(kPaperAxes);
  double mean = 0;
  for (std::size_t i = 0; i < 3; ++i) mean += f[i] * hexagonArea(kPaperAxes[i]);
  return static_cast<int>(std::lround(kPi * diameter * diameter / 4 / 1.27 / mean));
}

TEST(SpecimenCount, FollowsDiameterAndVoidRatio) {
  // Solid area = π(D/2)²/(1 + e), over the mean particle area.
  EXPECT_EQ(generateSpecimen(discs(), 1).specimenCount,
            std::lround(kPi * 0.08 * 0.08 / 1.27 / (kPi * 0.002 * 0.002)));
  EXPECT_EQ(generateSpecimen(discs(), 1).specimenCount, 1260);
  EXPECT_EQ(generateSpecimen(elongated(), 1).specimenCount, expectedElongatedCount(0.160));
  EXPECT_EQ(generateSpecimen(discs(0.07), 1).specimenCount,
            std::lround(kPi * 0.035 * 0.035 / 1.27 / (kPi * 0.002 * 0.002)));
  EXPECT_EQ(generateSpecimen(elongated(0.07), 1).specimenCount, expectedElongatedCount(0.07));
  Recipe r = discs();
  r.particleCount = 2000;
  EXPECT_EQ(generateSpecimen(r, 1).specimenCount, 2000);
}

TEST(SpecimenCount, QuickAndLargeSpecimensGenerateFast) {
  const auto time = [](const Recipe& r, Specimen* out) {
    const auto t0 = std::chrono::steady_clock::now();
    *out = generateSpecimen(r, 8);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  Specimen s;
  // A few hundred particles for tests and demos; bounds far above the milliseconds
  // measured in Release so that a debug or sanitizer build passes too.
  EXPECT_LT(time(discs(0.07), &s), 1.0);
  EXPECT_GT(s.specimenCount, 200);
  EXPECT_LT(s.specimenCount, 300);
  EXPECT_LT(time(elongated(0.07), &s), 1.0);
  EXPECT_GT(s.specimenCount, 200);
  EXPECT_LT(s.specimenCount, 300);
  Recipe big = elongated();
  big.particleCount = 2500;
  EXPECT_LT(time(big, &s), 1.0);
  EXPECT_EQ(s.specimenCount, 2500);
}

// --- The ring --------------------------------------------------------------------------

// The deformations the ring must survive: F = s·diag(λ1, λ2) with s the consolidation
// shrink, then up to 30 % widening along 1 and 20 % compression along 2.
std::vector<Eigen::Matrix2d> loadingPath(double shrink) {
  std::vector<Eigen::Matrix2d> states;
  for (double s : {1.0, 0.5 * (1 + shrink), shrink}) {
    for (double l1 : {1.0, 1.15, 1.3}) {
      for (double l2 : {1.0, 0.9, 0.8}) {
        if (s != shrink && (l1 != 1.0 || l2 != 1.0)) continue;  // shearing follows consolidation
        Eigen::Matrix2d f = Eigen::Matrix2d::Zero();
        f(0, 0) = s * l1;
        f(1, 1) = s * l2;
        states.push_back(f);
      }
    }
  }
  return states;
}

TEST(SpecimenRing, KeepsParticlesInAlongTheWholeLoadingPath) {
  for (const Recipe& r : {discs(), elongated(), discs(0.07), elongated(0.07)}) {
    const Specimen s = generateSpecimen(r, 6);
    const auto ring = ringOf(s);
    ASSERT_GE(ring.size(), 8u);
    for (const ParticleSpec& p : ring) {
      EXPECT_EQ(p.shape, ShapeKind::Disc);
      EXPECT_EQ(p.motion, Motion::Kinematic);
      EXPECT_TRUE(p.boundary);
      EXPECT_EQ(p.radius, ring[0].radius);
      EXPECT_NEAR(p.position.norm(), s.initialRingRadius, 1e-15);
    }
    // Smallest width of the smallest particle, from the geometry: a disc's diameter, or
    // for the hexagon of the 4.5 mm class its height 2·(L/3)·sin 60° = L/√3.
    const double smallestWidth = r.shape == Recipe::Shape::Disc ? 2 * r.discRadius : kPaperAxes[0] / std::sqrt(3.0);
    // Automatic ring discs: half that width.
    EXPECT_NEAR(ring[0].radius, 0.5 * smallestWidth, 1e-15);
    const double consolidated = 0.5 * r.specimenDiameter + ring[0].radius;
    const double shrink = consolidated / s.initialRingRadius;
    EXPECT_LT(shrink, 1.0);
    for (const Eigen::Matrix2d& f : loadingPath(shrink)) {
      EXPECT_TRUE(specimen::ringRetains(ring, f, smallestWidth)) << f;
      // The generator's own sizing is stricter: neighbours still overlap.
      EXPECT_LT(specimen::largestRingGap(ring, f), 0.0) << f;
    }
  }
}

TEST(SpecimenRing, ATooSparseRingFailsTheCondition) {
  const Specimen s = generateSpecimen(discs(), 6);
  const auto ring = ringOf(s);
  const double width = 0.004;
  // Every fourth disc of the ring: neighbours 4·2R·sin(π/M) apart, far more than 2r + w.
  std::vector<ParticleSpec> sparse;
  for (std::size_t k = 0; k < ring.size(); k += 4) sparse.push_back(ring[k]);
  const double chord = (sparse[1].position - sparse[0].position).norm();
  ASSERT_GT(chord - 2 * sparse[0].radius, width);
  EXPECT_FALSE(specimen::ringRetains(sparse, Eigen::Matrix2d::Identity(), width));
  const double shrink = (0.08 + ring[0].radius) / s.initialRingRadius;
  Eigen::Matrix2d end = Eigen::Matrix2d::Zero();
  end(0, 0) = shrink * 1.3;
  end(1, 1) = shrink * 0.8;
  // Even after consolidation: the gap across the top is stretched by 1.3.
  EXPECT_GT(shrink * 1.3 * chord - 2 * sparse[0].radius, width);
  EXPECT_FALSE(specimen::ringRetains(sparse, end, width));
}

TEST(SpecimenRing, DiscCountFollowsTheWidestState) {
  // A ring that widens beyond its start (a dense placement): the biaxial end state rules.
  specimen::RingPath path;
  path.consolidatedRadius = 0.1;
  EXPECT_DOUBLE_EQ(specimen::ringWidestStretch(0.12, path), 0.1 * 1.3 / 0.12);
  path.consolidatedRadius = 0.08;
  EXPECT_EQ(specimen::ringWidestStretch(0.12, path), 1.0);
  const int m = specimen::ringDiscCount(0.12, 0.002, path);
  EXPECT_LE(2 * 0.12 * std::sin(kPi / m), 2 * 0.9 * 0.002);
  EXPECT_GT(2 * 0.12 * std::sin(kPi / (m - 1)), 2 * 0.9 * 0.002);
}

// --- JSON ------------------------------------------------------------------------------

TEST(SpecimenJson, EmptyObjectGivesTheDefaults) {
  const Recipe r = parseSpecimenRecipe(nlohmann::json::object(), "assembly");
  const Recipe d;
  EXPECT_EQ(r.shape, d.shape);
  EXPECT_EQ(r.discRadius, d.discRadius);
  EXPECT_EQ(r.longAxes, d.longAxes);
  EXPECT_TRUE(r.countFractions.empty());
  EXPECT_EQ(r.aspectRatio, d.aspectRatio);
  EXPECT_EQ(r.vertices, d.vertices);
  EXPECT_EQ(r.orientation, d.orientation);
  EXPECT_EQ(r.beddingAngle, 0.0);
  EXPECT_EQ(r.specimenDiameter, d.specimenDiameter);
  EXPECT_EQ(r.targetVoidRatio, d.targetVoidRatio);
  EXPECT_FALSE(r.particleCount.has_value());
  EXPECT_EQ(r.boundaryRadius, 0.0);
}

TEST(SpecimenJson, ReadsEveryKeyAndRoundTrips) {
  const nlohmann::json j = {{"shape", "elongated"},        {"disc_radius", 0.0025},
                            {"long_axes", {0.004, 0.006}}, {"count_fractions", {0.25, 0.75}},
                            {"aspect_ratio", 2.0},         {"vertices", 8},
                            {"orientation", "bedding"},    {"bedding_angle_deg", 30},
                            {"specimen_diameter", 0.1},    {"target_void_ratio", 0.3},
                            {"particle_count", 400},       {"boundary_radius", 0.0015},
                            {"clump_discs", 5}};
  const Recipe r = parseSpecimenRecipe(j, "assembly");
  EXPECT_EQ(r.clumpDiscs, 5);
  EXPECT_EQ(r.shape, Recipe::Shape::Elongated);
  EXPECT_EQ(r.discRadius, 0.0025);
  EXPECT_EQ(r.longAxes, (std::vector<double>{0.004, 0.006}));
  EXPECT_EQ(r.countFractions, (std::vector<double>{0.25, 0.75}));
  EXPECT_EQ(r.aspectRatio, 2.0);
  EXPECT_EQ(r.vertices, 8);
  EXPECT_EQ(r.orientation, Recipe::Orientation::Bedding);
  EXPECT_NEAR(r.beddingAngle, kPi / 6, 1e-15);
  EXPECT_EQ(r.specimenDiameter, 0.1);
  EXPECT_EQ(r.targetVoidRatio, 0.3);
  EXPECT_EQ(r.particleCount, 400);
  EXPECT_EQ(r.boundaryRadius, 0.0015);

  const nlohmann::json back = specimenRecipeToJson(r);
  for (const auto& [key, value] : j.items()) {
    if (value.is_number()) {
      EXPECT_NEAR(back.at(key).get<double>(), value.get<double>(), 1e-12) << key;
    } else {
      EXPECT_EQ(back.at(key), value) << key;
    }
  }
  EXPECT_EQ(back.size(), j.size());
  // Defaults write out and read back too; an absent count stays absent.
  const nlohmann::json defaults = specimenRecipeToJson(Recipe{});
  EXPECT_FALSE(defaults.contains("particle_count"));
  const Recipe again = parseSpecimenRecipe(defaults, "assembly");
  EXPECT_EQ(again.longAxes, Recipe{}.longAxes);
  // particle_count null means "derive it", as if omitted.
  EXPECT_FALSE(parseSpecimenRecipe({{"particle_count", nullptr}}, "assembly").particleCount.has_value());
}

void expectFieldError(const nlohmann::json& j, const std::string& field, const std::string& reasonPart) {
  try {
    parseSpecimenRecipe(j, "assembly");
    ADD_FAILURE() << j.dump() << " parsed";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.field(), field) << j.dump() << ": " << e.what();
    EXPECT_NE(e.reason().find(reasonPart), std::string::npos) << j.dump() << ": " << e.what();
  }
}

TEST(SpecimenJson, ErrorsNameTheField) {
  expectFieldError(nlohmann::json::array(), "assembly", "object");
  expectFieldError({{"colour", "red"}}, "assembly.colour", "unknown");
  expectFieldError({{"vertices", 9}}, "assembly.vertices", "between 3 and 8");
  expectFieldError({{"vertices", 2}}, "assembly.vertices", "between 3 and 8");
  expectFieldError({{"vertices", 6.5}}, "assembly.vertices", "integer");
  expectFieldError({{"shape", "square"}}, "assembly.shape", "disc");
  expectFieldError({{"shape", 3}}, "assembly.shape", "string");
  expectFieldError({{"orientation", "diagonal"}}, "assembly.orientation", "bedding");
  expectFieldError({{"disc_radius", -0.002}}, "assembly.disc_radius", "0");
  expectFieldError({{"disc_radius", "big"}}, "assembly.disc_radius", "number");
  expectFieldError({{"aspect_ratio", 0.5}}, "assembly.aspect_ratio", "1");
  expectFieldError({{"bedding_angle_deg", 200}}, "assembly.bedding_angle_deg", "180");
  expectFieldError({{"specimen_diameter", 0}}, "assembly.specimen_diameter", "0");
  expectFieldError({{"specimen_diameter", 10.0}}, "assembly.specimen_diameter", "more than");
  expectFieldError({{"target_void_ratio", -0.1}}, "assembly.target_void_ratio", "0");
  expectFieldError({{"particle_count", 0}}, "assembly.particle_count", "between 1 and");
  expectFieldError({{"particle_count", 2.5}}, "assembly.particle_count", "integer");
  expectFieldError({{"boundary_radius", -1}}, "assembly.boundary_radius", "0");
  expectFieldError({{"long_axes", 0.005}}, "assembly.long_axes", "array");
  expectFieldError({{"long_axes", {0.005, "x"}}}, "assembly.long_axes[1]", "number");
  expectFieldError({{"long_axes", {0.005, 0.004}}}, "assembly.long_axes[1]", "increasing");
  expectFieldError({{"long_axes", {0.005, -0.004}}}, "assembly.long_axes[1]", "positive");
  expectFieldError({{"long_axes", nlohmann::json::array()}}, "assembly.long_axes", "at least one");
  expectFieldError({{"count_fractions", {0.5, 0.5}}}, "assembly.count_fractions", "one entry per long axis");
  expectFieldError({{"count_fractions", {0.3, 0.3, 0.3}}}, "assembly.count_fractions", "sum to 1");
  expectFieldError({{"count_fractions", {0.6, -0.1, 0.5}}}, "assembly.count_fractions[1]", ">= 0");
  expectFieldError({{"shape", "elongated"}, {"long_axes", {0.004, 0.005}}}, "assembly.count_fractions",
                   "must be given");
  expectFieldError({{"shape", "elongated"}, {"long_axes", {0.005, 0.00501, 0.00502}}}, "assembly.long_axes",
                   "D60/D10");
  // The path given is the prefix used.
  try {
    parseSpecimenRecipe({{"vertices", 12}}, "scene.assembly");
    ADD_FAILURE();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.field(), "scene.assembly.vertices");
  }
}

TEST(SpecimenJson, GeneratorRejectsABadRecipeBuiltInCode) {
  Recipe r = elongated();
  r.vertices = 9;
  try {
    generateSpecimen(r, 1);
    ADD_FAILURE();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.field(), "assembly.vertices");
  }
}

}  // namespace
}  // namespace grainlab

namespace grainlab {
namespace {

// The planned count (the server's particle limit) is the generator's, for discs, random and
// bedded polygons, and recipes of a given count and of a given size, over several seeds.
TEST(SpecimenPlan, PlannedCountIsTheGeneratedCount) {
  const std::vector<nlohmann::json> recipes = {
      {{"shape", "disc"}, {"disc_radius", 0.002}, {"specimen_diameter", 0.06}},
      {{"shape", "disc"}, {"disc_radius", 0.001}, {"specimen_diameter", 0.03}, {"particle_count", 150}},
      {{"shape", "elongated"}, {"specimen_diameter", 0.06}},
      {{"shape", "elongated"}, {"specimen_diameter", 0.05}, {"orientation", "bedding"}, {"bedding_angle_deg", 30}},
  };
  for (const nlohmann::json& json : recipes) {
    const SpecimenRecipe recipe = parseSpecimenRecipe(json, "assembly");
    for (std::uint64_t seed : {1, 2, 3}) {
      const Specimen s = generateSpecimen(recipe, seed);
      EXPECT_EQ(plannedParticleCount(recipe), static_cast<int>(s.particles.size())) << json.dump() << " seed " << seed;
      EXPECT_GT(s.specimenCount, 100);
    }
  }
}

}  // namespace
}  // namespace grainlab

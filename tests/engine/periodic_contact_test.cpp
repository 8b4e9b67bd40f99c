// Contacts across the edges of a periodic cell. A pair that meets across an edge (through an
// image) must feel exactly what the same pair feels in the middle of the cell: the cell's
// tiling is translation-invariant, so force, torque, overlap and the tangential spring's
// history agree to rounding (positions differ by a cell-sized translation: their last bits
// differ, nothing else does). Also when a particle is wrapped to the far side mid-contact, when
// the cell is tilted far enough to be remapped, and when it deforms.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "grainlab/periodic_cell.hpp"
#include "world_helpers.hpp"

namespace grainlab {
namespace {

using Mat2 = Eigen::Matrix2d;
using test::disc;

Mat2 matrix(double a, double b, double c, double d) {
  Mat2 m;
  m << a, b, c, d;
  return m;
}

// What a two-particle run shows at each step.
struct Sample {
  bool touching = false;
  double fn = 0, ft = 0, overlap = 0, elastic = 0;
  Vec2 forceA, forceB, velocityA, velocityB;
  double torqueA = 0, torqueB = 0, spinA = 0, spinB = 0;
  Vec2 positionA;
};

struct PairRun {
  std::vector<Sample> samples;
  int wrapsWhileTouching = 0;  // steps where a particle jumped by a cell edge during the contact
};

// Two particles (specs a and b, placed at their positions + offset) in a cell h under L, for
// `steps` steps of dt.
PairRun runPair(const Mat2& h, const Mat2& L, ParticleSpec a, ParticleSpec b, const Vec2& offset, int steps, double dt,
            const Material& material) {
  World world(material);
  world.setPeriodicCell(h);
  a.position += offset;
  b.position += offset;
  world.addParticle(a);
  world.addParticle(b);
  world.setCellVelocityGradient(L);
  world.setTimestep(dt);
  world.initialize();
  PairRun run;
  std::vector<ContactRecord> contacts;
  Vec2 last[2] = {world.positions()[0], world.positions()[1]};
  for (int s = 0; s < steps; ++s) {
    world.step();
    world.contacts(contacts);
    Sample x;
    x.touching = !contacts.empty();
    if (x.touching) {
      x.fn = contacts[0].fn;
      x.ft = contacts[0].ft;
      x.overlap = contacts[0].overlap;
    }
    x.elastic = world.elasticEnergy();
    x.forceA = world.forces()[0];
    x.forceB = world.forces()[1];
    x.torqueA = world.torques()[0];
    x.torqueB = world.torques()[1];
    x.velocityA = world.velocities()[0];
    x.velocityB = world.velocities()[1];
    x.spinA = world.spins()[0];
    x.spinB = world.spins()[1];
    x.positionA = world.positions()[0];
    for (int k = 0; k < 2; ++k) {
      // A step moves a particle by far less than a tenth of the cell: a larger jump is a wrap.
      if ((world.positions()[k] - last[k]).norm() > 0.1 * world.periodicCell()->minWidth() && x.touching &&
          (run.samples.empty() || run.samples.back().touching)) {
        ++run.wrapsWhileTouching;
      }
      last[k] = world.positions()[k];
    }
    run.samples.push_back(x);
  }
  return run;
}

// Rounding of positions ~1e-18 m against overlaps ~1e-5 m: agreement to 1e-9 of each
// quantity's scale leaves room for that and nothing else (a wrong image or a missing affine
// velocity changes these at the percent level).
void expectSameRun(const PairRun& inside, const PairRun& across) {
  ASSERT_EQ(inside.samples.size(), across.samples.size());
  double fScale = 0, tScale = 0, vScale = 0, wScale = 0, eScale = 0, dScale = 0;
  int touching = 0, sliding = 0;
  for (const Sample& s : inside.samples) {
    fScale = std::max({fScale, s.forceA.norm(), std::abs(s.fn)});
    tScale = std::max(tScale, std::abs(s.torqueA));
    vScale = std::max(vScale, s.velocityA.norm());
    wScale = std::max(wScale, std::abs(s.spinA));
    eScale = std::max(eScale, s.elastic);
    dScale = std::max(dScale, s.overlap);
    touching += s.touching;
    sliding += s.touching && s.ft != 0;
  }
  ASSERT_GT(touching, 20) << "the pair must be in contact for a while";
  ASSERT_GT(sliding, 20) << "the tangential spring must be loaded";
  const double tol = 1e-9;
  for (size_t k = 0; k < inside.samples.size(); ++k) {
    const Sample &a = inside.samples[k], &b = across.samples[k];
    ASSERT_EQ(a.touching, b.touching) << "step " << k;
    EXPECT_NEAR(a.fn, b.fn, tol * fScale) << "step " << k;
    EXPECT_NEAR(a.ft, b.ft, tol * fScale) << "step " << k;
    EXPECT_NEAR(a.overlap, b.overlap, tol * dScale) << "step " << k;
    EXPECT_NEAR(a.elastic, b.elastic, tol * eScale) << "step " << k;
    EXPECT_NEAR((a.forceA - b.forceA).norm(), 0, tol * fScale) << "step " << k;
    EXPECT_NEAR((a.forceB - b.forceB).norm(), 0, tol * fScale) << "step " << k;
    EXPECT_NEAR(a.torqueA, b.torqueA, tol * tScale) << "step " << k;
    EXPECT_NEAR(a.torqueB, b.torqueB, tol * tScale) << "step " << k;
    EXPECT_NEAR((a.velocityA - b.velocityA).norm(), 0, tol * vScale) << "step " << k;
    EXPECT_NEAR((a.velocityB - b.velocityB).norm(), 0, tol * vScale) << "step " << k;
    EXPECT_NEAR(a.spinA, b.spinA, tol * wScale) << "step " << k;
    EXPECT_NEAR(a.spinB, b.spinB, tol * wScale) << "step " << k;
  }
}

const double kEdge = 0.02, kR = 0.001, kDt = 2e-7;
const Material kMaterial = test::material(1e6, 0.7, 0.4);

// An oblique, spinning collision: the tangential spring loads and slips.
std::pair<ParticleSpec, ParticleSpec> discPair(const Vec2& at) {
  // Centres 1.789 kR apart against a reach of 1.8 kR: touching from the start.
  return {disc(kR, at, {0.4, 0.05}, 30), disc(0.8 * kR, at + Vec2(1.6 * kR, 0.8 * kR), {-0.3, -0.1}, -50)};
}

struct CellCase {
  const char* name;
  Mat2 h, L;
};

std::vector<CellCase> cellCases() {
  return {
      {"square, at rest", matrix(kEdge, 0, 0, kEdge), Mat2::Zero()},
      {"tilted 0.3, sheared", matrix(kEdge, 0.3 * kEdge, 0, kEdge), matrix(0, 40, 0, 0)},
      // Tilted past half an edge: remapped (LAMMPS's flip) at the first build.
      {"tilted 0.8, compressed", matrix(kEdge, 0.8 * kEdge, 0.1 * kEdge, kEdge), matrix(-30, 5, 10, -20)},
  };
}

TEST(PeriodicContact, DiscsAcrossAnEdgeFeelWhatTheyFeelInside) {
  for (const CellCase& c : cellCases()) {
    SCOPED_TRACE(c.name);
    const PeriodicCell cell(c.h);
    const Vec2 middle = c.h * Vec2(0.5, 0.5) - Vec2(kR, 0.5 * kR);
    const auto [a, b] = discPair(Vec2::Zero());
    const PairRun inside = runPair(c.h, c.L, a, b, middle, 3000, kDt, kMaterial);
    // The same pair straddling the edge x = h·(1, s2) (b beyond it), and the corner.
    for (const Vec2& s : {Vec2(1, 0.5), Vec2(0.5, 1), Vec2(1, 1), Vec2(0, 0)}) {
      SCOPED_TRACE(testing::Message() << "straddling the edge at fractional " << s.transpose());
      const Vec2 at = c.h * s - Vec2(kR, 0.5 * kR);
      const PairRun across = runPair(c.h, c.L, a, b, at, 3000, kDt, kMaterial);
      expectSameRun(inside, across);
    }
  }
}

TEST(PeriodicContact, PolygonsAcrossAnEdgeFeelWhatTheyFeelInside) {
  ParticleSpec a = test::box(2 * kR, 1.4 * kR, Vec2::Zero(), 0.1);
  a.velocity = {0.3, 0.02};
  a.spin = 20;
  ParticleSpec b = test::box(1.6 * kR, 1.6 * kR, Vec2(1.78 * kR, 0.6 * kR), -0.05);
  b.velocity = {-0.2, -0.05};
  b.spin = -30;
  for (const CellCase& c : cellCases()) {
    SCOPED_TRACE(c.name);
    const Vec2 middle = c.h * Vec2(0.5, 0.5) - Vec2(kR, 0.3 * kR);
    const PairRun inside = runPair(c.h, c.L, a, b, middle, 3000, kDt, kMaterial);
    for (const Vec2& s : {Vec2(1, 0.5), Vec2(0.5, 1), Vec2(1, 1)}) {
      SCOPED_TRACE(testing::Message() << "straddling the edge at fractional " << s.transpose());
      const PairRun across = runPair(c.h, c.L, a, b, c.h * s - Vec2(kR, 0.3 * kR), 3000, kDt, kMaterial);
      expectSameRun(inside, across);
    }
  }
}

// The pair flies across the top edge while in contact: one particle is wrapped to the bottom
// at a neighbour rebuild mid-contact, and its image shift renamed. The contact must go on as if
// nothing happened, its tangential spring included.
TEST(PeriodicContact, AContactCrossingAnEdgeMidSlideKeepsItsHistory) {
  const Mat2 h = matrix(kEdge, 0.2 * kEdge, 0, kEdge);
  auto [a, b] = discPair(Vec2::Zero());
  const Vec2 drift(0.5, 10.0);  // m/s, common to both: carries the pair across y = edge
  a.velocity += drift;
  b.velocity += drift;
  const PairRun inside = runPair(h, Mat2::Zero(), a, b, h * Vec2(0.3, 0.1), 3000, kDt, kMaterial);
  const PairRun across = runPair(h, Mat2::Zero(), a, b, h * Vec2(0.3, 1) - Vec2(0, 0.9 * kR), 3000, kDt, kMaterial);
  EXPECT_EQ(inside.wrapsWhileTouching, 0);
  EXPECT_GE(across.wrapsWhileTouching, 1) << "no particle was wrapped during the contact: the test tests nothing";
  expectSameRun(inside, across);
}

// The relative velocity of a pair includes the affine velocity of the image, L (x_j + h n −
// x_i): a pair across an edge in a deforming cell starts with the force the same two discs feel
// without a cell when given their full velocities ṽ + L x (the image's for the one across).
TEST(PeriodicContact, AnImageMovesWithTheCellsAffineVelocity) {
  const Mat2 h = matrix(kEdge, 0.1 * kEdge, 0, kEdge);
  const Mat2 L = matrix(-50, 120, 30, 20);
  const Vec2 xa = h * Vec2(1, 0.5) - Vec2(kR, 0);
  const Vec2 xb = xa + Vec2(1.9 * kR, 0.3 * kR);  // beyond the edge: inside, it is at xb − h₁
  const Vec2 va(0.01, -0.02), vb(-0.03, 0.01);
  World cellWorld(kMaterial);
  cellWorld.setPeriodicCell(h);
  cellWorld.addParticle(disc(kR, xa, va, 3));
  cellWorld.addParticle(disc(kR, xb - h.col(0), vb, -2));
  cellWorld.setCellVelocityGradient(L);
  cellWorld.setTimestep(kDt);
  cellWorld.initialize();
  World open(kMaterial);
  open.addParticle(disc(kR, xa, va + L * xa, 3));
  open.addParticle(disc(kR, xb, vb + L * xb, -2));
  open.setTimestep(kDt);
  open.initialize();
  const double scale = open.forces()[0].norm();
  ASSERT_GT(scale, 0);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR((cellWorld.forces()[k] - open.forces()[k]).norm(), 0, 1e-12 * scale);
    EXPECT_NEAR(cellWorld.torques()[k], open.torques()[k], 1e-12 * scale * kR);
  }
  // And the affine part matters here: without it the dashpot would see another velocity.
  World still(kMaterial);
  still.addParticle(disc(kR, xa, va, 3));
  still.addParticle(disc(kR, xb, vb, -2));
  still.setTimestep(kDt);
  still.initialize();
  EXPECT_GT((still.forces()[0] - open.forces()[0]).norm(), 1e-3 * scale);
}

TEST(PeriodicContact, RefusesACellNarrowerThanTwoReaches) {
  World world(kMaterial);
  world.setPeriodicCell(matrix(0.004, 0, 0, 0.05));  // 2 × (2r + skin) = 4.6 mm
  world.addParticle(disc(kR, {0.001, 0.001}));
  world.addParticle(disc(kR, {0.003, 0.02}));
  EXPECT_THROW(world.initialize(), std::invalid_argument);
}

TEST(PeriodicContact, Box2dRefusesAPeriodicCell) {
  WorldSettings settings;
  settings.engine = WorldSettings::Engine::Box2d;
  World world(kMaterial, settings);
  EXPECT_THROW(world.setPeriodicCell(matrix(kEdge, 0, 0, kEdge)), std::invalid_argument);
}

}  // namespace
}  // namespace grainlab

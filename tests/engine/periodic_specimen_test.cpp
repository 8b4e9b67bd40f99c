// Specimens for the periodic cell: the paper's gradings and fabrics placed without overlap,
// images included, then consolidated in the cell by the isotropic servos.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "grainlab/periodic_cell.hpp"
#include "grainlab/specimen.hpp"
#include "grainlab/world.hpp"
#include "neighbour_index_gaps.hpp"
#include "periodic_stages.hpp"

namespace grainlab {
namespace {

SpecimenRecipe discRecipe() {
  SpecimenRecipe r;  // the paper's circular assembly: equal discs
  r.particleCount = 300;
  return r;
}

SpecimenRecipe beddingRecipe() {
  SpecimenRecipe r;  // the paper's elongated hexagons at a bedding angle of 30°, its grading
  r.shape = SpecimenRecipe::Shape::Elongated;
  r.orientation = SpecimenRecipe::Orientation::Bedding;
  r.beddingAngle = radians(30);
  r.particleCount = 300;
  return r;
}

// Placed without overlap: the world, once built, has no touching pair (across the edges
// included), and the cell holds the recipe's particles at the placement fraction.
void expectPlacedWithoutOverlap(const SpecimenRecipe& recipe, double fraction) {
  const CellSpecimen s = generateCellSpecimen(recipe, 3);
  ASSERT_EQ(static_cast<int>(s.particles.size()), generateSpecimen(recipe, 3).specimenCount);
  World world(Material{});
  world.setPeriodicCell(s.edges);
  double solid = 0;
  for (const ParticleSpec& p : s.particles) solid += world.area(world.addParticle(p));
  world.initialize();
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  EXPECT_TRUE(contacts.empty()) << contacts.size() << " particles overlap";
  EXPECT_NEAR(solid, s.solidArea, 1e-9 * solid);
  EXPECT_NEAR(solid / world.periodicCell()->area(), fraction, 1e-9);
  // Grains cross the edges: some are within a radius of one.
  int nearEdge = 0;
  for (const Vec2& x : world.positions()) {
    const Vec2 f = world.periodicCell()->fractional(x);
    nearEdge += f.minCoeff() < 0.01 || f.maxCoeff() > 0.99;
  }
  EXPECT_GT(nearEdge, 0);
}

TEST(PeriodicSpecimen, DiscsArePlacedWithoutOverlapAcrossTheEdges) { expectPlacedWithoutOverlap(discRecipe(), 0.45); }

TEST(PeriodicSpecimen, BeddingHexagonsKeepTheirAngleAndDoNotOverlap) {
  const SpecimenRecipe recipe = beddingRecipe();
  expectPlacedWithoutOverlap(recipe, 0.40);
  for (const ParticleSpec& p : generateCellSpecimen(recipe, 3).particles) EXPECT_DOUBLE_EQ(p.angle, radians(30));
}

TEST(PeriodicSpecimen, SameSeedSameSpecimenOtherSeedAnother) {
  const CellSpecimen a = generateCellSpecimen(discRecipe(), 9), b = generateCellSpecimen(discRecipe(), 9),
                     c = generateCellSpecimen(discRecipe(), 10);
  ASSERT_EQ(a.particles.size(), b.particles.size());
  for (size_t k = 0; k < a.particles.size(); ++k) EXPECT_EQ(a.particles[k].position, b.particles[k].position);
  EXPECT_NE(a.particles[0].position, c.particles[0].position);
}

// Numbered along space, as the ring's specimens are (specimen_order.hpp): in bands two mean
// spacings s = L/√N tall across a cell of side L, each holding about 2√N particles. A particle's
// nearest neighbour (measured straight, not across the edges) lies in its own band or the next,
// so their indices differ by less than two bands' worth, 4√N. Numbered in the order of
// placement, the gaps would be about N/3 (333 against 126 here).
TEST(PeriodicSpecimen, NeighboursInSpaceAreNeighboursInIndex) {
  for (SpecimenRecipe recipe : {discRecipe(), beddingRecipe()}) {
    recipe.particleCount = 1000;
    const CellSpecimen s = generateCellSpecimen(recipe, 5);
    const size_t n = s.particles.size();
    ASSERT_EQ(n, 1000u);
    const std::vector<double> gaps = test::sortedNeighbourIndexGaps(s.particles);
    const double twoBands = 4 * std::sqrt(static_cast<double>(n));
    EXPECT_LT(gaps[n / 2], twoBands);
    EXPECT_LT(gaps[n * 9 / 10], twoBands);
  }
}

// Preparation as the paper's: compaction without friction to a dense state, by the cell's
// isotropic servos at p. The specimen ends at p and dense: frictionless equal discs pack
// between random close packing (about 0.82-0.84 in 2D) and the hexagonal 0.907, which they
// partly reach by ordering (overlaps at p = 100 kPa add only ~p/k_n = 1e-3).
TEST(PeriodicSpecimen, ConsolidatedInTheCellToP) {
  const CellSpecimen s = generateCellSpecimen(discRecipe(), 3);
  Material m;
  m.friction = 0;
  m.restitution = 0.5;
  m.localDamping = 0.1;
  World world(m);
  world.setPeriodicCell(s.edges);
  for (const ParticleSpec& p : s.particles) world.addParticle(p);
  world.initialize();
  CellLoading loading;
  loading.d11 = CellComponent::holding(100e3);
  loading.d22 = CellComponent::holding(100e3);
  loading.rateCap = 10;
  CellStage stage("compaction", loading, world, 0.08, 0.005);
  while (!stage.finished()) {
    stage.beforeStep();
    world.step();
    stage.afterStep();
  }
  const StressTensor& stress = stage.measureStress();
  EXPECT_NEAR(stress.s11, 100e3, 500);
  EXPECT_NEAR(stress.s22, 100e3, 500);
  const double fraction = s.solidArea / world.periodicCell()->area();
  std::printf("consolidated in the cell: solid fraction %.4f (void ratio %.4f)\n", fraction, 1 / fraction - 1);
  EXPECT_GT(fraction, 0.80);
  EXPECT_LT(fraction, 0.90);
}

}  // namespace
}  // namespace grainlab

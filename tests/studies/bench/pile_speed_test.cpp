// The bench's measure on a small pile: one rate per repeat, the settled pile's contacts
// counted, and the median of the repeats.
#include <gtest/gtest.h>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/studies/bench/pile_speed.hpp"

namespace grainlab::bench {
namespace {

TEST(PileSpeed, TimesEachRepeatOfASettledPile) {
  const PileSpeed s = measurePileSpeed(pileScene(6, 6, false), 20, 3, 1, WorldSettings::Engine::Dem, nullptr);
  EXPECT_EQ(s.particles, 36);
  ASSERT_EQ(s.rates.size(), 3u);
  for (double r : s.rates) EXPECT_GT(r, 0);
  EXPECT_GT(s.coordination, 1);  // settled: the discs rest on each other
  EXPECT_GT(s.timestep, 0);
}

TEST(PileSpeed, TimesBothContactPathsInTurnAndLeavesThePathAsItWas) {
  const SimdPath before = simdPath();
  const PathSpeeds s = measurePathSpeeds(pileScene(6, 6, false), 20, 3, 1, nullptr);
  EXPECT_EQ(simdPath(), before);
  ASSERT_EQ(s.wide.rates.size(), 3u);
  ASSERT_EQ(s.baseline.rates.size(), 3u);
  for (double r : s.wide.rates) EXPECT_GT(r, 0);
  for (double r : s.baseline.rates) EXPECT_GT(r, 0);
  EXPECT_EQ(s.wide.cpuRates.size(), 3u);  // one thread: timed by its CPU time too
  EXPECT_EQ(s.baseline.cpuRates.size(), 3u);
  EXPECT_EQ(s.wide.particles, 36);
  EXPECT_EQ(s.wide.coordination, s.baseline.coordination);  // one settled pile for both
}

TEST(PileSpeed, TimesSeveralPilesInTurnEachAsItIs) {
  Scene clumps = clumpPileScene(6, 6);
  const std::vector<PileSpeed> s = measureInTurn({pileScene(6, 6, false), clumps}, 20, 3, 1, nullptr);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].name, "disc-pile");
  EXPECT_EQ(s[1].name, "clump-pile");
  for (const PileSpeed& p : s) {
    EXPECT_EQ(p.particles, 36);
    ASSERT_EQ(p.rates.size(), 3u);
    EXPECT_EQ(p.cpuRates.size(), 3u);  // one thread: timed by its CPU time too
    for (double r : p.rates) EXPECT_GT(r, 0);
  }
  // Each pile settled on its own: a clump's three discs touch more neighbours than a disc.
  EXPECT_GT(s[1].coordination, s[0].coordination);
}

// The cell copies the pile: the same discs, compressed to the settled pile's bulk solid
// fraction (a settled disc packing: between a loose 0.7 and the hexagonal 0.907). A pile this
// small settles looser (0.80) than the bench's 2,500 discs (0.85), too loose for the cell to
// jam: its coordination is not asked for here.
TEST(PileSpeed, TimesTheCellAgainstThePileItCopies) {
  const Scene pile = pileScene(10, 10, false), cell = periodicPileScene(10, 10);
  EXPECT_TRUE(cell.walls.empty());
  EXPECT_EQ(cell.particles.size(), pile.particles.size());
  for (size_t k = 0; k < pile.particles.size(); ++k) EXPECT_EQ(cell.particles[k].radius, pile.particles[k].radius);
  const CellSpeeds s = measureCellAgainstPile(pile, cell, 1.0, 20, 3, 1, nullptr);
  EXPECT_GT(s.solidFraction, 0.7);
  EXPECT_LT(s.solidFraction, 0.907);
  ASSERT_EQ(s.cell.rates.size(), 3u);
  ASSERT_EQ(s.pile.rates.size(), 3u);
  EXPECT_EQ(s.cell.cpuRates.size(), 3u);
  for (double r : s.cell.rates) EXPECT_GT(r, 0);
}

// One settled pile copied into a one-thread world: both start from the same contacts.
TEST(PileSpeed, TimesOneAndTwoThreadsOnTheSamePile) {
  const ThreadSpeeds s = measureThreadScaling(pileScene(6, 6, false), 2, 20, 3, nullptr);
  EXPECT_EQ(s.serial.particles, 36);
  EXPECT_EQ(s.serial.coordination, s.threaded.coordination);
  EXPECT_GT(s.serial.coordination, 1);
  ASSERT_EQ(s.serial.rates.size(), 3u);
  ASSERT_EQ(s.threaded.rates.size(), 3u);
  EXPECT_EQ(s.serial.cpuRates.size(), 3u);
  EXPECT_TRUE(s.threaded.cpuRates.empty());  // several threads: wall time only
}

TEST(PileSpeed, MedianOfOddAndEvenRepeats) {
  PileSpeed s;
  s.rates = {3, 1, 2};
  EXPECT_DOUBLE_EQ(s.medianRate(), 2);
  s.rates = {4, 1, 3, 2};
  EXPECT_DOUBLE_EQ(s.medianRate(), 2.5);
}

TEST(PileSpeed, TheGeneralPathPileIsTheDiscPileAndOnePolygon) {
  const std::vector<Scene> piles = benchPiles();
  ASSERT_EQ(piles.size(), 5u);
  EXPECT_EQ(piles[1].name, "disc-pile+1poly");
  EXPECT_EQ(piles[1].particles.size(), piles[0].particles.size() + 1);
  EXPECT_EQ(piles[1].particles.back().shape, ShapeKind::Polygon);
}

TEST(PileSpeed, TheRollingPileIsTheDiscPileWithRollingResistance) {
  const std::vector<Scene> piles = benchPiles();
  ASSERT_EQ(piles.size(), 5u);
  EXPECT_EQ(piles[3].name, "disc-pile-rolling");
  EXPECT_EQ(piles[3].particles.size(), piles[0].particles.size());
  EXPECT_EQ(piles[0].material.rollingFriction, 0.0);
  EXPECT_GT(piles[3].material.rollingFriction, 0.0);
}

TEST(PileSpeed, TheClumpPileHasOneThreeDiscClumpPerDisc) {
  const std::vector<Scene> piles = benchPiles();
  ASSERT_EQ(piles.size(), 5u);
  EXPECT_EQ(piles[4].name, "clump-pile");
  EXPECT_EQ(piles[4].particles.size(), piles[0].particles.size());
  EXPECT_EQ(piles[4].particles.back().members.size(), 3u);
}

}  // namespace
}  // namespace grainlab::bench

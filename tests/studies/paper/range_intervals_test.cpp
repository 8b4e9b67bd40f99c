// Intervals that stay inside what a quantity can take: a t-interval cut at the ends of a
// bounded range (which keeps its coverage), and the circular interval of axial directions.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "grainlab/studies/paper/ensemble_stats.hpp"
#include "grainlab/studies/paper/findings.hpp"

namespace grainlab::report {
namespace {

constexpr ValueRange kShare{0.0, 1.0};

TEST(RangeInterval, CutAtTheRangeEndAndSaysSo) {
  // mean 0.99, s = 0.01: t(2)·s/√3 = 4.303 · 0.01 / 1.732 = 0.02484, so 0.96516 to 1.01484,
  // and a share cannot exceed 1.
  const MeanInterval m = meanIntervalInRange({0.99, 1.0, 0.98}, kShare);
  EXPECT_NEAR(m.mean, 0.99, 1e-15);
  EXPECT_NEAR(m.low, 0.99 - 0.024843, 1e-5);
  EXPECT_EQ(m.high, 1.0);
  EXPECT_EQ(m.method, IntervalMethod::StudentTInRange);
  EXPECT_EQ(intervalMethodText(m.method, 0, 1), "t, cut to [0, 1]");
  EXPECT_EQ(intervalMethodText(IntervalMethod::StudentTInRange, 0, INFINITY), "t, cut to [0, ∞]");
}

TEST(RangeInterval, InsideTheRangeItIsThePlainTInterval) {
  const std::vector<double> v{0.4, 0.5, 0.6, 0.55};
  const MeanInterval plain = meanInterval(v), inRange = meanIntervalInRange(v, kShare);
  EXPECT_EQ(inRange.low, plain.low);
  EXPECT_EQ(inRange.high, plain.high);
  EXPECT_EQ(inRange.method, IntervalMethod::StudentT);
  EXPECT_EQ(meanIntervalInRange({0.7}, kShare).method, IntervalMethod::None);
}

TEST(RangeInterval, CuttingNeverLosesTheTrueMean) {
  // Shares near 1 (Beta(20, 1), mean 20/21): over many small ensembles the cut interval holds
  // the true mean exactly as often as the t-interval does, since that mean lies in [0, 1].
  std::mt19937_64 rng(7);
  std::gamma_distribution<double> a(20.0, 1.0), b(1.0, 1.0);
  const double truth = 20.0 / 21.0;
  int plainHits = 0, cutHits = 0, cut = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::vector<double> v;
    for (int k = 0; k < 4; ++k) {
      const double x = a(rng), y = b(rng);
      v.push_back(x / (x + y));
    }
    const MeanInterval p = meanInterval(v), c = meanIntervalInRange(v, kShare);
    plainHits += p.low <= truth && truth <= p.high;
    cutHits += c.low <= truth && truth <= c.high;
    cut += c.method == IntervalMethod::StudentTInRange;
    EXPECT_GE(c.low, 0.0);
    EXPECT_LE(c.high, 1.0);
  }
  EXPECT_EQ(cutHits, plainHits);
  EXPECT_GT(cut, 1000);  // the case is common for shares near 1, not a corner
}

TEST(CircularInterval, ByHandForThreeDirectionsAcrossTheWrap) {
  // 170°, 176°, 4°: doubled 340°, 352°, 8°. Their resultant points at 2θ̄ = 353.32°, so
  // θ̄ = 176.66°; R̄ = 0.980063, ρ̂₂ = (1/3) Σ cos 2(2θ − 2θ̄) = 0.921445,
  // σ̂ = √((1 − ρ̂₂)/(2·2·R̄²)) = 0.142989, t(2)·σ̂ = 4.303 · 0.142989 = 0.615280,
  // arcsin = 37.972°, half of it 18.986°.
  const MeanInterval m = axialMeanInterval({170, 176, 4});
  EXPECT_EQ(m.n, 3);
  EXPECT_NEAR(m.mean, 176.660, 1e-3);
  EXPECT_NEAR(m.high - m.mean, 18.986, 1e-3);
  EXPECT_NEAR(m.mean - m.low, 18.986, 1e-3);
  EXPECT_EQ(m.method, IntervalMethod::Circular);
}

TEST(CircularInterval, TwoSeedsThatDisagreeBy6DegreesDoNotPlaceTheDirection) {
  // 178° and 4°: t(1) = 12.706 times σ̂ = 0.105 exceeds 1, so the interval is the whole period.
  const MeanInterval m = axialMeanInterval({178, 4});
  EXPECT_NEAR(m.mean, 1, 1e-9);
  EXPECT_NEAR(m.halfWidth(), 90.0, 1e-9);
}

TEST(CircularInterval, NarrowSpreadsGiveTheLinearInterval) {
  // For directions within a fraction of a degree the circle is a line: the interval is
  // t·s/√n of the offsets (here ±0.1° about 90.05°: s = 0.1155, t(3) = 3.182, half 0.1837°).
  const MeanInterval m = axialMeanInterval({89.95, 90.15, 89.95, 90.15});
  EXPECT_NEAR(m.mean, 90.05, 1e-9);
  const double linear = 3.182 * std::sqrt(4 * 0.01 / 3.0) / 2.0;
  EXPECT_NEAR(m.halfWidth(), linear, 1e-4 * linear);
}

TEST(CircularInterval, RotatingTheDataRotatesTheMeanAndKeepsTheWidth) {
  const std::vector<double> data{10, 25, 170, 5, 40};
  const MeanInterval base = axialMeanInterval(data);
  std::vector<double> turned;
  for (double t : data) turned.push_back(std::fmod(t + 137.0, 180.0));
  const MeanInterval m = axialMeanInterval(turned);
  EXPECT_NEAR(std::remainder(m.mean - base.mean - 137.0, 180.0), 0.0, 1e-9);
  EXPECT_NEAR(m.halfWidth(), base.halfWidth(), 1e-9);
  EXPECT_LT(base.halfWidth(), 90.0);
}

TEST(CircularInterval, DirectionsThatCancelAreNotLocated) {
  // 0°, 60°, 120°: their doubled angles sum to zero, so there is no mean direction to bound.
  const MeanInterval m = axialMeanInterval({0, 60, 120});
  EXPECT_NEAR(m.halfWidth(), 90.0, 1e-9);
  const MeanInterval same = axialMeanInterval({33, 33, 33});
  EXPECT_NEAR(same.mean, 33, 1e-9);
  EXPECT_NEAR(same.halfWidth(), 0.0, 1e-6);
}

Check shareCheck(double value) {
  Check c{"random: a_lt > a_ln", "", Verdict::Holds};
  c.quantity = "share of samples with a_lt > a_ln";
  c.value = value;
  c.holdsFrom = 0.75;
  c.range = kShare;
  return c;
}

TEST(MergedFindings, ABoundedCheckKeepsItsIntervalInItsRange) {
  std::vector<std::vector<Finding>> perSeed;
  for (double v : {0.99, 1.0, 0.98, 1.0}) {
    Finding f;
    f.number = 3;
    f.checks.push_back(shareCheck(v));
    perSeed.push_back({f});
  }
  const Check c = mergeSeedFindings(perSeed).front().checks.front();
  EXPECT_LE(c.ciHigh, 1.0);
  EXPECT_EQ(c.interval, IntervalMethod::StudentTInRange);
  EXPECT_EQ(c.verdict, Verdict::Holds);
}

TEST(SeedsToResolve, TheLeastEnsembleWhoseIntervalExcludesTheThreshold) {
  // mean 1, sd 2, threshold 0: need t(n − 1) · 2/√n < 1. At n = 18, t(17) = 2.110 gives
  // 0.9947 < 1; at n = 17, t(16) = 2.120 gives 1.0284: 18 seeds.
  EXPECT_EQ(seedsToExclude(1.0, 2.0, 0.0), 18);
  EXPECT_EQ(seedsToExclude(1.0, 2.0, 2.0), 18);  // the same gap above
  EXPECT_EQ(seedsToExclude(1.0, 2.0, 1.0), -1);  // on the threshold: no number of seeds
  EXPECT_EQ(seedsToExclude(1.0, 0.0, 0.0), 2);
}

TEST(MergedFindings, ANotResolvedCheckSaysHowManySeedsWouldResolveIt) {
  // Shares 0.85, 0.95, 0.85, 0.95 (mean 0.9, sd 0.0577) judged against "share ≥ 0.89": the
  // 4-seed interval straddles 0.89.
  std::vector<std::vector<Finding>> perSeed;
  std::vector<double> values;
  for (int k = 0; k < 4; ++k) {
    Finding f;
    f.number = 3;
    Check c = shareCheck(k % 2 ? 0.95 : 0.85);
    c.holdsFrom = 0.89;
    f.checks.push_back(c);
    perSeed.push_back({f});
    values.push_back(c.value);
  }
  const Check merged = mergeSeedFindings(perSeed).front().checks.front();
  ASSERT_EQ(merged.verdict, Verdict::NotResolved) << merged.measured;
  const MeanInterval m = meanInterval(values);
  EXPECT_EQ(merged.seedsToResolve, seedsToExclude(m.mean, m.sd, 0.89));
  // By hand: gap 0.01, so t(n − 1) · 0.0577/√n < 0.01 first at n = 131 (t ≈ 1.978).
  EXPECT_GT(merged.seedsToResolve, 120);
  EXPECT_LT(merged.seedsToResolve, 140);
  EXPECT_NE(merged.measured.find("seeds would resolve it"), std::string::npos);
}

}  // namespace
}  // namespace grainlab::report

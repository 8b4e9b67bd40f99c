// The seed-ensemble statistics: Student-t intervals, axial means across the wrap, bands on a
// common strain axis, and findings judged on an interval (holds / does not hold / not resolved).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "grainlab/studies/paper/ensemble_series.hpp"
#include "grainlab/studies/paper/ensemble_stats.hpp"
#include "grainlab/studies/paper/findings.hpp"
#include "synthetic_runs.hpp"

namespace grainlab::report {
namespace {

using testing::setColumn;
using testing::syntheticRun;

TEST(StudentT, TabulatedQuantiles) {
  EXPECT_NEAR(studentT975(1), 12.706, 1e-3);
  EXPECT_NEAR(studentT975(4), 2.776, 1e-3);
  EXPECT_NEAR(studentT975(30), 2.042, 1e-3);
  EXPECT_NEAR(studentT975(60), 2.000, 2e-3);   // statistics tables: 2.000
  EXPECT_NEAR(studentT975(120), 1.980, 2e-3);  // 1.980
  EXPECT_TRUE(std::isnan(studentT975(0)));
}

TEST(MeanInterval, ByHandForThreeValues) {
  // mean 2, s = 1, half-width t(2) · 1/√3 = 4.303/1.732 = 2.484.
  const MeanInterval m = meanInterval({1, 2, 3, NAN});
  EXPECT_EQ(m.n, 3);
  EXPECT_DOUBLE_EQ(m.mean, 2);
  EXPECT_NEAR(m.low, 2 - 2.4843, 1e-3);
  EXPECT_NEAR(m.high, 2 + 2.4843, 1e-3);
}

TEST(MeanInterval, OneValueHasNoIntervalAndIdenticalValuesAZeroWidthOne) {
  const MeanInterval one = meanInterval({0.21});
  EXPECT_EQ(one.n, 1);
  EXPECT_DOUBLE_EQ(one.mean, 0.21);
  EXPECT_FALSE(one.hasInterval());
  EXPECT_TRUE(std::isnan(one.low) && std::isnan(one.high));
  const MeanInterval same = meanInterval({0.21, 0.21, 0.21, 0.21});
  EXPECT_EQ(same.low, 0.21);
  EXPECT_EQ(same.high, 0.21);
  EXPECT_EQ(meanInterval({NAN}).n, 0);
  EXPECT_TRUE(std::isnan(meanInterval({}).mean));
}

TEST(MeanInterval, AxialDirectionsAverageAcrossTheWrap) {
  // 178°, 4° and 2° lie within 6° of each other through 0°: mean 1.33°, and a symmetric
  // interval about it (its width by hand in range_intervals_test.cpp).
  const MeanInterval m = axialMeanInterval({178, 4, 2});
  EXPECT_NEAR(m.mean, 4.0 / 3.0, 1e-2);
  EXPECT_NEAR(m.high - m.mean, m.mean - m.low, 1e-9);
  EXPECT_GT(m.halfWidth(), 3.0);
  EXPECT_LT(m.halfWidth(), 90.0);
}

TEST(EnsembleBand, HalfWidthIsTTimesTheSpreadOverRootNAndVanishesForIdenticalRuns) {
  // Eight synthetic runs whose a_c differs by a fixed offset per seed (spread ±0.02 around the
  // closed form). At every strain the runs differ only by the offsets, so the band's half-width
  // over the first n runs is t_0.975(n−1)·s_n/√n with s_n the offsets' sample deviation:
  // by hand 12.706·0.020506/√2 = 0.18424, 3.182·0.015588/√4 = 0.024801, 2.365·0.014675/√8 = 0.012271.
  const double offsets[] = {0.012, -0.017, 0.004, 0.019, -0.008, -0.003, 0.015, -0.020};
  std::vector<AssemblyResult> runs;
  for (int s = 0; s < 8; ++s) {
    AssemblyResult a = syntheticRun(AssemblyKind::Circular);
    a.seed = s + 1;
    setColumn(a, "a_c", [&, s](double e) { return 0.1 + 2 * e + offsets[s]; });
    runs.push_back(a);
  }
  auto widthOver = [&](size_t n) {
    const auto groups = groupEnsembles(std::span<const AssemblyResult>(runs.data(), n));
    const EnsembleBand b = ensembleColumn(groups.at(0), "a_c");
    EXPECT_EQ(b.perRun.size(), n);
    return b.stats.at(10).halfWidth();
  };
  // t quantiles from a statistics table; the sample deviation by its definition.
  auto expected = [&](size_t n, double t) {
    double mean = 0, squares = 0;
    for (size_t s = 0; s < n; ++s) mean += offsets[s] / n;
    for (size_t s = 0; s < n; ++s) squares += (offsets[s] - mean) * (offsets[s] - mean);
    return t * std::sqrt(squares / (n - 1)) / std::sqrt(static_cast<double>(n));
  };
  // 1e-3 relative: the tables' three decimals of t.
  EXPECT_NEAR(widthOver(2), expected(2, 12.706), 1e-3 * 0.18424);
  EXPECT_NEAR(widthOver(4), expected(4, 3.182), 1e-3 * 0.024801);
  EXPECT_NEAR(widthOver(8), expected(8, 2.365), 1e-3 * 0.012271);
  EXPECT_NEAR(expected(8, 2.365), 0.012271, 1e-6);  // the hand figure above

  std::vector<AssemblyResult> same(5, syntheticRun(AssemblyKind::Circular));
  for (size_t s = 0; s < same.size(); ++s) same[s].seed = static_cast<int>(s) + 1;
  const auto groups = groupEnsembles(same);
  const EnsembleBand b = ensembleColumn(groups.at(0), "a_c");
  for (const MeanInterval& m : b.stats) {
    EXPECT_EQ(m.n, 5);
    EXPECT_EQ(m.low, m.mean);
    EXPECT_EQ(m.high, m.mean);
  }
}

TEST(EnsembleBand, RunsSampledAtOtherStrainsAreInterpolated) {
  AssemblyResult coarse = syntheticRun(AssemblyKind::Circular, 0, 41), fine = syntheticRun(AssemblyKind::Circular, 0, 81);
  fine.seed = 2;
  setColumn(coarse, "p", [](double e) { return 1000 * e; });
  setColumn(fine, "p", [](double e) { return 1000 * e + 2; });
  const std::vector<AssemblyResult> runs{coarse, fine};
  const EnsembleBand b = ensembleColumn(groupEnsembles(runs).at(0), "p");
  ASSERT_EQ(b.strain.size(), 41u);  // the first run's samples
  for (size_t k = 0; k < b.strain.size(); ++k) EXPECT_NEAR(b.stats[k].mean, 1000 * b.strain[k] + 1, 1e-9);
}

Check checkOf(double value) {
  Check c{"α = 30°", "", Verdict::Inconclusive};
  c.quantity = "ω at onset (°)";
  c.value = value;
  c.holdsFrom = 0;
  c.verdict = value >= 0 ? Verdict::Holds : Verdict::DoesNotHold;
  return c;
}

std::vector<std::vector<Finding>> seedsOf(const std::vector<double>& values) {
  std::vector<std::vector<Finding>> out;
  for (double v : values) {
    Finding f;
    f.number = 8;
    f.checks.push_back(checkOf(v));
    f.verdict = f.checks.back().verdict;  // as the evaluators leave it
    out.push_back({f});
  }
  return out;
}

TEST(EnsembleFindings, TheIntervalDecides) {
  // Clearly positive: holds. Clearly negative: does not hold. Straddling zero: not resolved.
  const auto holds = mergeSeedFindings(seedsOf({3.0, 3.5, 2.8, 3.1}));
  EXPECT_EQ(holds.at(0).verdict, Verdict::Holds);
  const Check& c = holds[0].checks.at(0);
  EXPECT_EQ(c.seeds, 4);
  EXPECT_NEAR(c.value, 3.1, 1e-12);
  EXPECT_LT(c.ciLow, 3.1);
  EXPECT_GT(c.ciHigh, 3.1);
  EXPECT_EQ(mergeSeedFindings(seedsOf({-3.0, -3.5, -2.8, -3.1})).at(0).verdict, Verdict::DoesNotHold);
  const auto open = mergeSeedFindings(seedsOf({2.0, -1.0, 1.5, -0.5}));
  EXPECT_EQ(open.at(0).verdict, Verdict::NotResolved);
  EXPECT_EQ(verdictText(open[0].verdict, 4), "not resolved at 4 seeds");
  // Every seed on the holding side, but the interval still crosses zero: not resolved.
  EXPECT_EQ(mergeSeedFindings(seedsOf({0.1, 5.0})).at(0).verdict, Verdict::NotResolved);
  // One seed: judged on its value, no interval invented.
  const auto single = mergeSeedFindings(seedsOf({1.0}));
  EXPECT_EQ(single.at(0).verdict, Verdict::Holds);
  EXPECT_TRUE(std::isnan(single[0].checks[0].ciLow));
}

TEST(EnsembleFindings, SeedsThatMeasuredNothingAreLeftOutAndSaidSo) {
  const auto merged = mergeSeedFindings(seedsOf({3.0, NAN, 3.2}));
  const Check& c = merged.at(0).checks.at(0);
  EXPECT_EQ(c.seeds, 2);
  EXPECT_EQ(c.runs, 3);
  EXPECT_NE(c.measured.find("2 of 3 seeds"), std::string::npos) << c.measured;
}

}  // namespace
}  // namespace grainlab::report

// The ensemble trade-off's statistics against closed forms: the t-interval of a mean of
// differences, Welch's interval, axial differences wrapped into (−90°, 90°], a planted bias
// found, a zero bias not, and the runs a tolerance needs.
#include <gtest/gtest.h>

#include <cmath>

#include "grainlab/studies/tradeoff/paired_bias.hpp"

namespace grainlab::tradeoff {
namespace {

TEST(PairedBias, IntervalOfThreeDifferencesIsTheClosedForm) {
  // mean 2, sd 1, t_{0.975, 2} = 4.303: half-width 4.303/√3.
  const BiasEstimate e = pairedBias({1, 2, 3}, 1.0);
  EXPECT_EQ(e.seeds, 3);
  EXPECT_DOUBLE_EQ(e.bias, 2.0);
  EXPECT_DOUBLE_EQ(e.sd, 1.0);
  EXPECT_NEAR(e.low, 2.0 - 4.303 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(e.high, 2.0 + 4.303 / std::sqrt(3.0), 1e-12);
  EXPECT_EQ(e.verdict, "undecided at 3 seeds");  // holds 0 and reaches past ±1
  EXPECT_EQ(e.runsForTolerance, 19);             // ⌈(4.303·1/1)²⌉ = ⌈18.52⌉
}

TEST(PairedBias, SeedsWithoutAValueAreLeftOut) {
  const BiasEstimate e = pairedBias({1, std::nan(""), 2, 3}, 1.0);
  EXPECT_EQ(e.seeds, 3);
  EXPECT_DOUBLE_EQ(e.bias, 2.0);
}

TEST(PairedBias, PlantedBiasIsFound) {
  // 0.5 plus deterministic noise of sd ~0.03 over 10 seeds: the interval is about ±0.02.
  std::vector<double> d;
  for (int k = 0; k < 10; ++k) d.push_back(0.5 + 0.01 * (k - 4.5));
  const BiasEstimate e = pairedBias(d, 0.1);
  EXPECT_GT(e.low, 0.45);
  EXPECT_LT(e.high, 0.55);
  EXPECT_EQ(e.verdict.rfind("biased by 0.5 (", 0), 0u) << e.verdict;
  EXPECT_EQ(e.verdict.find("within"), std::string::npos) << e.verdict;
  // Within a tolerance larger than the bias, it is still a bias, and said so.
  EXPECT_NE(pairedBias(d, 1.0).verdict.find(", within tolerance"), std::string::npos);
}

TEST(PairedBias, ZeroBiasIsNoBiasFound) {
  const BiasEstimate e = pairedBias({-0.1, 0.1, -0.2, 0.2, -0.1, 0.1, 0.0, 0.0}, 1.0);
  EXPECT_NEAR(e.bias, 0.0, 1e-15);
  EXPECT_LT(e.low, 0);
  EXPECT_GT(e.high, 0);
  EXPECT_EQ(e.verdict, "no bias found at 8 seeds");
}

TEST(PairedBias, OneSeedHasNoInterval) {
  const BiasEstimate e = pairedBias({0.3}, 1.0);
  EXPECT_TRUE(std::isnan(e.low));
  EXPECT_EQ(e.verdict, "undecided at 1 seeds");
}

TEST(UnpairedBias, WelchAgainstAConstantReferenceIsTheOneSampleInterval) {
  // The reference has no spread: Welch's dof is the setting's n − 1 and the interval the
  // one-sample interval of the setting around the reference's value.
  const BiasEstimate e = unpairedBias({1, 2, 3}, {0, 0, 0, 0}, 1.0, false);
  EXPECT_DOUBLE_EQ(e.bias, 2.0);
  EXPECT_NEAR(e.high - e.bias, 4.303 / std::sqrt(3.0), 1e-12);
}

TEST(UnpairedBias, EqualGroupsGiveWelchsDegreesOfFreedom) {
  // Two groups of 4 with equal variance: dof = 6, t = 2.447, se = √(2 s²/4).
  const BiasEstimate e = unpairedBias({1, 2, 3, 4}, {0, 1, 2, 3}, 1.0, false);
  const double s2 = 5.0 / 3.0;
  EXPECT_DOUBLE_EQ(e.bias, 1.0);
  EXPECT_NEAR(e.high - e.bias, 2.447 * std::sqrt(2 * s2 / 4), 1e-12);
  EXPECT_EQ(e.seeds, 4);
}

TEST(UnpairedBias, AxialDirectionsAcrossTheWrapAreClose) {
  // 89° and −89° (= 91°) are 2° apart, not 178°.
  const BiasEstimate e = unpairedBias({-89, -88, -89, -90}, {89, 90, 89, 88}, 5.0, true);
  EXPECT_NEAR(e.bias, 2.0, 1e-9);
}

TEST(Difference, AxialIsWrappedIntoMinus90To90) {
  EXPECT_DOUBLE_EQ(difference(89, -89, true), -2);
  EXPECT_DOUBLE_EQ(difference(-89, 89, true), 2);
  EXPECT_DOUBLE_EQ(difference(90, 0, true), 90);
  EXPECT_DOUBLE_EQ(difference(0, 90, true), 90);  // −90 is the same axis as +90
  EXPECT_DOUBLE_EQ(difference(10, 5, true), 5);
  EXPECT_DOUBLE_EQ(difference(179, 0, true), -1);
  EXPECT_DOUBLE_EQ(difference(179, 0, false), 179);
}

}  // namespace
}  // namespace grainlab::tradeoff

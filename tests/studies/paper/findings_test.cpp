// The findings' evaluators on synthetic series whose answers are known.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "grainlab/studies/paper/findings.hpp"
#include "grainlab/studies/paper/series_stats.hpp"
#include "synthetic_runs.hpp"

namespace grainlab::report {
namespace {

using testing::setColumn;
using testing::syntheticRun;

std::vector<AssemblyResult> one(AssemblyResult a) { return {std::move(a)}; }

TEST(Verdicts, CombineFailureFirstThenDoubt) {
  EXPECT_EQ(combine({Verdict::Holds, Verdict::Holds}), Verdict::Holds);
  EXPECT_EQ(combine({Verdict::Holds, Verdict::Inconclusive}), Verdict::Inconclusive);
  EXPECT_EQ(combine({Verdict::Inconclusive, Verdict::DoesNotHold, Verdict::Holds}), Verdict::DoesNotHold);
  EXPECT_EQ(combine({}), Verdict::Inconclusive);
  EXPECT_EQ(verdictText(Verdict::DoesNotHold), "does not hold");
}

TEST(SeriesStats, AxialAveragesSkipMissingValues) {
  EXPECT_NEAR(axialDistanceDeg(179, 1), 2, 1e-12);
  EXPECT_NEAR(axialDistanceDeg(0, 90), 90, 1e-12);
  const double m = axialMeanDeg({178, 2, NAN});
  EXPECT_LT(std::min(m, 180 - m), 1e-9);
  EXPECT_NEAR(noiseFloor(2500), 0.0354, 1e-4);
  EXPECT_NEAR(finiteMedian({3, NAN, 1, 2}), 2, 1e-12);
  const LinearTrend exact = linearTrend({0, 1, 2, 3}, {1, 3, 5, 7});
  EXPECT_NEAR(exact.slope, 2, 1e-12);
  EXPECT_NEAR(exact.standardError, 0, 1e-12);
  EXPECT_TRUE(exact.risesBeyond(2));
  // y = 1, 3, 1, 3, ...: a slope well inside its error.
  const LinearTrend noisy = linearTrend({0, 1, 2, 3, 4, 5}, {1, 3, 1, 3, 1, 3});
  EXPECT_GT(noisy.slope, 0);
  EXPECT_FALSE(noisy.risesBeyond(2));
  EXPECT_TRUE(std::isnan(linearTrend({1, 2}, {1, 2}).slope));
}

TEST(OmegaDecay, DecayingOmegaHolds) {
  const Finding f = findOmegaDecay(one(syntheticRun(AssemblyKind::Circular)));
  EXPECT_EQ(f.verdict, Verdict::Holds) << f.checks.at(0).measured;
}

TEST(OmegaDecay, GrowingOmegaDoesNotHold) {
  AssemblyResult a = syntheticRun(AssemblyKind::Random);
  setColumn(a, "omega_macro_deg", [](double e) { return 2 + 50 * e; });
  EXPECT_EQ(findOmegaDecay(one(a)).verdict, Verdict::DoesNotHold);
}

TEST(OmegaDecay, RisingAgainAfterThePeakDoesNotHold) {
  AssemblyResult a = syntheticRun(AssemblyKind::Random);
  // Falls from 10° to 1° up to the φ_mob peak at 10 %, then climbs back to 4°: still lower at
  // the end than at the start, but not decreasing after the peak.
  setColumn(a, "omega_macro_deg", [](double e) { return e <= 0.1 ? 10 - 90 * e : 1 + 30 * (e - 0.1); });
  EXPECT_EQ(findOmegaDecay(one(a)).verdict, Verdict::DoesNotHold);
}

TEST(OmegaDecay, FastDecayThenNoiseAroundZeroHolds) {
  AssemblyResult a = syntheticRun(AssemblyKind::Bedding, 30);
  // Gone within a few % strain, then ±0.8° of scatter: a slope after the peak within its noise.
  setColumn(a, "omega_macro_deg", [](double e) { return 7 * std::exp(-e / 0.01) + 0.8 * std::sin(900 * e); });
  EXPECT_EQ(findOmegaDecay(one(a)).verdict, Verdict::Holds) << findOmegaDecay(one(a)).checks.at(0).measured;
}

TEST(OmegaDecay, OmegaThatIsNeverThereIsInconclusive) {
  AssemblyResult a = syntheticRun(AssemblyKind::Circular);
  setColumn(a, "omega_macro_deg", [](double e) { return 0.5 * std::cos(100 * e); });
  EXPECT_EQ(findOmegaDecay(one(a)).verdict, Verdict::Inconclusive);
}

TEST(StressSymmetry, SmallAsymmetryHoldsLargeDoesNot) {
  AssemblyResult a = syntheticRun(AssemblyKind::Bedding, 30);
  EXPECT_EQ(findStressSymmetry(one(a)).verdict, Verdict::Holds);
  setColumn(a, "sigma21", [](double) { return 1e3 + 0.05 * 300e3; });
  EXPECT_EQ(findStressSymmetry(one(a)).verdict, Verdict::DoesNotHold);
}

TEST(CircularFabric, ZeroBranchAnisotropyAndDirectionsTurningTo90Hold) {
  const Finding f = findCircularFabric(one(syntheticRun(AssemblyKind::Circular)));
  EXPECT_EQ(f.verdict, Verdict::Holds);
  ASSERT_EQ(f.checks.size(), 4u);  // branch vectors, coincidence, away from 90° at the start, turned to 90°
}

TEST(CircularFabric, NoisyStartIsInconclusiveNotFailed) {
  AssemblyResult a = syntheticRun(AssemblyKind::Circular);
  setColumn(a, "a_c", [](double e) { return e == 0 ? 0.03 : 0.1 + 2 * e; });  // below 2 × 0.035 at the start
  const Finding f = findCircularFabric(one(a));
  EXPECT_EQ(f.checks.at(2).verdict, Verdict::Inconclusive);
  EXPECT_EQ(f.verdict, Verdict::Inconclusive);
  EXPECT_FALSE(evaluateFindings(one(a)).at(1).note.empty());
}

TEST(CircularFabric, BranchAnisotropyOfDiscsDoesNotHold) {
  AssemblyResult a = syntheticRun(AssemblyKind::Circular);
  setColumn(a, "a_ln", [](double) { return 0.02; });
  EXPECT_EQ(findCircularFabric(one(a)).checks.at(0).verdict, Verdict::DoesNotHold);
}

TEST(RandomBranchVectors, SmallWithTangentialLargerHolds) {
  AssemblyResult a = syntheticRun(AssemblyKind::Random);
  setColumn(a, "a_ln", [](double) { return 0.03; });
  setColumn(a, "a_lt", [](double) { return 0.06; });
  EXPECT_EQ(findRandomBranchVectors(one(a)).verdict, Verdict::Holds);
  setColumn(a, "a_ln", [](double) { return 0.08; });
  EXPECT_EQ(findRandomBranchVectors(one(a)).verdict, Verdict::DoesNotHold);
}

AssemblyResult bedded(double alpha) {
  AssemblyResult a = syntheticRun(AssemblyKind::Bedding, alpha);
  setColumn(a, "theta_c_deg", [alpha](double e) { return 90 + alpha * std::exp(-e / 0.04); });
  for (const char* t : {"ln", "lt"}) {
    setColumn(a, std::string("a_") + t, [](double) { return 0.2; });
    setColumn(a, std::string("theta_") + t + "_deg", [alpha](double e) { return alpha + 3 * std::sin(50 * e); });
  }
  return a;
}

TEST(BeddingFabric, TheBeddingSignaturesHold) {
  const std::vector<AssemblyResult> runs{bedded(0), bedded(30), bedded(60), bedded(90)};
  const Finding f = findBeddingFabric(runs);
  for (const Check& c : f.checks) EXPECT_EQ(c.verdict, Verdict::Holds) << c.subject << ": " << c.measured;
  EXPECT_EQ(f.verdict, Verdict::Holds);
}

TEST(BeddingFabric, TheA_cMagnitudeForSixtyDegreesIsMeasuredBesideThePapersValue) {
  // a_c = 0.1 + 2ε: over the second half (ε from 0.1 to 0.2) its mean is 0.1 + 2 · 0.15 = 0.4.
  const std::vector<AssemblyResult> runs{bedded(30), bedded(60)};
  const Finding f = findBeddingFabric(runs);
  int rows = 0;
  for (const Check& c : f.checks) {
    if (c.quantity != "mean a_c over the second half of the shearing") continue;
    ++rows;
    EXPECT_EQ(c.subject.rfind("α = 60°", 0), 0u) << c.subject;
    EXPECT_NEAR(c.value, 0.4, 1e-12);
    EXPECT_TRUE(c.diagnostic);
  }
  EXPECT_EQ(rows, 1);
}

TEST(BeddingFabric, BranchDirectionsAwayFromTheBeddingDoNotHold) {
  AssemblyResult a = bedded(30);
  setColumn(a, "theta_lt_deg", [](double) { return 80.0; });
  EXPECT_EQ(findBeddingFabric(one(a)).verdict, Verdict::DoesNotHold);
}

TEST(BeddingFabric, DifferentStartingAnisotropyDoesNotHold) {
  std::vector<AssemblyResult> runs{bedded(0), bedded(90)};
  setColumn(runs[1], "a_c", [](double e) { return 0.5 + e; });  // 0.1 for α = 0
  const Finding f = findBeddingFabric(runs);
  EXPECT_EQ(f.checks.back().verdict, Verdict::DoesNotHold) << f.checks.back().measured;
}

TEST(MicroExpressions, Eq7FollowsAndEq11FailsForBedding) {
  AssemblyResult a = bedded(30);
  setColumn(a, "omega_micro_deg", [](double e) { return 8 * std::exp(-e / 0.05) + 0.5; });
  setColumn(a, "omega_eq11_deg", [](double e) { return 8 * std::exp(-e / 0.05) + 12; });
  EXPECT_EQ(findMicroExpressions(one(a)).verdict, Verdict::Holds);
  // Where Eq. (11) is as good as Eq. (7) the paper's claim that it fails does not hold.
  setColumn(a, "omega_eq11_deg", [](double e) { return 8 * std::exp(-e / 0.05) + 0.5; });
  EXPECT_EQ(findMicroExpressions(one(a)).verdict, Verdict::DoesNotHold);
}

TEST(MicroExpressions, Eq10OffTheStressDoesNotHoldForCircular) {
  AssemblyResult a = syntheticRun(AssemblyKind::Circular);
  setColumn(a, "omega_eq10_deg", [](double) { return 20.0; });
  const Finding f = findMicroExpressions(one(a));
  EXPECT_EQ(f.checks.at(0).verdict, Verdict::Holds);
  EXPECT_EQ(f.checks.at(1).verdict, Verdict::DoesNotHold);
}

TEST(VoidRatios, InsideThePapersRangeHoldsOutsideDoesNot) {
  AssemblyResult a = syntheticRun(AssemblyKind::Circular);
  a.summary.voidRatioAfterConsolidation = 0.282;
  EXPECT_EQ(findVoidRatios(one(a)).verdict, Verdict::Holds);
  a.summary.voidRatioAfterConsolidation = 0.22;
  EXPECT_EQ(findVoidRatios(one(a)).verdict, Verdict::DoesNotHold);
  EXPECT_DOUBLE_EQ(paperVoidRatio(bedded(60)), 0.272);
}

TEST(OmegaOnsetSign, PositiveAndDecayingHoldsNegativeDoesNot) {
  AssemblyResult a = syntheticRun(AssemblyKind::Bedding, 30);
  Finding f = findOmegaOnsetSign(one(a));
  EXPECT_EQ(f.verdict, Verdict::Holds) << f.checks.at(0).measured;
  // The onset is the first sample at or beyond 0.2 % with φ_mob ≥ 5°: ε22 = 0.25 %, ω = 8·exp(−0.0025/0.05).
  EXPECT_NEAR(f.checks.at(0).value, 8 * std::exp(-0.0025 / 0.05), 1e-9);
  // The pushes a_k sin 2(θ_k − 90°) are reported but do not judge the claim.
  int diagnostics = 0;
  for (const Check& c : f.checks) diagnostics += c.diagnostic;
  EXPECT_EQ(diagnostics, 13);  // ω by Eqs. 7 and 11, five pushes at ε22 = 0 and at the onset, θ_n(0)
  setColumn(a, "omega_macro_deg", [](double e) { return -6 * std::exp(-e / 0.05); });
  f = findOmegaOnsetSign(one(a));
  EXPECT_EQ(f.checks.at(0).verdict, Verdict::DoesNotHold);
  EXPECT_EQ(f.verdict, Verdict::DoesNotHold);
  // α = 0° and 90° have no tilt to have a sign: the claim is about 30° and 60° only.
  EXPECT_EQ(findOmegaOnsetSign(one(syntheticRun(AssemblyKind::Bedding, 90))).verdict, Verdict::Inconclusive);
}

TEST(Findings, FailedOrMissingRunsMakeClaimsInconclusive) {
  AssemblyResult a = syntheticRun(AssemblyKind::Circular);
  a.summary.status = RunStatus::Failed;
  const auto all = evaluateFindings(one(a));
  ASSERT_EQ(all.size(), 8u);
  for (const Finding& f : all) {
    EXPECT_EQ(f.verdict, Verdict::Inconclusive) << f.number;
    EXPECT_FALSE(f.note.empty());
  }
}

}  // namespace
}  // namespace grainlab::report

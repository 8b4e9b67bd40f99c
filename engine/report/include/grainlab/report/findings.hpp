#pragma once
// The paper's claims (sections 4-6), each evaluated on the measured series: what was measured
// and whether the claim holds, does not hold, or cannot be told from the data. Every number
// comes from the runs; the criteria are the constants below.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "grainlab/report/assembly_result.hpp"

namespace grainlab::report {

enum class Verdict { Holds, DoesNotHold, Inconclusive };

/// "holds", "does not hold", "inconclusive".
std::string verdictText(Verdict v);
/// Does not hold if any part does not; otherwise inconclusive if any part is; otherwise holds.
/// An empty list is inconclusive.
Verdict combine(const std::vector<Verdict>& parts);

/// One measured part of a claim, for one assembly or for a group of them.
struct Check {
  std::string subject;   ///< e.g. "α = 30°", "all six"
  std::string measured;  ///< the numbers, as text
  Verdict verdict = Verdict::Inconclusive;
};

struct Finding {
  int number = 0;                ///< 1..7, as in the report's table
  std::string claim;             ///< the paper's claim, in a sentence
  std::string criterion;         ///< how "holds" is decided here
  std::vector<Check> checks;
  Verdict verdict = Verdict::Inconclusive;  ///< combine() of the checks
  std::string note;              ///< where it does not hold: the likely reasons
};

/// The criteria (units in the names).
namespace criteria {
inline constexpr double kAsymmetryOverP = 0.01;        ///< max |σ12 − σ21| / p
inline constexpr double kDiscBranchAnisotropy = 1e-3;  ///< a_ln, a_lt of discs
inline constexpr double kCoincideDeg = 10.0;           ///< median spread of θ_c, θ_n, θ_t
inline constexpr double kAwayFromAxisDeg = 10.0;       ///< "away from 90°" / "at 90°"
inline constexpr double kNearDirectionDeg = 15.0;      ///< "near 90° + α", "near α"
inline constexpr double kSmallBranchAnisotropy = 0.1;  ///< "small" a_ln, a_lt (medians)
inline constexpr double kMostRows = 0.75;              ///< share of samples for "a_lt > a_ln"
inline constexpr double kSameStartRelative = 0.25;     ///< spread of a_c(0) over its mean
inline constexpr double kMinPhiMobDeg = 5.0;           ///< below it θσ (and ω) mean nothing
inline constexpr double kOmegaSignalDeg = 2.0;         ///< |ω| below this, at onset and end, is no signal
inline constexpr double kOnsetFraction = 0.1;          ///< "onset": the first 10 % of the final strain
inline constexpr double kTrendSigmas = 2.0;            ///< a rise after the peak must clear 2 standard errors
inline constexpr size_t kMinSamplesAfterPeak = 4;      ///< to judge the trend of |ω| after the peak
inline constexpr double kEquationDeg = 5.0;            ///< median |ω_eq − ω_macro| that "follows"
inline constexpr double kVoidRatioLow = 0.255;         ///< 0.26 at two decimals
inline constexpr double kVoidRatioHigh = 0.285;        ///< 0.28 at two decimals
}  // namespace criteria

/// The paper's void ratio after consolidation for an assembly (section 4), NaN if it gives none.
double paperVoidRatio(const AssemblyResult& a);

// Each takes every assembly that ran; those a claim is not about, or whose run did not
// complete, are left out (and a claim about none of them is inconclusive).
Finding findStressSymmetry(std::span<const AssemblyResult> runs);        ///< 1
Finding findCircularFabric(std::span<const AssemblyResult> runs);        ///< 2
Finding findRandomBranchVectors(std::span<const AssemblyResult> runs);   ///< 3
Finding findBeddingFabric(std::span<const AssemblyResult> runs);         ///< 4
Finding findOmegaDecay(std::span<const AssemblyResult> runs);            ///< 5
Finding findMicroExpressions(std::span<const AssemblyResult> runs);      ///< 6
Finding findVoidRatios(std::span<const AssemblyResult> runs);            ///< 7

/// All seven, in order, with notes on the likely reasons wherever a claim does not hold or
/// cannot be told.
std::vector<Finding> evaluateFindings(std::span<const AssemblyResult> runs);

}  // namespace grainlab::report

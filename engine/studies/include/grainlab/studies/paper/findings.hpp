#pragma once
// The paper's claims (sections 4-6), each evaluated on the measured series: what was measured
// and whether the claim holds, does not hold, or cannot be told from the data. Every number
// comes from the runs; the criteria are the constants below.
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "grainlab/studies/paper/assembly_result.hpp"
#include "grainlab/studies/paper/ensemble_stats.hpp"

namespace grainlab::report {

/// NotResolved: over a seed ensemble, the 95 % interval of the measured quantity straddles the
/// criterion's threshold, so more seeds could still decide it either way.
enum class Verdict { Holds, DoesNotHold, NotResolved, Inconclusive };

/// "holds", "does not hold", "not resolved at N seeds", "inconclusive".
std::string verdictText(Verdict v, int seeds = 0);
/// Does not hold if any part does not; otherwise not resolved if any part is; otherwise
/// inconclusive if any part is; otherwise holds. An empty list is inconclusive.
Verdict combine(const std::vector<Verdict>& parts);

/// One measured part of a claim, for one assembly or for a group of them: a scalar quantity
/// and the range in which the claim holds. Over a seed ensemble the quantity is the mean
/// over seeds, judged by its 95 % interval (ensemble_stats.hpp).
struct Check {
  Check() = default;
  Check(std::string subject_, std::string measured_, Verdict verdict_)
      : subject(std::move(subject_)), measured(std::move(measured_)), verdict(verdict_) {}
  std::string subject;   ///< e.g. "α = 30°", "all six"
  std::string measured;  ///< the numbers, as text
  Verdict verdict = Verdict::Inconclusive;
  std::string quantity;  ///< what value is, e.g. "max |σ12 − σ21|/p"
  double value = std::nan("");  ///< the quantity (the mean over seeds); NaN if not measured
  double holdsFrom = -std::numeric_limits<double>::infinity();  ///< holds for value in [holdsFrom, holdsTo]
  double holdsTo = std::numeric_limits<double>::infinity();
  int seeds = 1;         ///< runs whose value was finite
  int runs = 1;          ///< runs that were judged
  double ciLow = std::nan(""), ciHigh = std::nan("");  ///< 95 % interval of the mean; NaN with one seed
  /// Measured to explain another check, not a criterion: left out of the finding's verdict.
  bool diagnostic = false;
  bool axial = false;    ///< value is an axial direction (degrees): averaged on 2θ
  ValueRange range;      ///< the values the quantity can take; its interval stays inside
  IntervalMethod interval = IntervalMethod::None;  ///< how ciLow, ciHigh were computed
  /// Not resolved: the seeds that would resolve it if the mean and the seed-to-seed spread
  /// stayed as measured (seedsToExclude of the threshold inside the interval); −1 otherwise.
  int seedsToResolve = -1;
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
inline constexpr double kOnsetStrain = 0.002;          ///< ε22 at which ω's onset sign is read (0.2 %)
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
Finding findOmegaOnsetSign(std::span<const AssemblyResult> runs);        ///< 8

/// All eight on one run per assembly (one seed), in order, without notes.
std::vector<Finding> evaluateSeedFindings(std::span<const AssemblyResult> runs);

/// Merges the findings of each seed (same claims, one list per seed): each check's value
/// becomes the mean over the seeds that measured it with its 95 % interval (ensemble_stats.hpp:
/// t, cut to the check's range; circular for axial directions), and its verdict
/// holds when the whole interval lies in the holding range, does not hold when none of it
/// does, and is not resolved otherwise. With one seed the checks are returned as they were.
std::vector<Finding> mergeSeedFindings(const std::vector<std::vector<Finding>>& perSeed);

/// All eight, in order, judged on the ensemble: `runs` may hold several seeds of each
/// assembly (AssemblyResult::seed); the findings are evaluated seed by seed and merged, with
/// notes on the likely reasons wherever a claim does not hold or cannot be told.
std::vector<Finding> evaluateFindings(std::span<const AssemblyResult> runs);

}  // namespace grainlab::report

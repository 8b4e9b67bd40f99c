#pragma once
// The statistics of `grainlab tradeoff --seeds N`: how far a setting moves a quantity from the
// reference, with a 95% interval over seeds, and whether that is a bias or chance.
//
// Paired: the setting and the reference ran on the same specimen (one per seed); the bias is
// the mean of the per-seed differences, its interval the Student-t interval of that mean.
// Unpaired: each ran on its own specimens; the bias is the difference of the means, its
// interval Welch's.
#include <limits>
#include <string>
#include <vector>

namespace grainlab::tradeoff {

/// a − b; for axial directions (degrees) the shorter way round, in (−90°, 90°].
double difference(double a, double b, bool axial);

struct BiasEstimate {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  int seeds = 0;           ///< paired: seeds with both values finite; unpaired: the smaller group
  double bias = kNaN;      ///< setting − reference
  double low = kNaN, high = kNaN;  ///< its 95% interval; NaN with fewer than 2 seeds
  /// Seed-to-seed standard deviation: of the differences (paired), or of the setting's values
  /// (unpaired).
  double sd = kNaN;
  double t = kNaN;         ///< the Student-t quantile the interval used
  /// Runs per setting that bring the interval's half-width to the tolerance: ⌈(t·s/tol)²⌉ with
  /// s the differences' sd (paired) or √(s_setting² + s_reference²) (unpaired), and t this
  /// estimate's quantile (a slight overestimate once more seeds lower t).
  double runsForTolerance = kNaN;
  std::string verdict;
};

/// From the per-seed differences setting − reference (NaNs are seeds that did not measure it).
BiasEstimate pairedBias(const std::vector<double>& differences, double tolerance);
/// From each group's values (NaNs skipped); `axial`: degrees of direction, each value taken
/// the shorter way round from the reference's circular mean.
BiasEstimate unpairedBias(const std::vector<double>& setting, const std::vector<double>& reference, double tolerance,
                          bool axial);

/// "no bias found at N seeds" when the interval lies inside ±tolerance and holds 0; "biased by
/// X (lo to hi)" when it excludes 0 (", within tolerance" if it also lies inside ±tolerance);
/// otherwise "undecided at N seeds".
std::string verdictOf(const BiasEstimate& estimate, double tolerance);

}  // namespace grainlab::tradeoff

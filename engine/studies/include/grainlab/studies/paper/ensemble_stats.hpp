#pragma once
// The statistics of a seed ensemble: the mean of one quantity over the seeds with its 95 %
// interval — Student's t for plain values, kept inside the quantity's range where it has one,
// and a circular interval for axial directions. Figures and findings both take their
// intervals from here.
#include <limits>
#include <string>
#include <vector>

namespace grainlab::report {

/// The two-sided 95 % quantile t_{0.975} of Student's t with `dof` degrees of freedom
/// (12.706 for 1, 2.776 for 4, → 1.960); NaN for dof < 1.
double studentT975(int dof);

/// How an interval was computed (findings.csv's `interval` column says it in words).
enum class IntervalMethod {
  None,            ///< fewer than two values: no interval
  StudentT,        ///< mean ∓ t·s/√n
  StudentTInRange, ///< the same, cut at the ends of the quantity's range
  Circular,        ///< axial directions: the circular mean and Fisher's standard error
};

/// "none", "t", "t, cut to [lo, hi]", "circular".
std::string intervalMethodText(IntervalMethod method, double rangeLow, double rangeHigh);

/// A mean over seeds and its 95 % confidence interval.
struct MeanInterval {
  int n = 0;                 ///< finite values used
  double mean = 0;           ///< NaN when n = 0
  double low = 0, high = 0;  ///< NaN when n < 2: one run has no interval
  IntervalMethod method = IntervalMethod::None;
  double sd = 0;             ///< the seeds' standard deviation (plain values); NaN otherwise
  bool hasInterval() const { return n >= 2; }
  double halfWidth() const { return 0.5 * (high - low); }
};

/// The values a quantity can take: a share lies in [0, 1], an absolute value in [0, ∞).
struct ValueRange {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool bounded() const { return low > -std::numeric_limits<double>::infinity() || high < std::numeric_limits<double>::infinity(); }
};

/// Mean and t-interval of the finite values (NaNs are runs that did not measure it).
MeanInterval meanInterval(const std::vector<double>& values);

/// The same, with the interval cut at the ends of `range`. The true mean lies in the range, so
/// the cut interval holds it whenever the t-interval does: the coverage is the t-interval's,
/// and no end is reported that the quantity cannot take.
MeanInterval meanIntervalInRange(const std::vector<double>& values, ValueRange range);

/// The seeds an interval would need to exclude `threshold`, if the mean and the seeds' standard
/// deviation stayed as measured: the least n with t_{0.975}(n − 1) · sd / √n < |mean − threshold|.
/// −1 when the mean lies on the threshold, or more than 100,000 seeds would be needed.
int seedsToExclude(double mean, double sd, double threshold);

/// Axial directions (degrees, period 180°), by circular statistics on the doubled angles:
/// the mean direction is that of the mean resultant of 2θ, in [0, 180); the interval is
/// mean ∓ ½ arcsin(t · σ̂), with Fisher's circular standard error of the doubled angles taken
/// with n − 1, σ̂ = √((1 − ρ̂₂) / (2 (n − 1) R̄²)) (R̄ their mean resultant length, ρ̂₂ their
/// second central trigonometric moment), and Student's t_{0.975}(n − 1) in place of the normal
/// quantile: for concentrated directions it is the t-interval of the offsets. Where t · σ̂ ≥ 1 the data do not locate the direction: the
/// interval is the whole period, mean ∓ 90°. low and high are not wrapped (low ≤ mean ≤ high).
MeanInterval axialMeanInterval(const std::vector<double>& thetasDeg);

/// axialMeanInterval shifted by whole turns of 180° so that its mean lies within 90° of `near`
/// (θσ near 90° in a biaxial test, ω near 0).
MeanInterval axialMeanIntervalNear(const std::vector<double>& thetasDeg, double near);

}  // namespace grainlab::report

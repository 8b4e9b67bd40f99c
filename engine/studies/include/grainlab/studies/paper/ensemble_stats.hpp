#pragma once
// The statistics of a seed ensemble: the mean of one quantity over the seeds with its 95 %
// Student-t interval, for plain values and for axial directions. Figures and findings both
// take their intervals from here.
#include <vector>

namespace grainlab::report {

/// The two-sided 95 % quantile t_{0.975} of Student's t with `dof` degrees of freedom
/// (12.706 for 1, 2.776 for 4, → 1.960); NaN for dof < 1.
double studentT975(int dof);

/// A mean over seeds and its 95 % confidence interval.
struct MeanInterval {
  int n = 0;                 ///< finite values used
  double mean = 0;           ///< NaN when n = 0
  double low = 0, high = 0;  ///< mean ∓ t·s/√n; NaN when n < 2: one run has no interval
  bool hasInterval() const { return n >= 2; }
  double halfWidth() const { return 0.5 * (high - low); }
};

/// Mean and t-interval of the finite values (NaNs are runs that did not measure it).
MeanInterval meanInterval(const std::vector<double>& values);

/// The same for axial directions (degrees): the mean is the circular mean on 2θ, in [0, 180);
/// the interval is the t-interval of each direction's axial difference from that mean, so
/// low may fall below 0 or high above 180 (it is not wrapped, to keep low ≤ mean ≤ high).
MeanInterval axialMeanInterval(const std::vector<double>& thetasDeg);

}  // namespace grainlab::report

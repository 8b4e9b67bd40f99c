#pragma once
// The pure measuring parts of `grainlab tradeoff`: values read off a shearing series, their
// errors against a reference run, and the Pareto front of error against cost.
#include <cstddef>
#include <string>
#include <vector>

#include "grainlab/studies/paper/shearing_series.hpp"

namespace grainlab::tradeoff {

/// The axial strains (compression positive, dimensionless) at which ω_macro is compared.
inline const std::vector<double> kOmegaStrains{0.02, 0.05, 0.10, 0.20};
/// The axial strain at which φ_mob is compared (the end of the presets' shearing).
inline constexpr double kPhiStrain = 0.20;

/// What a run is judged on; NaN where it could not be measured.
struct RunMetrics {
  double peakPhiMobDeg = 0;                 ///< from the run's summary
  double phiMobAtEndDeg = 0;                ///< φ_mob at kPhiStrain
  std::vector<double> omegaDeg;             ///< ω_macro at each of kOmegaStrains
  double thetaSigmaGapDeg = 0;              ///< median |θσ(Eq. 7) − θσ(stress)| over shearing
  double voidRatio = 0;                     ///< after consolidation
  double inertialNumber = 0;                ///< median measured I over shearing
  double kineticEnergy = 0;                 ///< median over shearing, J/m: numerical heating shows here
};

/// y at x = `at` by linear interpolation between the first pair of neighbouring samples
/// that brackets it (x need not be strictly monotonic). With `period` > 0, y is periodic
/// (an axial angle, period 180): the shorter way round is taken and the result wrapped into
/// the range of the first bracketing sample's period, [y0 − period/2, y0 + period/2).
/// NaN if no pair brackets `at` or a bracketing value is not finite.
double interpolateAt(const std::vector<double>& x, const std::vector<double>& y, double at, double period = 0);

/// ω wrapped into [−90°, 90°).
double wrapOmegaDeg(double deg);

/// The metrics of one run from its shearing stage (as ShearingRecorder keeps it) and its
/// summary's values.
RunMetrics measureRun(const report::ShearingSeries& shearing, double peakPhiMobDeg, double voidRatio);

/// |run − reference| per metric, in the order of errorNames(); ω by the axial distance.
std::vector<double> metricErrors(const RunMetrics& run, const RunMetrics& reference);
/// Names of metricErrors()'s entries (CSV column suffixes).
const std::vector<std::string>& errorNames();
/// Of metricErrors(): the largest of the angle errors (all but the void ratio), degrees;
/// NaN if any is NaN.
double maxAngleErrorDeg(const std::vector<double>& errors);
/// Of metricErrors(): the mean of the angle errors, degrees (less at the mercy of the one
/// noisiest measure than the largest); NaN if any is NaN.
double meanAngleErrorDeg(const std::vector<double>& errors);

/// Indices of the points not dominated by another (one with cost ≤ and error ≤ and one of
/// them <), in increasing cost. Points with a non-finite coordinate are left out.
std::vector<size_t> paretoFront(const std::vector<double>& cost, const std::vector<double>& error);

}  // namespace grainlab::tradeoff

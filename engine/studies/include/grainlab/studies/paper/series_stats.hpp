#pragma once
// Statistics the findings are computed with: NaN-skipping means and medians, axial
// (mod 180°) differences and means, and the fabric's noise floor.
#include <vector>

namespace grainlab::report {

/// Mean of the finite values; NaN if there are none.
double finiteMean(const std::vector<double>& values);
/// Median of the finite values; NaN if there are none.
double finiteMedian(std::vector<double> values);
/// Largest finite value; NaN if there are none.
double finiteMax(const std::vector<double>& values);
/// A least-squares line's slope dy/dx and its standard error (units of y per unit of x).
struct LinearTrend {
  double slope = 0;
  double standardError = 0;
  /// The slope exceeds zero by more than `sigmas` standard errors.
  bool risesBeyond(double sigmas) const { return slope - sigmas * standardError > 0; }
};
/// The least-squares line through the pairs where both are finite; NaNs with fewer than three
/// such pairs or no spread in x.
LinearTrend linearTrend(const std::vector<double>& x, const std::vector<double>& y);
/// |a − b| for axial directions (degrees), in [0, 90].
double axialDistanceDeg(double aDeg, double bDeg);
/// Circular mean of axial directions (degrees) through e^{2iθ}, in [0, 180); NaN if none is finite.
double axialMeanDeg(const std::vector<double>& thetasDeg);
/// 1.25·√(2/N_c): the a_c an isotropic sample of N_c contacts shows by chance
/// (docs/micromechanics.md). NaN for N_c ≤ 0.
double noiseFloor(double contacts);
/// A direction θ_k means something only where a_k ≥ this factor × noiseFloor.
inline constexpr double kDirectionNoiseFactor = 2.0;

}  // namespace grainlab::report

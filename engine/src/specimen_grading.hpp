#pragma once
// The elongated assemblies' size grading (paper, Section 4): long axes L mixed by count so
// that D60/D10 = 1.35 and D30²/(D10·D60) = 1.2, D_x being the long axis below which x % of
// the particles by count lie.
//
// With three discrete sizes the grading "curve" is a matter of interpretation. Ours: the
// cumulative fraction finer by count is F_i = f_1 + ... + f_i at L_i, linear in L between
// the sizes, and linear from the origin (0 mm, 0 %) up to the smallest size. The origin is
// not a whim: no curve that is linear between the sizes and puts less than 10 % below the
// smallest one can meet both targets. Cu = 1.35 and Cc = 1.2 force D30/D10 = √(Cu·Cc) =
// 1.273 but D60/D30 = 1.061, a steep 30→60 % rise. If D10 ≥ 4.5 mm then D30 ≥ 5.73 mm and
// D60 ≥ 6.08 mm, both on the 5→7 mm segment, whose slope is at most 100 %/2 mm, so
// D60 − D30 ≥ 0.6 mm; but D60 − D30 = 0.057·D60 ≤ 0.4 mm. So 10 % of the curve must lie
// below the smallest size, and the origin is the one anchor that invents no size. (Linear
// interpolation between class boundaries, the statistician's ogive, fails the same way.)
// For 4.5, 5.0 and
// 7.0 mm this gives the unique fractions 0.1227, 0.5298, 0.3475 (D10 = 3.667 mm,
// D30 = 4.667 mm, D60 = 4.950 mm).
#include <optional>
#include <span>
#include <vector>

namespace grainlab::specimen {

/// The paper's uniformity coefficient D60/D10 of the elongated assemblies.
inline constexpr double kPaperUniformity = 1.35;
/// The paper's curvature coefficient D30²/(D10·D60) of the elongated assemblies.
inline constexpr double kPaperCurvature = 1.2;

/// D_x of the grading curve above: the long axis (m) below which the fraction `finer`
/// (0 < finer ≤ 1) of the particles by count lies. `longAxes` strictly increasing (m);
/// `fractions` by count, one per size, summing to 1.
double gradingSize(std::span<const double> longAxes, std::span<const double> fractions, double finer);

struct GradingCoefficients {
  double uniformity = 0;  ///< D60/D10
  double curvature = 0;   ///< D30²/(D10·D60)
};

/// Cu and Cc of the grading curve above.
GradingCoefficients gradingCoefficients(std::span<const double> longAxes, std::span<const double> fractions);

/// Count fractions for three strictly increasing sizes that give the requested Cu and Cc on
/// the grading curve above, to about 1e-12; nullopt when no mix of the three does.
std::optional<std::vector<double>> solveCountFractions(std::span<const double> longAxes,
                                                       double uniformity = kPaperUniformity,
                                                       double curvature = kPaperCurvature);

}  // namespace grainlab::specimen

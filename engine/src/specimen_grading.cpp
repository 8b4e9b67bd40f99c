#include "specimen_grading.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace grainlab::specimen {

double gradingSize(std::span<const double> longAxes, std::span<const double> fractions, double finer) {
  if (longAxes.empty() || longAxes.size() != fractions.size()) {
    throw std::invalid_argument("gradingSize: one fraction per long axis");
  }
  // Knots (0, 0), (L_i, F_i); a zero fraction makes a flat segment, which is skipped.
  double lowSize = 0, lowFiner = 0, cumulative = 0;
  for (std::size_t i = 0; i < longAxes.size(); ++i) {
    cumulative += fractions[i];
    const double highFiner = i + 1 == longAxes.size() ? 1.0 : cumulative;
    if (highFiner >= finer && highFiner > lowFiner) {
      return lowSize + (longAxes[i] - lowSize) * (finer - lowFiner) / (highFiner - lowFiner);
    }
    lowSize = longAxes[i];
    lowFiner = highFiner;
  }
  return longAxes.back();
}

GradingCoefficients gradingCoefficients(std::span<const double> longAxes, std::span<const double> fractions) {
  const double d10 = gradingSize(longAxes, fractions, 0.1);
  const double d30 = gradingSize(longAxes, fractions, 0.3);
  const double d60 = gradingSize(longAxes, fractions, 0.6);
  return {d60 / d10, d30 * d30 / (d10 * d60)};
}

std::optional<std::vector<double>> solveCountFractions(std::span<const double> longAxes, double uniformity,
                                                       double curvature) {
  if (longAxes.size() != 3) return std::nullopt;
  // Unknowns: the cumulative fractions a = F(L1) and b = F(L2), 0 < a < b < 1.
  const auto residual = [&](double a, double b) {
    const std::array<double, 3> f{a, b - a, 1 - b};
    const GradingCoefficients c = gradingCoefficients(longAxes, f);
    return std::array<double, 2>{c.uniformity - uniformity, c.curvature - curvature};
  };
  const auto inside = [](double a, double b) { return a > 0 && b > a && b < 1; };
  // The residual is smooth only piecewise (D_x changes segment), so Newton starts from a
  // grid over the triangle, in a fixed order, and the first start that converges wins.
  constexpr int kGrid = 40;
  constexpr int kIterations = 60;
  constexpr double kStep = 1e-7;
  constexpr double kTolerance = 1e-13;
  for (int i = 1; i < kGrid; ++i) {
    for (int j = i + 1; j < kGrid; ++j) {
      double a = static_cast<double>(i) / kGrid, b = static_cast<double>(j) / kGrid;
      for (int it = 0; it < kIterations && inside(a, b); ++it) {
        const std::array<double, 2> r = residual(a, b);
        if (std::max(std::abs(r[0]), std::abs(r[1])) < kTolerance) {
          return std::vector<double>{a, b - a, 1 - b};
        }
        if (!inside(a + kStep, b + kStep)) break;
        const std::array<double, 2> ra = residual(a + kStep, b), rb = residual(a, b + kStep);
        const double j00 = (ra[0] - r[0]) / kStep, j01 = (rb[0] - r[0]) / kStep;
        const double j10 = (ra[1] - r[1]) / kStep, j11 = (rb[1] - r[1]) / kStep;
        const double det = j00 * j11 - j01 * j10;
        if (!(std::abs(det) > 1e-12)) break;
        a -= (j11 * r[0] - j01 * r[1]) / det;
        b -= (j00 * r[1] - j10 * r[0]) / det;
      }
    }
  }
  return std::nullopt;
}

}  // namespace grainlab::specimen

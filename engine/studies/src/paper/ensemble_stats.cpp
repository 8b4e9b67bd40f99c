#include "grainlab/studies/paper/ensemble_stats.hpp"

#include <array>
#include <cmath>

#include "grainlab/analysis/angles.hpp"
#include "grainlab/studies/paper/series_stats.hpp"

namespace grainlab::report {

double studentT975(int dof) {
  if (dof < 1) return std::nan("");
  // Tabulated quantiles for 1..30 degrees of freedom (any statistics table).
  static constexpr std::array<double, 30> table{12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                                2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                                2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof <= 30) return table[static_cast<size_t>(dof - 1)];
  // Beyond the table, the Cornish-Fisher expansion in 1/dof: within 1e-3 of the exact value.
  const double z = 1.959964, v = dof;
  return z + (z * z * z + z) / (4 * v) + (5 * std::pow(z, 5) + 16 * z * z * z + 3 * z) / (96 * v * v);
}

MeanInterval meanInterval(const std::vector<double>& values) {
  MeanInterval m;
  // Summed as offsets from the first value: identical values give exactly that value and a
  // zero-width interval (a plain sum / n can be off by an ulp).
  double first = std::nan(""), offsets = 0;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    if (m.n == 0) first = v;
    offsets += v - first;
    ++m.n;
  }
  const double nan = std::nan("");
  m.low = m.high = nan;
  if (m.n == 0) {
    m.mean = nan;
    return m;
  }
  m.mean = first + offsets / m.n;
  if (m.n < 2) return m;
  double squares = 0;
  for (double v : values) {
    if (std::isfinite(v)) squares += (v - m.mean) * (v - m.mean);
  }
  const double half = studentT975(m.n - 1) * std::sqrt(squares / (m.n - 1) / m.n);
  m.low = m.mean - half;
  m.high = m.mean + half;
  return m;
}

MeanInterval axialMeanInterval(const std::vector<double>& thetasDeg) {
  const double centre = axialMeanDeg(thetasDeg);
  std::vector<double> offsets;
  for (double t : thetasDeg) {
    if (std::isfinite(t)) offsets.push_back(analysis::wrapAxialDeg(t - centre));
  }
  MeanInterval m = meanInterval(offsets);
  if (m.n == 0) return m;
  // The circular mean and the mean offset differ slightly when the spread is wide; centre the
  // interval on the circular mean the charts draw.
  const double half = m.hasInterval() ? m.halfWidth() : std::nan("");
  m.mean = centre;
  m.low = centre - half;
  m.high = centre + half;
  return m;
}

}  // namespace grainlab::report

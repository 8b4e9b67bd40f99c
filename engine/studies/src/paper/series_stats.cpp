#include "grainlab/studies/paper/series_stats.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "grainlab/analysis/angles.hpp"

namespace grainlab::report {

double finiteMean(const std::vector<double>& values) {
  double sum = 0;
  int n = 0;
  for (double v : values) {
    if (std::isfinite(v)) sum += v, ++n;
  }
  return n ? sum / n : std::nan("");
}

double finiteMedian(std::vector<double> values) {
  std::erase_if(values, [](double v) { return !std::isfinite(v); });
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double finiteMax(const std::vector<double>& values) {
  double best = std::nan("");
  for (double v : values) {
    if (std::isfinite(v) && !(v <= best)) best = v;
  }
  return best;
}

LinearTrend linearTrend(const std::vector<double>& x, const std::vector<double>& y) {
  const LinearTrend none{std::nan(""), std::nan("")};
  double sx = 0, sy = 0;
  int n = 0;
  const size_t size = std::min(x.size(), y.size());
  for (size_t k = 0; k < size; ++k) {
    if (std::isfinite(x[k]) && std::isfinite(y[k])) sx += x[k], sy += y[k], ++n;
  }
  if (n < 3) return none;
  const double mx = sx / n, my = sy / n;
  double sxx = 0, sxy = 0;
  for (size_t k = 0; k < size; ++k) {
    if (!std::isfinite(x[k]) || !std::isfinite(y[k])) continue;
    sxx += (x[k] - mx) * (x[k] - mx);
    sxy += (x[k] - mx) * (y[k] - my);
  }
  if (!(sxx > 0)) return none;
  const double slope = sxy / sxx, intercept = my - slope * mx;
  double residuals = 0;
  for (size_t k = 0; k < size; ++k) {
    if (!std::isfinite(x[k]) || !std::isfinite(y[k])) continue;
    const double r = y[k] - (intercept + slope * x[k]);
    residuals += r * r;
  }
  return {slope, std::sqrt(residuals / (n - 2) / sxx)};
}

double axialDistanceDeg(double aDeg, double bDeg) { return std::abs(analysis::wrapAxialDeg(aDeg - bDeg)); }

double axialMeanDeg(const std::vector<double>& thetasDeg) {
  std::complex<double> sum = 0;
  int n = 0;
  for (double t : thetasDeg) {
    if (!std::isfinite(t)) continue;
    sum += analysis::axialComplex(1.0, t);
    ++n;
  }
  return n ? analysis::axialDirectionDeg(sum) : std::nan("");
}

double noiseFloor(double contacts) { return contacts > 0 ? 1.25 * std::sqrt(2.0 / contacts) : std::nan(""); }

}  // namespace grainlab::report

#include "grainlab/studies/paper/ensemble_stats.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

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
  m.low = m.high = m.sd = nan;
  if (m.n == 0) {
    m.mean = nan;
    return m;
  }
  m.mean = first + offsets / m.n;
  m.sd = nan;
  if (m.n < 2) return m;
  double squares = 0;
  for (double v : values) {
    if (std::isfinite(v)) squares += (v - m.mean) * (v - m.mean);
  }
  m.sd = std::sqrt(squares / (m.n - 1));
  const double half = studentT975(m.n - 1) * m.sd / std::sqrt(m.n);
  m.low = m.mean - half;
  m.high = m.mean + half;
  m.method = IntervalMethod::StudentT;
  return m;
}

int seedsToExclude(double mean, double sd, double threshold) {
  const double gap = std::abs(mean - threshold);
  if (!(gap > 0) || !std::isfinite(sd)) return -1;
  for (int n = 2; n <= 100000; ++n) {
    if (studentT975(n - 1) * sd / std::sqrt(static_cast<double>(n)) < gap) return n;
  }
  return -1;
}

MeanInterval meanIntervalInRange(const std::vector<double>& values, ValueRange range) {
  MeanInterval m = meanInterval(values);
  if (!m.hasInterval() || (m.low >= range.low && m.high <= range.high)) return m;
  m.low = std::max(m.low, range.low);
  m.high = std::min(m.high, range.high);
  m.method = IntervalMethod::StudentTInRange;
  return m;
}

std::string intervalMethodText(IntervalMethod method, double rangeLow, double rangeHigh) {
  switch (method) {
    case IntervalMethod::None: return "none";
    case IntervalMethod::StudentT: return "t";
    case IntervalMethod::Circular: return "circular";
    case IntervalMethod::StudentTInRange: {
      const auto end = [](double v) {
        if (std::isinf(v)) return std::string(v > 0 ? "∞" : "−∞");
        std::string s = std::to_string(v);
        s.erase(s.find_last_not_of('0') + 1);
        if (s.back() == '.') s.pop_back();
        return s;
      };
      return "t, cut to [" + end(rangeLow) + ", " + end(rangeHigh) + "]";
    }
  }
  return "none";
}

MeanInterval axialMeanInterval(const std::vector<double>& thetasDeg) {
  MeanInterval m;
  const double nan = std::nan("");
  m.mean = m.low = m.high = m.sd = nan;
  std::vector<double> doubled;  // 2θ in radians
  for (double t : thetasDeg) {
    if (std::isfinite(t)) doubled.push_back(2.0 * t * std::numbers::pi / 180.0);
  }
  m.n = static_cast<int>(doubled.size());
  if (m.n == 0) return m;
  m.mean = axialMeanDeg(thetasDeg);
  if (m.n < 2) return m;
  std::complex<double> resultant = 0;
  for (double a : doubled) resultant += std::polar(1.0, a);
  const double n = m.n, meanLength = std::abs(resultant) / n;
  const double meanDoubled = 2.0 * m.mean * std::numbers::pi / 180.0;
  double secondMoment = 0;  // ρ̂₂ = (1/n) Σ cos 2(2θ − mean of 2θ)
  for (double a : doubled) secondMoment += std::cos(2.0 * (a - meanDoubled));
  secondMoment /= n;
  // Fisher's σ̂² = (1 − ρ̂₂)/(2n R̄²) uses moments over n; scaled by n/(n − 1) it becomes, for
  // concentrated directions, s²/n of the offsets with the same n − 1 as Student's t.
  const double standardError = std::sqrt(std::max(0.0, 1.0 - secondMoment) / (2.0 * (n - 1) * meanLength * meanLength));
  const double reach = studentT975(m.n - 1) * standardError;
  // Half of the doubled angle's half-width; the whole period where the data cannot place it.
  const double half = meanLength > 0 && reach < 1 ? 0.5 * std::asin(reach) * 180.0 / std::numbers::pi : 90.0;
  m.low = m.mean - half;
  m.high = m.mean + half;
  m.method = IntervalMethod::Circular;
  return m;
}

MeanInterval axialMeanIntervalNear(const std::vector<double>& thetasDeg, double near) {
  MeanInterval m = axialMeanInterval(thetasDeg);
  const double shift = 180.0 * std::round((near - m.mean) / 180.0);
  if (std::isfinite(shift)) {
    m.mean += shift;
    m.low += shift;
    m.high += shift;
  }
  return m;
}

}  // namespace grainlab::report

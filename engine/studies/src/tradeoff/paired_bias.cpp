#include "grainlab/studies/tradeoff/paired_bias.hpp"

#include <cmath>
#include <cstdio>

#include "grainlab/studies/paper/ensemble_stats.hpp"
#include "grainlab/studies/paper/series_stats.hpp"

namespace grainlab::tradeoff {
namespace {

struct Moments {
  int n = 0;
  double mean = BiasEstimate::kNaN, variance = BiasEstimate::kNaN;  // sample variance (n − 1)
};

Moments moments(const std::vector<double>& values) {
  Moments m;
  double sum = 0;
  for (double v : values)
    if (std::isfinite(v)) {
      sum += v;
      ++m.n;
    }
  if (m.n == 0) return m;
  m.mean = sum / m.n;
  if (m.n < 2) return m;
  double squares = 0;
  for (double v : values)
    if (std::isfinite(v)) squares += (v - m.mean) * (v - m.mean);
  m.variance = squares / (m.n - 1);
  return m;
}

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

double runsFor(double t, double sd, double tolerance) {
  if (!std::isfinite(t) || !std::isfinite(sd)) return BiasEstimate::kNaN;
  return std::max(2.0, std::ceil((t * sd / tolerance) * (t * sd / tolerance)));
}

}  // namespace

double difference(double a, double b, bool axial) {
  const double d = a - b;
  if (!axial || !std::isfinite(d)) return d;
  return d - 180.0 * std::ceil((d - 90.0) / 180.0);  // into (−90, 90]
}

std::string verdictOf(const BiasEstimate& e, double tolerance) {
  const std::string seeds = std::to_string(e.seeds) + " seeds";
  if (!std::isfinite(e.low) || !std::isfinite(e.high)) return "undecided at " + seeds;
  const bool inside = -tolerance <= e.low && e.high <= tolerance;
  const bool excludesZero = e.low > 0 || e.high < 0;
  if (excludesZero) {
    return "biased by " + number(e.bias) + " (" + number(e.low) + " to " + number(e.high) + ")" +
           (inside ? ", within tolerance" : "");
  }
  return inside ? "no bias found at " + seeds : "undecided at " + seeds;
}

BiasEstimate pairedBias(const std::vector<double>& differences, double tolerance) {
  BiasEstimate e;
  const Moments m = moments(differences);
  e.seeds = m.n;
  e.bias = m.mean;
  if (m.n >= 2) {
    e.sd = std::sqrt(m.variance);
    e.t = report::studentT975(m.n - 1);
    const double half = e.t * e.sd / std::sqrt(static_cast<double>(m.n));
    e.low = e.bias - half;
    e.high = e.bias + half;
    e.runsForTolerance = runsFor(e.t, e.sd, tolerance);
  }
  e.verdict = verdictOf(e, tolerance);
  return e;
}

BiasEstimate unpairedBias(const std::vector<double>& setting, const std::vector<double>& reference, double tolerance,
                          bool axial) {
  std::vector<double> a = setting, b = reference;
  if (axial) {
    const double centre = report::axialMeanDeg(reference);
    for (double& v : a) v = centre + difference(v, centre, true);
    for (double& v : b) v = centre + difference(v, centre, true);
  }
  const Moments ma = moments(a), mb = moments(b);
  BiasEstimate e;
  e.seeds = std::min(ma.n, mb.n);
  e.bias = ma.mean - mb.mean;
  if (ma.n >= 2 && mb.n >= 2) {
    e.sd = std::sqrt(ma.variance);
    const double va = ma.variance / ma.n, vb = mb.variance / mb.n, se = std::sqrt(va + vb);
    // Welch–Satterthwaite degrees of freedom, rounded down (a slightly wider interval).
    const double dof = se > 0 ? (va + vb) * (va + vb) / (va * va / (ma.n - 1) + vb * vb / (mb.n - 1)) : ma.n + mb.n - 2;
    e.t = report::studentT975(std::max(1, static_cast<int>(std::floor(dof))));
    e.low = e.bias - e.t * se;
    e.high = e.bias + e.t * se;
    e.runsForTolerance = runsFor(e.t, std::sqrt(ma.variance + mb.variance), tolerance);
  }
  e.verdict = verdictOf(e, tolerance);
  return e;
}

}  // namespace grainlab::tradeoff

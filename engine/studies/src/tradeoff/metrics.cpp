#include "grainlab/studies/tradeoff/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "grainlab/studies/paper/series_stats.hpp"

namespace grainlab::tradeoff {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// v wrapped into [centre − period/2, centre + period/2).
double wrapAround(double v, double centre, double period) {
  return v - period * std::floor((v - centre) / period + 0.5);
}

}  // namespace

double interpolateAt(const std::vector<double>& x, const std::vector<double>& y, double at, double period) {
  const size_t n = std::min(x.size(), y.size());
  for (size_t k = 0; k + 1 < n; ++k) {
    const double x0 = x[k], x1 = x[k + 1];
    if (!(std::min(x0, x1) <= at && at <= std::max(x0, x1))) continue;
    const double y0 = y[k];
    double y1 = y[k + 1];
    if (!std::isfinite(y0) || !std::isfinite(y1)) return kNaN;
    if (period > 0) y1 = wrapAround(y1, y0, period);  // the shorter way round
    const double t = x1 == x0 ? 0.0 : (at - x0) / (x1 - x0);
    const double v = y0 + t * (y1 - y0);
    return period > 0 ? wrapAround(v, y0, period) : v;
  }
  return kNaN;
}

double wrapOmegaDeg(double deg) { return wrapAround(deg, 0.0, 180.0); }

RunMetrics measureRun(const report::ShearingSeries& shearing, double peakPhiMobDeg, double voidRatio) {
  RunMetrics m;
  m.peakPhiMobDeg = peakPhiMobDeg;
  m.voidRatio = voidRatio;
  const std::vector<double> strain = shearing.column("axial_strain");
  m.phiMobAtEndDeg = interpolateAt(strain, shearing.column("phi_mob_deg"), kPhiStrain);
  const std::vector<double> omega = shearing.column("omega_macro_deg");
  for (double e : kOmegaStrains) {
    const double w = interpolateAt(strain, omega, e, 180.0);
    m.omegaDeg.push_back(std::isfinite(w) ? wrapOmegaDeg(w) : w);
  }
  // The gap once shearing has begun: at zero strain (the state the stage starts from) the
  // stress is isotropic and θσ has no meaning; inertia and heating are the shearing's too.
  std::vector<double> gaps, inertial, kinetic;
  for (size_t k = 0; k < strain.size(); ++k) {
    if (!(strain[k] > 0)) continue;
    const double a = shearing.at("theta_sigma_micro_deg", k);
    const double b = shearing.at("theta_sigma_macro_deg", k);
    if (std::isfinite(a) && std::isfinite(b)) gaps.push_back(report::axialDistanceDeg(a, b));
    inertial.push_back(shearing.at("inertial_number", k));
    kinetic.push_back(shearing.at("kinetic_energy", k));
  }
  m.thetaSigmaGapDeg = report::finiteMedian(gaps);
  m.inertialNumber = report::finiteMedian(inertial);
  m.kineticEnergy = report::finiteMedian(kinetic);
  return m;
}

const std::vector<std::string>& errorNames() {
  static const std::vector<std::string> names{"peak_phi_mob_deg", "phi_mob_20_deg", "omega_2_deg",   "omega_5_deg",
                                              "omega_10_deg",     "omega_20_deg",   "theta_sigma_gap_deg", "void_ratio"};
  return names;
}

std::vector<double> metricErrors(const RunMetrics& run, const RunMetrics& reference) {
  std::vector<double> e{std::abs(run.peakPhiMobDeg - reference.peakPhiMobDeg),
                        std::abs(run.phiMobAtEndDeg - reference.phiMobAtEndDeg)};
  for (size_t k = 0; k < kOmegaStrains.size(); ++k) {
    const double a = k < run.omegaDeg.size() ? run.omegaDeg[k] : kNaN;
    const double b = k < reference.omegaDeg.size() ? reference.omegaDeg[k] : kNaN;
    e.push_back(std::isfinite(a) && std::isfinite(b) ? report::axialDistanceDeg(a, b) : kNaN);
  }
  e.push_back(std::abs(run.thetaSigmaGapDeg - reference.thetaSigmaGapDeg));
  e.push_back(std::abs(run.voidRatio - reference.voidRatio));
  return e;
}

double maxAngleErrorDeg(const std::vector<double>& errors) {
  double worst = 0;
  for (size_t k = 0; k + 1 < errors.size(); ++k) {  // the last is the void ratio
    if (!std::isfinite(errors[k])) return kNaN;
    worst = std::max(worst, errors[k]);
  }
  return worst;
}

double meanAngleErrorDeg(const std::vector<double>& errors) {
  if (errors.size() < 2) return kNaN;
  double sum = 0;
  for (size_t k = 0; k + 1 < errors.size(); ++k) {  // the last is the void ratio
    if (!std::isfinite(errors[k])) return kNaN;
    sum += errors[k];
  }
  return sum / static_cast<double>(errors.size() - 1);
}

std::vector<size_t> paretoFront(const std::vector<double>& cost, const std::vector<double>& error) {
  std::vector<size_t> order;
  for (size_t k = 0; k < std::min(cost.size(), error.size()); ++k) {
    if (std::isfinite(cost[k]) && std::isfinite(error[k])) order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return cost[a] != cost[b] ? cost[a] < cost[b] : error[a] < error[b];
  });
  std::vector<size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (size_t k : order) {
    if (error[k] < best) {  // cheaper ones all had a larger error
      front.push_back(k);
      best = error[k];
    }
  }
  return front;
}

}  // namespace grainlab::tradeoff

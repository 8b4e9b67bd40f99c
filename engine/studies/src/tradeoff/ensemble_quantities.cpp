#include "grainlab/studies/tradeoff/ensemble_quantities.hpp"

#include <cmath>

#include "grainlab/studies/paper/series_stats.hpp"
#include "grainlab/studies/tradeoff/metrics.hpp"

namespace grainlab::tradeoff {

// Tolerances (docs/speed-accuracy.md, "Tolerances"): 1° for angles, the unit the paper gives its
// directions in (its findings' margins are 5° and more); 0.003 for the void ratio, three units
// of the last digit the paper gives (0.263-0.282 across its assemblies); 0.01 for a_c, a tenth
// of the a_c a quick specimen's ~270 contacts show by chance (1.25·√(2/N_c) ≈ 0.11).
const std::vector<Quantity>& ensembleQuantities() {
  static const std::vector<Quantity> q{
      {"peak_phi_mob_deg", 1.0, false},    {"phi_mob_20_deg", 1.0, false},     {"void_ratio_5", 0.003, false},
      {"void_ratio_20", 0.003, false},     {"a_c_5", 0.01, false},             {"theta_sigma_1_deg", 1.0, true},
      {"theta_sigma_2_deg", 1.0, true},    {"theta_sigma_5_deg", 1.0, true},   {"theta_sigma_10_deg", 1.0, true},
      {"omega_1_deg", 1.0, true},          {"omega_2_deg", 1.0, true},         {"omega_5_deg", 1.0, true},
      {"omega_10_deg", 1.0, true},         {"theta_sigma_gap_deg", 1.0, false},
  };
  return q;
}

std::vector<double> measureQuantities(const report::ShearingSeries& shearing, double peakPhiMobDeg) {
  const std::vector<double> strain = shearing.column("axial_strain");
  auto at = [&](const char* column, double e, double period = 0) {
    return interpolateAt(strain, shearing.column(column), e, period);
  };
  std::vector<double> v{peakPhiMobDeg, at("phi_mob_deg", 0.20), at("void_ratio", 0.05), at("void_ratio", 0.20),
                        at("a_c", 0.05)};
  for (double e : {0.01, 0.02, 0.05, 0.10}) v.push_back(wrapOmegaDeg(at("theta_sigma_macro_deg", e, 180)));
  for (double e : {0.01, 0.02, 0.05, 0.10}) v.push_back(wrapOmegaDeg(at("omega_macro_deg", e, 180)));
  v.push_back(measureRun(shearing, peakPhiMobDeg, 0).thetaSigmaGapDeg);
  return v;
}

double lateralStressDeviation(const report::ShearingSeries& shearing, double targetPa) {
  std::vector<double> off;
  for (size_t k = 0; k < shearing.size(); ++k) {
    if (!(shearing.at("axial_strain", k) > 0)) continue;
    off.push_back(std::abs(shearing.at("sigma11", k) / targetPa - 1));
  }
  return report::finiteMedian(off);
}

}  // namespace grainlab::tradeoff

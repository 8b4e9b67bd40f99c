#pragma once
// What `grainlab tradeoff --seeds N` judges a setting on: the quantities the paper's findings
// rest on, each with the tolerance a setting may move it by (docs/speed-accuracy.md says why),
// read off one run's shearing series.
#include <string>
#include <vector>

#include "grainlab/studies/paper/shearing_series.hpp"

namespace grainlab::tradeoff {

struct Quantity {
  std::string name;        ///< as in tradeoff.csv's `quantity` column
  double tolerance = 0;    ///< in the quantity's unit (degrees, or none for ratios)
  bool axial = false;      ///< a direction in degrees: differences taken the shorter way round
};

/// peak_phi_mob_deg, phi_mob_20_deg, void_ratio_5, void_ratio_20, a_c_5, theta_sigma_{1,2,5,10}_deg,
/// omega_{1,2,5,10}_deg, theta_sigma_gap_deg.
const std::vector<Quantity>& ensembleQuantities();

/// One run's value of each ensembleQuantities() entry (NaN where it was not measured):
/// interpolated at the axial strain (ε22 of the shearing stage) its name gives.
std::vector<double> measureQuantities(const report::ShearingSeries& shearing, double peakPhiMobDeg);

/// The median over the shearing samples past ε22 = 0 of |σ11/target − 1|: how far the lateral
/// boundary was from the stress it was asked to hold (NaN without samples).
double lateralStressDeviation(const report::ShearingSeries& shearing, double targetPa);

}  // namespace grainlab::tradeoff

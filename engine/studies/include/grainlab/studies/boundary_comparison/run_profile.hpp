#pragma once
// What `grainlab boundaries` keeps of one run's shearing stage: where φ_mob peaks (its value,
// the axial strain and a_c there) and the curves of φ_mob, a_c and ω against axial strain on a
// common grid, so that runs of different specimens average strain by strain.
#include <string>
#include <vector>

#include "grainlab/studies/paper/shearing_series.hpp"

namespace grainlab::boundaries {

/// The sample of largest φ_mob (the first of equals); NaN fields without a finite φ_mob.
struct PeakPoint {
  double phiMobDeg;
  double axialStrain;
  double aC;
};
PeakPoint peakOf(const report::ShearingSeries& shearing);

/// A curve's column in series.csv and whether it is an axial direction (degrees, period 180°).
struct CurveColumn {
  std::string name;  ///< "phi_mob_deg", "a_c", "omega_macro_deg"
  bool axial = false;
};
const std::vector<CurveColumn>& curveColumns();

/// The grid: 0, step, 2 step, … up to `end` (inclusive, within step·1e-9).
std::vector<double> strainGrid(double step, double end);

/// The column at each grid strain, linear between the samples around it (axial: the shorter
/// way round, ω wrapped into [−90°, 90°)); NaN outside the series.
std::vector<double> curveAt(const report::ShearingSeries& shearing, const CurveColumn& column,
                            const std::vector<double>& grid);

}  // namespace grainlab::boundaries

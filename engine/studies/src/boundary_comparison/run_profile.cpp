#include "grainlab/studies/boundary_comparison/run_profile.hpp"

#include <cmath>
#include <limits>

#include "grainlab/studies/tradeoff/metrics.hpp"

namespace grainlab::boundaries {

PeakPoint peakOf(const report::ShearingSeries& shearing) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  PeakPoint p{kNaN, kNaN, kNaN};
  for (size_t k = 0; k < shearing.size(); ++k) {
    const double phi = shearing.at("phi_mob_deg", k);
    if (std::isfinite(phi) && !(phi <= p.phiMobDeg)) p = {phi, shearing.at("axial_strain", k), shearing.at("a_c", k)};
  }
  return p;
}

const std::vector<CurveColumn>& curveColumns() {
  static const std::vector<CurveColumn> c{{"phi_mob_deg", false}, {"a_c", false}, {"omega_macro_deg", true}};
  return c;
}

std::vector<double> strainGrid(double step, double end) {
  std::vector<double> grid;
  for (int k = 0; k * step <= end + step * 1e-9; ++k) grid.push_back(k * step);
  return grid;
}

std::vector<double> curveAt(const report::ShearingSeries& shearing, const CurveColumn& column,
                            const std::vector<double>& grid) {
  const std::vector<double> strain = shearing.column("axial_strain"), values = shearing.column(column.name);
  std::vector<double> out;
  for (double e : grid) {
    const double v = tradeoff::interpolateAt(strain, values, e, column.axial ? 180.0 : 0.0);
    out.push_back(column.axial && std::isfinite(v) ? tradeoff::wrapOmegaDeg(v) : v);
  }
  return out;
}

}  // namespace grainlab::boundaries

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"

namespace grainlab {

const std::vector<std::string>& seriesColumns() {
  // contracts.md's columns first, in its order; grainlab's extensions after them.
  static const std::vector<std::string> columns{
      "step", "time", "stage", "axial_strain", "lateral_strain", "volumetric_strain",
      "sigma11", "sigma22", "sigma12", "sigma21", "p", "q", "phi_mob_deg", "void_ratio",
      "coordination", "contacts", "a_c", "theta_c_deg", "a_n", "theta_n_deg", "a_t",
      "theta_t_deg", "a_w", "a_ln", "theta_ln_deg", "a_lt", "theta_lt_deg",
      "theta_sigma_macro_deg", "theta_sigma_micro_deg", "theta_sigma_eq10_deg",
      "theta_sigma_eq11_deg", "omega_macro_deg", "omega_micro_deg", "kinetic_energy",
      // extensions
      "omega_eq10_deg", "omega_eq11_deg", "f0", "l0",
      "inertial_number", "elastic_energy", "area",
      // loading paths (docs/loading-paths.md)
      "theta_strain_rate_deg", "omega_strain_rate_deg"};
  return columns;
}

std::size_t seriesColumnIndex(std::string_view name) {
  const auto& columns = seriesColumns();
  for (std::size_t k = 0; k < columns.size(); ++k) {
    if (columns[k] == name) return k;
  }
  throw std::logic_error("series has no column " + std::string(name));
}

std::string seriesHeader() {
  std::string line;
  for (const std::string& c : seriesColumns()) line += (line.empty() ? "" : ",") + c;
  return line;
}

std::vector<std::string> splitSeriesRow(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

std::string formatSeriesRow(const Sample& sample) {
  std::string line;
  char buffer[32];
  const auto& columns = seriesColumns();
  for (size_t k = 0; k < columns.size(); ++k) {
    if (k) line += ',';
    if (columns[k] == "stage") {
      line += sample.stage;
      continue;
    }
    const double v = k < sample.values.size() ? sample.values[k] : NAN;
    if (std::isnan(v)) continue;  // not measured: an empty cell, never "nan"
    // 17 significant digits: the CSV round-trips the doubles exactly.
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    line += buffer;
  }
  return line;
}

}  // namespace grainlab

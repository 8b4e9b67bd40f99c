#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"
#include "grainlab/series_column.hpp"

namespace grainlab {
namespace {

struct Definition {
  SeriesColumnId id;
  std::string_view name, unit, meaning;
};
// contracts.md's columns first, in its order; grainlab's extensions after them. Angles follow
// docs/micromechanics.md; stresses and strains are compression positive.
constexpr std::array<Definition, kSeriesColumnCount> kDefinitions{{
    {SeriesColumnId::Step, "step", "", "timestep count since the run began"},
    {SeriesColumnId::Time, "time", "s", "simulated time since the run began"},
    {SeriesColumnId::Stage, "stage", "", "the stage's name"},
    {SeriesColumnId::AxialStrain, "axial_strain", "",
     "ε22 = 1 − stretch along axis 2 since the stage began (consolidation and loading stages)"},
    {SeriesColumnId::LateralStrain, "lateral_strain", "", "ε11 = 1 − stretch along axis 1, from the same start"},
    {SeriesColumnId::VolumetricStrain, "volumetric_strain", "",
     "1 − A/A0 of the area inside the ring (a periodic cell: the cell's area), from the same start"},
    {SeriesColumnId::Sigma11, "sigma11", "Pa", "σ11 of the contact stress over the area inside the ring (a periodic cell: over the cell)"},
    {SeriesColumnId::Sigma22, "sigma22", "Pa", "σ22 of the contact stress"},
    {SeriesColumnId::Sigma12, "sigma12", "Pa", "σ12 of the contact stress"},
    {SeriesColumnId::Sigma21, "sigma21", "Pa", "σ21 of the contact stress"},
    {SeriesColumnId::P, "p", "Pa", "mean stress (σ11 + σ22)/2"},
    {SeriesColumnId::Q, "q", "Pa", "radius of Mohr's circle √(((σ11 − σ22)/2)² + ((σ12 + σ21)/2)²) = (σ1 − σ3)/2, half the q = σ1 − σ3 of PFC and YADE"},
    {SeriesColumnId::PhiMobDeg, "phi_mob_deg", "°", "mobilised friction angle asin(q/p)"},
    {SeriesColumnId::VoidRatio, "void_ratio", "", "(A − solid area)/solid area, A the area inside the ring (a periodic cell: its area)"},
    {SeriesColumnId::Coordination, "coordination", "", "contact ends on specimen particles per specimen particle"},
    {SeriesColumnId::Contacts, "contacts", "", "contacts touching a specimen particle"},
    {SeriesColumnId::AC, "a_c", "", "anisotropy of the contact normals"},
    {SeriesColumnId::ThetaCDeg, "theta_c_deg", "°", "direction of the contact normals' anisotropy"},
    {SeriesColumnId::AN, "a_n", "", "anisotropy of the normal contact forces"},
    {SeriesColumnId::ThetaNDeg, "theta_n_deg", "°", "direction of the normal forces' anisotropy"},
    {SeriesColumnId::AT, "a_t", "", "anisotropy of the tangential contact forces"},
    {SeriesColumnId::ThetaTDeg, "theta_t_deg", "°", "direction of the tangential forces' anisotropy"},
    {SeriesColumnId::AW, "a_w", "", "rotation term from moment equilibrium"},
    {SeriesColumnId::ALn, "a_ln", "", "anisotropy of the normal part of the contact vectors"},
    {SeriesColumnId::ThetaLnDeg, "theta_ln_deg", "°", "its direction"},
    {SeriesColumnId::ALt, "a_lt", "", "anisotropy of the tangential part of the contact vectors"},
    {SeriesColumnId::ThetaLtDeg, "theta_lt_deg", "°", "its direction"},
    {SeriesColumnId::ThetaSigmaMacroDeg, "theta_sigma_macro_deg", "°",
     "major principal stress direction from the stress tensor"},
    {SeriesColumnId::ThetaSigmaMicroDeg, "theta_sigma_micro_deg", "°",
     "the same from the fabric coefficients, Eq. (7)"},
    {SeriesColumnId::ThetaSigmaEq10Deg, "theta_sigma_eq10_deg", "°",
     "the same by Eq. (10): the mean of θ_c, θ_n, θ_t"},
    {SeriesColumnId::ThetaSigmaEq11Deg, "theta_sigma_eq11_deg", "°",
     "the same by Eq. (11): Eq. (7) without the contact-vector terms"},
    {SeriesColumnId::OmegaMacroDeg, "omega_macro_deg", "°",
     "non-coaxiality ω = θσ(macro) − 90°, wrapped to [−90°, 90°)"},
    {SeriesColumnId::OmegaMicroDeg, "omega_micro_deg", "°", "ω from θσ(micro)"},
    {SeriesColumnId::KineticEnergy, "kinetic_energy", "J/m", "Σ ½ m v² + ½ I ω² over the dynamic particles"},
    {SeriesColumnId::OmegaEq10Deg, "omega_eq10_deg", "°", "ω from θσ by Eq. (10)"},
    {SeriesColumnId::OmegaEq11Deg, "omega_eq11_deg", "°", "ω from θσ by Eq. (11)"},
    {SeriesColumnId::F0, "f0", "N/m", "mean normal contact force per metre of thickness (the fabric fit's isotropic part)"},
    {SeriesColumnId::L0, "l0", "m", "mean normal contact-vector length (the fabric fit's isotropic part)"},
    {SeriesColumnId::InertialNumber, "inertial_number", "", "I = ε̇ d √(ρ/p) with ε̇ the strain rate's magnitude; quasi-static below about 1e-3"},
    {SeriesColumnId::ElasticEnergy, "elastic_energy", "J/m", "energy stored in the contact springs"},
    {SeriesColumnId::Area, "area", "m²", "area inside the ring's inner envelope; a periodic cell: its area det h"},
    {SeriesColumnId::ThetaStrainRateDeg, "theta_strain_rate_deg", "°",
     "direction of the major (most compressive) principal strain rate, fitted to the ring's motion (a periodic cell: of its velocity gradient)"},
    {SeriesColumnId::OmegaStrainRateDeg, "omega_strain_rate_deg", "°",
     "θσ(macro) − θ_strain_rate, wrapped to [−90°, 90°)"},
}};
// The ids are the table's positions.
constexpr bool idsInOrder() {
  for (std::size_t k = 0; k < kDefinitions.size(); ++k) {
    if (columnIndex(kDefinitions[k].id) != k) return false;
  }
  return true;
}
static_assert(idsInOrder(), "kDefinitions must list the columns in SeriesColumnId order");

}  // namespace

const std::vector<SeriesColumn>& seriesColumnTable() {
  static const std::vector<SeriesColumn> table = [] {
    std::vector<SeriesColumn> columns;
    for (const Definition& d : kDefinitions) columns.push_back({std::string(d.name), std::string(d.unit), std::string(d.meaning)});
    return columns;
  }();
  return table;
}

const std::vector<std::string>& seriesColumns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> names;
    for (const SeriesColumn& c : seriesColumnTable()) names.push_back(c.name);
    return names;
  }();
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

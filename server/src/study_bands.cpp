#include "study_bands.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "grainlab/studies/paper/ensemble_stats.hpp"
#include "grainlab/studies/paper/series_stats.hpp"

namespace grainlab::server {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double axial(double deg) { return std::fmod(std::fmod(deg, 180.0) + 180.0, 180.0); }
double axialOffset(double deg) { return axial(deg + 90.0) - 90.0; }

std::size_t columnIndex(const std::vector<std::string>& columns, const std::string& name) {
  const auto it = std::find(columns.begin(), columns.end(), name);
  return it == columns.end() ? columns.size() : static_cast<std::size_t>(it - columns.begin());
}

double valueOf(const SampleRecord& sample, std::size_t column) {
  return column < sample.values.size() ? sample.values[column] : kNaN;
}

}  // namespace

const std::vector<BandQuantity>& bandQuantities() {
  static const std::vector<BandQuantity> quantities{
      {"phi", "φ_mob (°)"},
      {"deviator", "σ1 − σ3 (kPa)"},
      {"volumetric", "ε_v (%)"},
      {"omega", "ω from the stress (°)"},
      {"omega7", "ω from Eq. 7 (°)"},
      {"a_c", "a_c"},
      {"theta_c", "θ_c (°), where a_c ≥ 2× noise floor", true},
      {"a_n", "a_n"},
      {"theta_n", "θ_n (°), where a_n ≥ 2× noise floor", true},
      {"a_t", "a_t"},
      {"theta_t", "θ_t (°), where a_t ≥ 2× noise floor", true},
      {"a_ln", "a_ln"},
      {"theta_ln", "θ_ln (°), where a_ln ≥ 2× noise floor", true},
      {"a_lt", "a_lt"},
      {"theta_lt", "θ_lt (°), where a_lt ≥ 2× noise floor", true},
      {"asymmetry", "σ12 − σ21 (kPa)"},
  };
  return quantities;
}

const BandQuantity* bandQuantity(const std::string& key) {
  for (const BandQuantity& q : bandQuantities())
    if (q.key == key) return &q;
  return nullptr;
}

std::set<std::string> shearingStageNames(const std::string& sceneJson) {
  static const std::set<std::string> shearing{"biaxial", "rotation", "cyclic", "simple_shear", "lammps_deformation"};
  std::set<std::string> names;
  const nlohmann::json scene = nlohmann::json::parse(sceneJson, nullptr, false);
  if (!scene.is_object() || !scene.contains("stages") || !scene["stages"].is_array()) return names;
  for (const nlohmann::json& stage : scene["stages"]) {
    if (!stage.is_object() || !stage.contains("type") || !stage["type"].is_string()) continue;
    const std::string type = stage["type"].get<std::string>();
    if (!shearing.contains(type)) continue;
    names.insert(stage.contains("name") && stage["name"].is_string() ? stage["name"].get<std::string>() : type);
  }
  return names;
}

BandCurve bandCurve(const std::vector<SampleRecord>& samples, const std::vector<std::string>& columns,
                    const std::set<std::string>& shearing, const BandQuantity& quantity) {
  const auto at = [&](const char* name) { return columnIndex(columns, name); };
  const std::size_t strain = at("axial_strain");
  // The quantity as the dashboard's chart computes it from a row (chart_specs.js).
  std::size_t column = columns.size(), other = columns.size(), contacts = at("contacts");
  double factor = 1;
  const std::string& key = quantity.key;
  if (key == "phi") column = at("phi_mob_deg");
  else if (key == "deviator") column = at("q"), factor = 2e-3;  // q is (σ1 − σ3)/2, in Pa
  else if (key == "volumetric") column = at("volumetric_strain"), factor = 100;
  else if (key == "omega") column = at("omega_macro_deg");
  else if (key == "omega7") column = at("omega_micro_deg");
  else if (key == "asymmetry") column = at("sigma12"), other = at("sigma21");
  else if (quantity.direction) {
    const std::string term = key.substr(std::string("theta_").size());
    column = at(("theta_" + term + "_deg").c_str());
    other = at(("a_" + term).c_str());
  } else column = at(key.c_str());

  BandCurve curve;
  for (const SampleRecord& sample : samples) {
    if (!shearing.contains(sample.stage)) continue;
    const double x = valueOf(sample, strain) * 100;
    if (!std::isfinite(x)) continue;
    double y = valueOf(sample, column) * factor;
    if (key == "asymmetry") {
      y = (valueOf(sample, column) - valueOf(sample, other)) / 1000;
    } else if (quantity.direction) {
      const double floor = report::noiseFloor(valueOf(sample, contacts));
      if (!(valueOf(sample, other) >= report::kDirectionNoiseFactor * floor)) y = kNaN;
    }
    curve.x.push_back(x);
    curve.y.push_back(std::isfinite(y) ? y : kNaN);
  }
  return curve;
}

std::vector<double> strainGrid(const std::vector<BandCurve>& curves, int points) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const BandCurve& c : curves) {
    if (c.x.empty()) continue;
    low = std::min(low, c.x.front());
    high = std::max(high, c.x.back());
  }
  if (!(low <= high) || points < 2) return {};
  if (low == high) return {low};
  std::vector<double> grid(static_cast<std::size_t>(points));
  for (int k = 0; k < points; ++k) grid[static_cast<std::size_t>(k)] = low + (high - low) * k / (points - 1);
  grid.back() = high;  // exactly the last strain reached, not a rounding beside it
  return grid;
}

std::vector<double> valuesAt(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& xs,
                             bool direction) {
  // As the dashboard's valuesAt (ensemble_stats.js): the first pair of samples around each x,
  // searched onwards from the last one found.
  std::vector<double> out;
  out.reserve(xs.size());
  const std::size_t size = x.size();
  std::size_t k = 1;
  for (double at : xs) {
    if (size == 0) {
      out.push_back(kNaN);
      continue;
    }
    if (at == x[0]) {
      out.push_back(y[0]);
      continue;
    }
    if (k >= size || !(x[k - 1] <= at)) k = 1;
    while (k < size && !(x[k - 1] <= at && at <= x[k])) ++k;
    if (k >= size) {
      out.push_back(kNaN);
      continue;
    }
    const double y0 = y[k - 1], y1 = y[k];
    if (at == x[k]) out.push_back(y1);
    else if (!std::isfinite(y0) || !std::isfinite(y1)) out.push_back(kNaN);
    else {
      const double w = (at - x[k - 1]) / (x[k] - x[k - 1]);
      out.push_back(direction ? axial(y0 + w * axialOffset(y1 - y0)) : y0 + w * (y1 - y0));
    }
  }
  return out;
}

std::vector<Band> ensembleBands(const std::vector<BandCurve>& curves, std::size_t groups, const std::vector<double>& grid,
                                bool direction) {
  std::vector<std::vector<std::vector<double>>> columns(groups);  // [group][run][grid point]
  for (const BandCurve& c : curves) {
    if (c.group >= groups || c.x.empty()) continue;  // a run that never reached its shearing stage
    columns[c.group].push_back(valuesAt(c.x, c.y, grid, direction));
  }
  std::vector<Band> bands(groups);
  std::vector<double> values;
  for (std::size_t g = 0; g < groups; ++g) {
    Band& band = bands[g];
    const auto& runs = columns[g];
    // A direction means something in few runs where most sit below their noise floor: a mean
    // of fewer than half the runs is dropped (the dashboard's quorum).
    const int need = std::max<int>(1, static_cast<int>((runs.size() + 1) / 2));
    for (std::size_t i = 0; i < grid.size(); ++i) {
      values.clear();
      for (const auto& run : runs) values.push_back(run[i]);
      const report::MeanInterval m = direction ? report::axialMeanInterval(values) : report::meanInterval(values);
      const bool drop = direction && m.n < need;
      band.mean.push_back(drop || m.n == 0 ? kNaN : m.mean);
      band.low.push_back(drop || m.n < 2 ? kNaN : m.low);
      band.high.push_back(drop || m.n < 2 ? kNaN : m.high);
      band.n.push_back(m.n);
    }
  }
  return bands;
}

}  // namespace grainlab::server

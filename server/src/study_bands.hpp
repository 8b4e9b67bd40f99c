#pragma once
// A study's ensemble bands (GET /api/studies/{name}/bands): its completed runs grouped by the
// value of one varied path, and each group's mean of one quantity with its 95 % interval
// against axial strain, every run read from its stored series and interpolated onto one
// strain grid shared by all groups. The statistics are the report's (grainlab::report:
// Student's t for plain values, circular for directions), so a band here and a figure of
// `grainlab paper` agree. Here the arithmetic and the quantities; the route is
// RunService::studyBands (study_bands_service.cpp).
#include <cstddef>
#include <set>
#include <string>
#include <vector>

#include "run_record.hpp"

namespace grainlab::server {

/// One quantity a band can show: the dashboard's compare charts (web/js/chart_specs.js
/// COMPARE_CHARTS), by the same keys.
struct BandQuantity {
  std::string key;    ///< "phi", "deviator", ... as the chart's
  std::string title;  ///< "φ_mob (°)"
  /// An axial direction (period 180°): interpolated along the shorter arc, averaged on the
  /// circle. Directions are gaps where a_k is below twice its noise floor, and a group's mean
  /// at a strain is dropped where fewer than half its runs have a value there.
  bool direction = false;
};

/// Every quantity, in the charts' order; bandQuantity(key) one of them or nullptr.
const std::vector<BandQuantity>& bandQuantities();
const BandQuantity* bandQuantity(const std::string& key);

/// One run's curve: x the axial strain in percent over its shearing stages, y the quantity
/// (NaN where it has no value).
struct BandCurve {
  std::size_t group = 0;  ///< the index of the group it belongs to
  std::vector<double> x, y;
};

/// The curve a run's stored series gives: its rows in the `shearing` stages with a finite
/// axial strain. `columns` names the values of each sample (grainlab::seriesColumns()).
BandCurve bandCurve(const std::vector<SampleRecord>& samples, const std::vector<std::string>& columns,
                    const std::set<std::string>& shearing, const BandQuantity& quantity);

/// The names of a scene's shearing stages (biaxial, rotation, cyclic, simple_shear,
/// lammps_deformation: `name`, else its type), as the dashboard's shearingStages().
std::set<std::string> shearingStageNames(const std::string& sceneJson);

/// `points` (>= 2) equally spaced strains from the least first x of the curves to the largest
/// last x; empty when no curve has a point.
std::vector<double> strainGrid(const std::vector<BandCurve>& curves, int points);

/// The curve's y at each of `xs` (ascending): linear between the two samples around it, along
/// the shorter arc for a direction; NaN outside its range or beside a NaN.
std::vector<double> valuesAt(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& xs,
                             bool direction);

/// One group's band on the grid: at each strain the mean, the ends of its 95 % interval (NaN
/// with fewer than two runs there) and how many runs have a value there.
struct Band {
  std::vector<double> mean, low, high;
  std::vector<int> n;
};

/// The `groups` groups' bands on `grid`.
std::vector<Band> ensembleBands(const std::vector<BandCurve>& curves, std::size_t groups, const std::vector<double>& grid,
                                bool direction);

}  // namespace grainlab::server

#pragma once
// The columns of series.csv, defined once: a typed id for the code that fills or reads a
// column (a misspelt id does not compile), and a table of name, unit and meaning from which
// the CSV header, the API's column list, `grainlab columns` and docs/series-columns.md come;
// the dashboard's charts are checked against it.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab {

/// One per column, in the table's order (contracts.md's columns first, then grainlab's).
enum class SeriesColumnId : std::size_t {
  Step,
  Time,
  Stage,
  AxialStrain,
  LateralStrain,
  VolumetricStrain,
  Sigma11,
  Sigma22,
  Sigma12,
  Sigma21,
  P,
  Q,
  PhiMobDeg,
  VoidRatio,
  Coordination,
  Contacts,
  AC,
  ThetaCDeg,
  AN,
  ThetaNDeg,
  AT,
  ThetaTDeg,
  AW,
  ALn,
  ThetaLnDeg,
  ALt,
  ThetaLtDeg,
  ThetaSigmaMacroDeg,
  ThetaSigmaMicroDeg,
  ThetaSigmaEq10Deg,
  ThetaSigmaEq11Deg,
  OmegaMacroDeg,
  OmegaMicroDeg,
  KineticEnergy,
  OmegaEq10Deg,
  OmegaEq11Deg,
  F0,
  L0,
  InertialNumber,
  ElasticEnergy,
  Area,
  ThetaStrainRateDeg,
  OmegaStrainRateDeg,
};
inline constexpr std::size_t kSeriesColumnCount = static_cast<std::size_t>(SeriesColumnId::OmegaStrainRateDeg) + 1;
/// The column's position in a Sample's values and in series.csv.
constexpr std::size_t columnIndex(SeriesColumnId id) { return static_cast<std::size_t>(id); }

/// A column of series.csv: its name, unit ("" for a pure number or a name) and meaning.
struct SeriesColumn {
  std::string name, unit, meaning;
};
/// The table, in SeriesColumnId order.
const std::vector<SeriesColumn>& seriesColumnTable();
/// The columns' names, in order.
const std::vector<std::string>& seriesColumns();
/// The position of a column named at run time (a file's header, a request); throws
/// std::logic_error for an unknown name. Code that knows its column uses SeriesColumnId.
std::size_t seriesColumnIndex(std::string_view name);

}  // namespace grainlab

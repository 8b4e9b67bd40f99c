#pragma once
// The shearing (biaxial) stage of one run, column by column, as the report reads it.
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab::report {

/// Named columns of equal length, one value per sample (units as series.csv: Pa, degrees,
/// strains compression positive). The first sample is the state the stage starts from, with
/// axial_strain = 0. A column that was not measured reads as NaN.
class ShearingSeries {
 public:
  /// Appends one sample: names[k] takes values[k]. Throws std::invalid_argument if the two
  /// differ in size. Columns not named get NaN for this sample.
  void append(const std::vector<std::string>& names, const std::vector<double>& values);
  /// Sets a whole column (for building series in tests). Throws std::invalid_argument if its
  /// length differs from the columns already present.
  void setColumn(const std::string& name, std::vector<double> values);
  /// Number of samples.
  size_t size() const { return size_; }
  bool has(std::string_view name) const;
  /// The column's values, or size() NaNs if there is no such column.
  std::vector<double> column(std::string_view name) const;
  /// One value; NaN if the column is absent or row is out of range.
  double at(std::string_view name, size_t row) const;

 private:
  std::map<std::string, std::vector<double>, std::less<>> columns_;
  size_t size_ = 0;
};

}  // namespace grainlab::report

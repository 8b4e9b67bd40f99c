#pragma once
// One sample row in the three shapes the server hands out: a {column: value} object (the
// stream's "sample" message), a positional array (the REST series) and a CSV line, which is
// the engine's own formatSeriesRow so the text is the CLI's series.csv byte for byte.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_record.hpp"

namespace grainlab {
struct Sample;
}

namespace grainlab::server {

/// Columns are grainlab::seriesColumns(); Sample::values has one entry per column.
class SeriesFormat {
 public:
  SeriesFormat();

  const std::vector<std::string>& columns() const { return *columns_; }
  /// {column: value}; `step` an integer, `stage` text, a value not measured (NaN) null.
  nlohmann::json rowObject(const SampleRecord& sample) const;
  /// The same values in column order.
  nlohmann::json rowArray(const SampleRecord& sample) const;
  /// series.csv's header line, with its newline.
  std::string csvHeader() const;
  /// One series.csv line, with its newline.
  std::string csvRow(const SampleRecord& sample) const;

 private:
  nlohmann::json cell(const SampleRecord& sample, std::size_t column) const;
  const std::vector<std::string>* columns_;
};

/// What the server stores of an engine sample.
SampleRecord toRecord(const Sample& sample, std::int64_t seq);

}  // namespace grainlab::server

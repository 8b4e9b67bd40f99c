#include "series_format.hpp"

#include <cmath>

#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"

namespace grainlab::server {

SeriesFormat::SeriesFormat() : columns_(&grainlab::seriesColumns()) {}

nlohmann::json SeriesFormat::cell(const SampleRecord& sample, std::size_t column) const {
  const auto& name = (*columns_)[column];
  if (name == "step") return sample.step;
  if (name == "time") return sample.time;
  if (name == "stage") return sample.stage;
  // JSON has no NaN: a quantity not measured (no contacts yet) is null, as the CSV's empty cell.
  if (column < sample.values.size() && std::isfinite(sample.values[column]))
    return sample.values[column];
  return nullptr;
}

nlohmann::json SeriesFormat::rowObject(const SampleRecord& sample) const {
  nlohmann::json row = nlohmann::json::object();
  for (std::size_t c = 0; c < columns_->size(); ++c) row[(*columns_)[c]] = cell(sample, c);
  return row;
}

nlohmann::json SeriesFormat::rowArray(const SampleRecord& sample) const {
  nlohmann::json row = nlohmann::json::array();
  for (std::size_t c = 0; c < columns_->size(); ++c) row.push_back(cell(sample, c));
  return row;
}

std::string SeriesFormat::csvHeader() const { return grainlab::seriesHeader() + "\n"; }

std::string SeriesFormat::csvRow(const SampleRecord& sample) const {
  grainlab::Sample s;
  s.step = sample.step;
  s.time = sample.time;
  s.stage = sample.stage;
  s.values = sample.values;
  return grainlab::formatSeriesRow(s) + "\n";
}

SampleRecord toRecord(const Sample& sample, std::int64_t seq) {
  return {seq, sample.step, sample.time, sample.stage, sample.values};
}

}  // namespace grainlab::server

#include "grainlab/studies/paper/shearing_series.hpp"

#include <cmath>
#include <stdexcept>

namespace grainlab::report {

void ShearingSeries::append(const std::vector<std::string>& names, const std::vector<double>& values) {
  if (names.size() != values.size()) throw std::invalid_argument("ShearingSeries::append: names and values differ in size");
  for (size_t k = 0; k < names.size(); ++k) {
    auto [it, fresh] = columns_.try_emplace(names[k]);
    // A column first seen now has no values for the earlier samples.
    if (fresh) it->second.assign(size_, std::nan(""));
    it->second.push_back(values[k]);
  }
  ++size_;
  for (auto& [name, column] : columns_) {
    if (column.size() < size_) column.push_back(std::nan(""));
  }
}

void ShearingSeries::setColumn(const std::string& name, std::vector<double> values) {
  const bool onlyThis = columns_.empty() || (columns_.size() == 1 && columns_.count(name));
  if (!onlyThis && values.size() != size_) {
    throw std::invalid_argument("ShearingSeries::setColumn: " + name + " has " + std::to_string(values.size()) +
                                " values, the other columns " + std::to_string(size_));
  }
  size_ = values.size();
  columns_[name] = std::move(values);
}

bool ShearingSeries::has(std::string_view name) const { return columns_.find(name) != columns_.end(); }

std::vector<double> ShearingSeries::column(std::string_view name) const {
  const auto it = columns_.find(name);
  if (it == columns_.end()) return std::vector<double>(size_, std::nan(""));
  return it->second;
}

double ShearingSeries::at(std::string_view name, size_t row) const {
  const auto it = columns_.find(name);
  if (it == columns_.end() || row >= it->second.size()) return std::nan("");
  return it->second[row];
}

}  // namespace grainlab::report

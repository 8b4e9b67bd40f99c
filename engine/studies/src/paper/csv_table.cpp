#include "grainlab/studies/paper/csv_table.hpp"

#include <fstream>
#include <stdexcept>

#include "grainlab/studies/paper/number_text.hpp"

namespace grainlab::report {
namespace {

std::string quoted(const std::string& cell) {
  if (cell.find_first_of(",\"\n\r") == std::string::npos) return cell;
  std::string out = "\"";
  for (char c : cell) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

CsvCell::CsvCell(double value) : text_(general(value)) {}
CsvCell::CsvCell(int value) : text_(std::to_string(value)) {}
CsvCell::CsvCell(std::string text) : text_(std::move(text)) {}
CsvCell::CsvCell(const char* text) : text_(text) {}

CsvTable::CsvTable(std::vector<std::string> header) : header_(std::move(header)) {}

void CsvTable::addRow(std::vector<CsvCell> row) {
  if (row.size() != header_.size()) {
    throw std::invalid_argument("CSV row has " + std::to_string(row.size()) + " cells for " +
                                std::to_string(header_.size()) + " columns");
  }
  std::vector<std::string> cells;
  cells.reserve(row.size());
  for (const CsvCell& c : row) cells.push_back(c.text());
  rows_.push_back(std::move(cells));
}

std::string CsvTable::text() const {
  std::string out;
  auto line = [&out](const std::vector<std::string>& cells) {
    for (size_t k = 0; k < cells.size(); ++k) {
      if (k) out += ',';
      out += quoted(cells[k]);
    }
    out += '\n';
  };
  line(header_);
  for (const auto& row : rows_) line(row);
  return out;
}

void CsvTable::write(const std::string& path) const {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text();
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace grainlab::report

#pragma once
// A small CSV table: the data behind one figure or table of the report, written as it is shown.
#include <initializer_list>
#include <string>
#include <vector>

namespace grainlab::report {

/// One CSV cell: a number (10 significant digits; empty for NaN or infinity, never "nan") or text.
class CsvCell {
 public:
  CsvCell(double value);                 // NOLINT: numbers convert implicitly, by design
  CsvCell(int value);                    // NOLINT
  CsvCell(std::string text);             // NOLINT
  CsvCell(const char* text);             // NOLINT
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> header);
  /// Throws std::invalid_argument unless the row has one cell per header column.
  void addRow(std::vector<CsvCell> row);
  const std::vector<std::string>& header() const { return header_; }
  size_t rows() const { return rows_.size(); }
  /// RFC 4180 text: a header line, then one line per row; cells with , " or a newline quoted.
  std::string text() const;
  /// Writes text() to `path`; throws std::runtime_error if it cannot.
  void write(const std::string& path) const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace grainlab::report

#pragma once
// A run's series.csv as columns by name, for tests that check what a run measured: an empty
// cell (a quantity not measured at that sample) and the stage's name read as NaN, the stage
// names kept in `stages`.
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "file_bytes.hpp"

namespace grainlab::testing {

inline std::map<std::string, std::vector<double>> readSeriesColumns(const std::filesystem::path& file,
                                                                    std::vector<std::string>& stages) {
  std::istringstream in(fileBytes(file));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string c; std::getline(header, c, ',');) names.push_back(c);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    size_t start = 0;
    for (size_t k = 0; k <= line.size(); ++k) {
      if (k == line.size() || line[k] == ',') {
        cells.push_back(line.substr(start, k - start));
        start = k + 1;
      }
    }
    for (size_t k = 0; k < names.size(); ++k) {
      const std::string cell = k < cells.size() ? cells[k] : "";
      if (names[k] == "stage") stages.push_back(cell);
      double v = std::nan("");
      if (!cell.empty() && names[k] != "stage") v = std::stod(cell);
      columns[names[k]].push_back(v);
    }
  }
  return columns;
}

}  // namespace grainlab::testing

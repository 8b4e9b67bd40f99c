#pragma once
// `grainlab columns [--json | --markdown]`: series.csv's columns from their one table
// (seriesColumnTable): name, unit and meaning.
#include <string>
#include <vector>

namespace grainlab {

int columnsCommand(const std::vector<std::string>& args);

}  // namespace grainlab

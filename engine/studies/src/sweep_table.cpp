#include "grainlab/studies/sweep_table.hpp"

#include "grainlab/output_writer.hpp"
#include "grainlab/validity.hpp"

#include <cstdio>
#include <fstream>
#include <map>

namespace grainlab::studies {
namespace {

namespace fs = std::filesystem;

// Scalars of summary.json, as columns of the same names.
const std::vector<std::string> kSummaryColumns{"steps", "particles", "peak_phi_mob_deg",
                                               "void_ratio_after_consolidation", "timestep"};
// Columns of series.csv whose last value is a run's final state, as final_<name>.
const std::vector<std::string> kFinalColumns{"axial_strain", "p", "q", "phi_mob_deg", "void_ratio",
                                             "coordination", "omega_macro_deg"};

std::string csvCell(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// The last row of series.csv by column name; empty if there is none.
std::map<std::string, std::string> lastSeriesRow(const fs::path& file) {
  std::ifstream in(file);
  std::string header, line, last;
  if (!std::getline(in, header)) return {};
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  std::map<std::string, std::string> row;
  const std::vector<std::string> names = splitSeriesRow(header), cells = splitSeriesRow(last);
  for (size_t k = 0; k < names.size() && k < cells.size(); ++k) row[names[k]] = cells[k];
  return row;
}

nlohmann::json readSummary(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return nlohmann::json::object();
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception&) {
    return nlohmann::json::object();
  }
}

std::string scalarText(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  return value.is_number() ? value.dump() : std::string();  // dump() keeps every bit of a double
}

}  // namespace

const std::vector<std::string>& sweepResultColumns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> c{"status", "error", "wall_seconds"};
    c.insert(c.end(), kSummaryColumns.begin(), kSummaryColumns.end());
    for (const std::string& name : kFinalColumns) c.push_back("final_" + name);
    c.push_back("warnings");  // the validity envelope's, as "quantity at field; ..." (docs/validity.md)
    return c;
  }();
  return columns;
}

std::string sweepTable(const std::vector<SweepRun>& runs, const std::vector<BatchRunResult>& results,
                       const fs::path& runsDir) {
  std::string text;
  auto cell = [&](const std::string& value) {  // appended piece by piece: gcc 12 warns falsely on "," + s
    if (!text.empty() && text.back() != '\n') text += ',';
    text += csvCell(value);
  };
  cell("run_id");
  if (!runs.empty()) {
    for (const auto& parameter : runs.front().parameters) cell(parameter.first);
  }
  for (const std::string& column : sweepResultColumns()) cell(column);
  text += '\n';
  for (size_t k = 0; k < runs.size(); ++k) {
    const SweepRun& run = runs[k];
    const BatchRunResult& result = results[k];
    cell(run.id);
    for (const auto& parameter : run.parameters) {
      const nlohmann::json& value = parameter.second;
      cell(value.is_string() ? value.get<std::string>() : value.dump());
    }
    char wall[32];
    std::snprintf(wall, sizeof wall, "%.3f", result.wallSeconds);
    cell(std::string(toString(result.status)));
    cell(result.error);
    cell(wall);
    const nlohmann::json summary = readSummary(runsDir / run.id / "summary.json");
    for (const std::string& name : kSummaryColumns) cell(summary.contains(name) ? scalarText(summary[name]) : "");
    const std::map<std::string, std::string> last = lastSeriesRow(runsDir / run.id / "series.csv");
    for (const std::string& name : kFinalColumns) {
      const auto it = last.find(name);
      cell(it == last.end() ? std::string() : it->second);
    }
    std::string warnings;
    for (const ValidityWarning& w : warningsFromJson(summary.value("warnings", nlohmann::json::array())))
      warnings += (warnings.empty() ? "" : "; ") + w.quantity + " at " + w.field;
    cell(warnings);
    text += '\n';
  }
  return text;
}

}  // namespace grainlab::studies

#include "grainlab/studies/paper/run_loader.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "grainlab/presets.hpp"
#include "grainlab/studies/paper/assembly_recorder.hpp"
#include "grainlab/studies/paper/shearing_collector.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"

namespace grainlab::report {
namespace {

namespace fs = std::filesystem;

}  // namespace

nlohmann::json rosesToJson(const std::vector<RoseSnapshot>& roses) {
  nlohmann::json list = nlohmann::json::array();
  for (const RoseSnapshot& r : roses) {
    nlohmann::json h = nullptr;
    if (r.histograms) h = *r.histograms;
    list.push_back({{"target_strain", r.targetStrain},
                    {"axial_strain", std::isfinite(r.axialStrain) ? nlohmann::json(r.axialStrain) : nlohmann::json()},
                    {"histograms", h}});
  }
  return {{"roses", list}};
}

void rosesFromJson(const nlohmann::json& json, std::vector<RoseSnapshot>& roses) {
  for (const nlohmann::json& item : json.at("roses")) {
    const double target = item.at("target_strain").get<double>();
    for (RoseSnapshot& r : roses) {
      if (std::abs(r.targetStrain - target) > 1e-12 || item.at("histograms").is_null()) continue;
      r.axialStrain = item.at("axial_strain").is_null() ? NAN : item.at("axial_strain").get<double>();
      analysis::PolarHistograms h;
      from_json(item.at("histograms"), h);
      r.histograms = std::move(h);
    }
  }
}

RunSummary readRunSummary(const std::string& runDir) {
  const fs::path file = fs::path(runDir) / "summary.json";
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  nlohmann::json s;
  try {
    in >> s;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
  RunSummary summary;
  summary.status = parseRunStatus(s.value("status", std::string())).value_or(RunStatus::Failed);
  summary.error = s.value("error", std::string());
  summary.wallSeconds = s.value("wall_seconds", 0.0);
  summary.steps = s.value("steps", std::int64_t{0});
  summary.particles = s.value("particles", 0);
  summary.peakPhiMobDeg = s.value("peak_phi_mob_deg", 0.0);
  summary.voidRatioAfterConsolidation = s.value("void_ratio_after_consolidation", -1.0);
  summary.warnings = warningsFromJson(s.value("warnings", nlohmann::json::array()));
  return summary;
}

AssemblyResult loadAssemblyResult(const std::string& runDir, const std::string& preset) {
  const fs::path dir(runDir);
  // The scene the run ran (its seed included) when it kept one; else the preset's.
  nlohmann::json sceneJson = presetScene(preset);
  if (std::ifstream sceneFile(dir / "scene.json"); sceneFile) {
    try {
      sceneFile >> sceneJson;
    } catch (const nlohmann::json::exception& e) {
      throw std::runtime_error((dir / "scene.json").string() + ": " + e.what());
    }
  }
  const Scene scene = parseScene(sceneJson);
  AssemblyResult result = describeAssembly(preset, scene);
  result.seed = static_cast<int>(scene.seed);

  result.summary = readRunSummary(runDir);

  std::ifstream series(dir / "series.csv");
  if (!series) throw std::runtime_error("cannot read " + (dir / "series.csv").string());
  std::string line;
  std::getline(series, line);
  const std::vector<std::string> header = splitSeriesRow(line);
  // Columns by name, so a series.csv with columns added or moved still reads.
  std::vector<int> slot(header.size(), -1);
  for (size_t k = 0; k < header.size(); ++k) {
    const auto& columns = seriesColumns();
    const auto it = std::find(columns.begin(), columns.end(), header[k]);
    if (it != columns.end()) slot[k] = static_cast<int>(it - columns.begin());
  }
  constexpr size_t stageColumn = columnIndex(SeriesColumnId::Stage), stepColumn = columnIndex(SeriesColumnId::Step);
  ShearingCollector collector(result, biaxialStageIndex(scene));
  while (std::getline(series, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = splitSeriesRow(line);
    std::vector<double> values(seriesColumns().size(), NAN);
    for (size_t k = 0; k < cells.size() && k < slot.size(); ++k) {
      if (slot[k] < 0) continue;
      const size_t c = static_cast<size_t>(slot[k]);
      if (c == stageColumn) {
        // The file names the stage; the collector wants its index.
        for (size_t st = 0; st < scene.stages.size(); ++st) {
          if (scene.stages[st].name == cells[k]) {
            values[c] = static_cast<double>(st);
            break;
          }
        }
      } else if (!cells[k].empty()) {
        values[c] = std::strtod(cells[k].c_str(), nullptr);
      }
    }
    collector.add(static_cast<std::int64_t>(values[stepColumn]), values, nullptr);
  }

  std::ifstream roses(dir / kRosesFile);
  if (roses) {
    nlohmann::json r;
    roses >> r;
    rosesFromJson(r, result.roses);
  }
  return result;
}

}  // namespace grainlab::report

#include "sweep_import.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"
#include "grainlab/server/import.hpp"
#include "repository.hpp"
#include "run_service.hpp"

namespace grainlab::server {
namespace {

namespace fs = std::filesystem;

nlohmann::json readJson(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::invalid_argument("cannot read " + file.string());
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(file.string() + " is not valid JSON: " + e.what());
  }
}

// series.csv back into sample rows, column by column name (an empty cell is "not measured").
std::vector<SampleRecord> readSeries(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  if (!in || !std::getline(in, line)) return {};
  const std::vector<std::string> header = splitSeriesRow(line);
  std::vector<long> slot(header.size(), -1);  // header column -> seriesColumns() index
  for (size_t c = 0; c < header.size(); ++c) {
    for (size_t k = 0; k < seriesColumns().size(); ++k) {
      if (seriesColumns()[k] == header[c]) slot[c] = static_cast<long>(k);
    }
  }
  std::vector<SampleRecord> samples;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = splitSeriesRow(line);
    SampleRecord s;
    s.seq = static_cast<std::int64_t>(samples.size());
    s.values.assign(seriesColumns().size(), NAN);
    for (size_t c = 0; c < cells.size() && c < header.size(); ++c) {
      if (slot[c] < 0) continue;
      if (header[c] == "stage") {
        s.stage = cells[c];
      } else if (!cells[c].empty()) {
        s.values[static_cast<size_t>(slot[c])] = std::strtod(cells[c].c_str(), nullptr);
      }
    }
    s.step = static_cast<std::int64_t>(s.values[columnIndex(SeriesColumnId::Step)]);
    s.time = s.values[columnIndex(SeriesColumnId::Time)];
    samples.push_back(std::move(s));
  }
  return samples;
}

}  // namespace

SweepImport importSweep(Repository& repo, const fs::path& dir) {
  const fs::path sweepFile = dir / "sweep.json";
  if (!fs::is_regular_file(sweepFile))
    throw std::invalid_argument(dir.string() + " is not a sweep folder (it has no sweep.json)");
  const nlohmann::json sweep = readJson(sweepFile);
  if (!sweep.contains("runs") || !sweep["runs"].is_array())
    throw std::invalid_argument(sweepFile.string() + " lists no runs");
  const nlohmann::json& spec = sweep.value("spec", nlohmann::json::object());
  const std::string sweepName =
      spec.contains("name") && spec["name"].is_string() ? spec["name"].get<std::string>()
                                                        : fs::absolute(dir).lexically_normal().filename().string();
  const std::string preset = spec.contains("base") && spec["base"].contains("preset") && spec["base"]["preset"].is_string()
                                 ? spec["base"]["preset"].get<std::string>()
                                 : std::string();

  // The study's row: the spec as the sweep folder keeps it (its "vary" in its order, the order
  // of its runs) and every run's values, as a launched study's (study_launch.cpp).
  if (const auto existing = repo.launchedStudies(sweepName); !existing.empty() && existing.front().source != "imported")
    throw std::invalid_argument("a study named '" + sweepName + "' was launched on this server: the sweep " +
                                dir.string() + " cannot be imported under its name (give its spec another name)");
  nlohmann::ordered_json orderedSpec = nlohmann::ordered_json::object();
  {
    std::ifstream in(sweepFile);
    const auto ordered = nlohmann::ordered_json::parse(in, nullptr, false);
    if (ordered.is_object() && ordered.contains("spec")) orderedSpec = ordered["spec"];
  }
  nlohmann::json listed = nlohmann::json::array();

  SweepImport outcome;
  for (const nlohmann::json& entry : sweep["runs"]) {
    const std::string id = entry.at("id").get<std::string>();
    const fs::path runDir = dir / "runs" / id;
    if (!fs::is_regular_file(runDir / "summary.json") || !fs::is_regular_file(runDir / "scene.json")) {
      ++outcome.notFinished;
      continue;
    }
    const nlohmann::json summary = readJson(runDir / "summary.json");
    const std::string scene = readJson(runDir / "scene.json").dump();
    RunRecord record;
    record.name = sweepName + "/" + id;
    const nlohmann::json parameters = entry.value("parameters", nlohmann::json::object());
    // Importing twice adds nothing: a run of this name with this scene is there already.
    std::optional<std::int64_t> seen;
    for (const std::int64_t storedId : repo.runIdsNamed(record.name)) {
      const std::optional<RunRecord> stored = repo.findRun(storedId);
      if (stored && stored->scene == scene) {
        seen = storedId;
        break;
      }
    }
    if (seen) {
      ++outcome.alreadyThere;
      listed.push_back({{"id", *seen}, {"name", record.name}, {"parameters", parameters}});
      continue;
    }
    record.preset = preset;
    record.study = sweepName;
    record.scene = scene;
    record.status = RunStatus::Queued;  // until finishRun below, in the same queue of writes
    record.particles = summary.value("particles", 0);
    record.createdAt = unixNow();
    const std::int64_t runId = repo.insertRun(record).get();
    repo.markStarted(runId, record.createdAt);
    const std::vector<SampleRecord> samples = readSeries(runDir / "series.csv");
    for (const SampleRecord& s : samples) repo.appendSample(runId, s);
    RunEnd end;
    end.status = parseRunStatus(summary.value("status", std::string())).value_or(RunStatus::Failed);
    if (end.status != RunStatus::Completed && end.status != RunStatus::Cancelled) end.status = RunStatus::Failed;
    end.error = summary.value("error", std::string());
    end.stage = samples.empty() ? std::string() : samples.back().stage;
    end.finishedAt = record.createdAt;
    if (summary.contains("wall_seconds")) end.wallSeconds = summary["wall_seconds"].get<double>();
    end.steps = summary.value("steps", std::int64_t{0});
    end.particles = record.particles;
    if (summary.contains("peak_phi_mob_deg")) end.peakPhiMobDeg = summary["peak_phi_mob_deg"].get<double>();
    if (summary.contains("warnings")) end.warnings = summary["warnings"].dump();
    repo.finishRun(runId, end, [] {});
    outcome.ids.push_back(runId);
    listed.push_back({{"id", runId}, {"name", record.name}, {"parameters", parameters}});
  }
  StudyRecord study;
  study.name = sweepName;
  study.spec = orderedSpec.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  study.runs = listed.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  study.createdAt = unixNow();
  study.source = "imported";
  repo.putImportedStudy(study).get();  // after the runs, in the same queue of writes
  return outcome;
}

ImportReport importSweepFolder(const std::string& dir, const std::string& db) {
  Repository repo(db, Repository::Opener::Tool);  // a server may be running on the same file
  const SweepImport outcome = importSweep(repo, dir);
  return {static_cast<int>(outcome.ids.size()), outcome.alreadyThere, outcome.notFinished};
}

}  // namespace grainlab::server

#include "specimen_source.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "grainlab/prepared_specimen.hpp"
#include "api_types.hpp"

namespace grainlab::server {
namespace {

namespace fs = std::filesystem;

constexpr const char* kStagedSuffix = ".incoming";

std::string inQuotes(const std::string& s) { return "'" + s + "'"; }

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// The stored run's stages, by name; empty if its scene cannot be read (it was, when stored).
std::vector<std::string> stageNames(const RunRecord& record) {
  try {
    const Scene scene = parseScene(nlohmann::json::parse(record.scene));
    std::vector<std::string> names;
    for (const StageSpec& s : scene.stages) names.push_back(s.name);
    return names;
  } catch (const std::exception&) {
    return {};
  }
}

// The stage a start_from without one begins after: the one before the first shearing stage.
std::string defaultStage(const Scene& scene) {
  for (std::size_t k = 1; k < scene.stages.size(); ++k)
    if (isShearing(scene.stages[k].type)) return scene.stages[k - 1].name;
  throw ApiError(400, "this scene has no shearing stage to begin before: name the stage to start from",
                 "start_from.stage");
}

bool isFile(const std::string& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

}  // namespace

StagedSpecimen::~StagedSpecimen() {
  if (path_.empty()) return;
  std::error_code ec;
  fs::remove(path_, ec);
}

std::string StagedSpecimen::release() {
  std::string path = std::move(path_);
  path_.clear();
  return path;
}

std::string SpecimenSource::runFolder(std::int64_t id) const {
  return (fs::path(dir_) / ("run-" + std::to_string(id))).string();
}

std::string SpecimenSource::startedFromPath(std::int64_t id) const {
  return (fs::path(runFolder(id)) / "specimen.checkpoint").string();
}

StagedSpecimen SpecimenSource::stage(Scene& scene, const std::optional<RunRecord>& parent, RunOrigin& origin) const {
  StartFrom& from = *scene.startFrom;
  // The server reads no file a request names (docs/security.md).
  if (!from.run.empty() || !from.checkpoint.empty()) {
    throw ApiError(400,
                   "this server reads no file a request names: start from a run stored here with start_from.run_id "
                   "(and start_from.stage)",
                   from.run.empty() ? "start_from.checkpoint" : "start_from.run");
  }
  const std::string runName = "run " + std::to_string(from.runId);
  if (!parent) throw ApiError(400, "there is no " + runName + " on this server", "start_from.run_id");
  if (from.stage.empty()) from.stage = defaultStage(scene);
  origin = RunOrigin{from.runId, from.stage};

  std::string path = stageCheckpointPath(runFolder(from.runId), from.stage);
  // A run that itself started from a specimen kept none of the stages it skipped, but it has
  // its own copy of the end of the one it started after.
  if (!isFile(path) && parent->origin && parent->origin->stage == from.stage) path = startedFromPath(from.runId);
  if (!isFile(path)) {
    const std::vector<std::string> stages = stageNames(*parent);
    if (!stages.empty() && std::find(stages.begin(), stages.end(), from.stage) == stages.end()) {
      throw ApiError(400, runName + " has no stage " + inQuotes(from.stage) + " (its stages: " + joined(stages) + ")",
                     "start_from.stage");
    }
    if (!hasEnded(parent->status)) {
      throw ApiError(409,
                     runName + " has not ended stage " + inQuotes(from.stage) + " yet (it is " +
                         std::string(toString(parent->status)) +
                         (parent->stage.empty() ? "" : ", in stage " + inQuotes(parent->stage)) +
                         "): start from it once that stage has ended",
                     "start_from.run_id");
    }
    const std::vector<std::string> kept = keptStages(*parent);
    std::string why = kept.empty() ? "it kept none" : "it kept: " + joined(kept);
    if (parent->status != RunStatus::Completed)
      why += "; it ended " + std::string(toString(parent->status)) +
             (parent->stage.empty() ? "" : " in stage " + inQuotes(parent->stage));
    else if (kept.empty())
      why += ": its scene keeps no stage checkpoints (output.stage_checkpoints, off by default for box2d), or it "
             "was imported from a sweep folder";
    throw ApiError(400, runName + " kept no checkpoint of stage " + inQuotes(from.stage) + " (" + why + ")",
                   "start_from.run_id");
  }

  // Linked (not copied) where the file system allows: stage checkpoints are replaced by
  // rename, never written in place, so the link keeps the bytes checked now.
  static std::atomic<std::uint64_t> counter{0};
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  const std::string staged = (fs::path(dir_) / ("specimen-" + std::to_string(now) + "-" +
                                                std::to_string(counter.fetch_add(1)) + kStagedSuffix))
                                 .string();
  std::error_code ec;
  fs::create_directories(dir_, ec);
  fs::create_hard_link(path, staged, ec);
  if (ec) {
    ec.clear();
    fs::copy_file(path, staged, fs::copy_options::overwrite_existing, ec);
  }
  if (ec) {
    // The parent was deleted meanwhile, or the disk is full.
    throw ApiError(isFile(path) ? 503 : 400,
                   runName + "'s end of stage " + inQuotes(from.stage) + " could not be kept for this run (" +
                       ec.message() + ")",
                   "start_from.run_id");
  }
  from.checkpoint = staged;
  return StagedSpecimen(staged);
}

void SpecimenSource::adopt(Scene& scene, StagedSpecimen& staged, std::int64_t id) const {
  const std::string path = startedFromPath(id);
  fs::create_directories(runFolder(id));
  fs::rename(staged.path(), path);  // throws; the staged link then goes with `staged`
  staged.release();
  scene.startFrom->checkpoint = path;
}

void SpecimenSource::pointAtOwnCopy(Scene& scene, std::int64_t id) const {
  if (scene.startFrom && scene.startFrom->runId != 0) scene.startFrom->checkpoint = startedFromPath(id);
}

std::vector<std::string> SpecimenSource::keptStages(const RunRecord& record) const {
  std::vector<std::string> kept;
  std::error_code ec;
  if (!fs::is_directory(runFolder(record.id), ec)) return kept;  // without parsing its scene
  if (record.origin && isFile(startedFromPath(record.id))) kept.push_back(record.origin->stage);
  for (const std::string& name : stageNames(record)) {
    if (std::find(kept.begin(), kept.end(), name) != kept.end()) continue;
    if (isFile(stageCheckpointPath(runFolder(record.id), name))) kept.push_back(name);
  }
  return kept;
}

std::string SpecimenSource::withoutPaths(const std::string& reason, const Scene& scene, const RunOrigin& origin) const {
  if (!scene.startFrom || scene.startFrom->checkpoint.empty()) return reason;
  const std::string& path = scene.startFrom->checkpoint;
  const std::string name = "run " + std::to_string(origin.runId) + "'s end of stage " + inQuotes(origin.stage);
  std::string out = reason;
  for (std::size_t at = out.find(path); at != std::string::npos; at = out.find(path, at + name.size()))
    out.replace(at, path.size(), name);
  return out;
}

void SpecimenSource::remove(std::int64_t id) const {
  std::error_code ec;
  fs::remove_all(runFolder(id), ec);
}

void SpecimenSource::removeStale() const {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir_, ec)) {
    if (entry.path().extension() == kStagedSuffix) fs::remove(entry.path(), ec);
  }
}

}  // namespace grainlab::server

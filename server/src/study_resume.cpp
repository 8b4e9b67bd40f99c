// POST /api/studies/{name}/resume: a cancelled or interrupted study's unfinished runs queued
// again, each from its checkpoint where it has one (a study's cancelled runs keep theirs for
// this), else from the start with what it had stored dropped. All of them or none: the queue
// must have room for every one.
#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/errors.hpp"
#include "grainlab/scene.hpp"
#include "api_types.hpp"
#include "repository.hpp"
#include "run_service.hpp"

namespace grainlab::server {

std::pair<int, std::string> RunService::resumeStudy(const std::string& name) {
  std::lock_guard lock(studyMutex_);
  const bool launched = !repo_.launchedStudies(name).empty();
  if (!launched && repo_.studies(name).empty()) throw ApiError(404, "no study '" + name + "'", "study");
  RunQuery query;
  query.study = name;
  query.statuses = {RunStatus::Cancelled, RunStatus::Interrupted};
  query.descending = false;  // in the order they were queued: the spec's
  std::vector<RunRecord> left;
  for (const RunRecord& run : repo_.listRuns(query).runs)
    if (!live(run.id)) left.push_back(run);
  if (left.empty())
    throw ApiError(409, "study '" + name + "' has no cancelled or interrupted run to resume", "study");
  const long room = std::max(0, manager_.maxConcurrent() - manager_.running()) +
                    std::max(0L, static_cast<long>(options_.maxQueuedRuns) - static_cast<long>(manager_.queued()));
  if (static_cast<long>(left.size()) > room)
    throw ApiError(429, "the run queue has room for " + std::to_string(room) + " runs, the study has " +
                            std::to_string(left.size()) + " to resume; try again when runs have finished",
                   "study");
  // Every scene parsed before any run is touched: a stored scene that no longer parses (this
  // server's limits changed) refuses the whole resume.
  std::vector<Scene> scenes;
  for (const RunRecord& run : left) {
    const auto stored = repo_.findRun(run.id);
    if (!stored) throw ApiError(409, "run " + std::to_string(run.id) + " was deleted meanwhile", "study");
    try {
      scenes.push_back(parseScene(nlohmann::json::parse(stored->scene)));
    } catch (const SceneError& e) {
      throw ApiError(400, "run " + std::to_string(run.id) + "'s scene: " + e.reason(), e.field());
    }
  }
  int resumed = 0;
  for (std::size_t k = 0; k < left.size(); ++k) {
    const RunRecord& run = left[k];
    const bool fromCheckpoint = hasCheckpoint(run.id);
    // Without a checkpoint the run starts again: what it stored before goes, so its series is
    // the one run from the start. With one, the run drops what it stored past it (onResume).
    if (!fromCheckpoint) repo_.truncateRun(run.id, 0, 0);
    repo_.requeueRun(run.id);
    repo_.flush().get();
    const auto submitted = enqueue(run.id, run.particles, std::move(scenes[k]), fromCheckpoint);
    if (submitted == RunManager::Submit::QueueFull || submitted == RunManager::Submit::ShuttingDown) {
      // Room was counted above, under the study lock; only runs posted meanwhile or a
      // stopping server take it. This run and the rest stay as they were: resumable later.
      RunEnd end;
      end.status = run.status;
      end.error = run.error;
      end.stage = fromCheckpoint ? run.stage : std::string();
      end.finishedAt = run.finishedAt.value_or(unixNow());
      end.steps = fromCheckpoint ? run.steps : 0;
      end.particles = run.particles;
      repo_.finishRun(run.id, end, nullptr);
      repo_.flush().get();
      if (submitted == RunManager::Submit::ShuttingDown) throw ApiError(503, "the server is shutting down");
      throw ApiError(429, "the run queue filled after " + std::to_string(resumed) + " of the study's " +
                              std::to_string(left.size()) + " runs were resumed; resume it again later",
                     "study");
    }
    ++resumed;
  }
  if (launched) repo_.setStudyStatus(name, "launched");
  repo_.flush().get();
  return {202, studyText(name)};
}

}  // namespace grainlab::server

// DELETE /api/studies/{name}: the study and everything of it: each run as DELETE
// /api/runs/{id} deletes one (its series, frames, checkpoint and kept stages; a live run is
// stopped first), then the study's row with its spec and findings.
#include <chrono>
#include <string>
#include <thread>

#include "api_types.hpp"
#include "repository.hpp"
#include "run_service.hpp"

namespace grainlab::server {

int RunService::deleteStudy(const std::string& name) {
  std::lock_guard lock(studyMutex_);
  const bool launched = !repo_.launchedStudies(name).empty();
  if (!launched && repo_.studies(name).empty()) throw ApiError(404, "no study '" + name + "'", "study");
  RunQuery query;
  query.study = name;
  query.descending = false;
  for (const RunRecord& run : repo_.listRuns(query).runs) {
    try {
      remove(run.id);
    } catch (const ApiError& e) {
      if (e.status() != 404) throw;  // deleted meanwhile
    }
  }
  if (launched) repo_.deleteStudy(name);
  repo_.flush().get();
  // A running run is deleted by its worker once it has stopped, at its next step: wait a
  // little for that, so that the answer can say the study is gone.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!repo_.studies(name).empty() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  return repo_.studies(name).empty() ? 204 : 202;
}

}  // namespace grainlab::server

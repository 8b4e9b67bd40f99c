#include "study_summary.hpp"

#include <algorithm>

#include "run_query.hpp"
#include "run_service.hpp"

namespace grainlab::server {

nlohmann::json studyJson(const StudyCounts& study) {
  std::int64_t total = 0, ended = 0;
  nlohmann::json byStatus = nlohmann::json::object();
  for (const auto& [status, count] : study.byStatus) {
    byStatus[status] = count;
    total += count;
    const auto parsed = parseRunStatus(status);
    if (!parsed || hasEnded(*parsed)) ended += count;
  }
  const auto has = [&](RunStatus s) { return study.byStatus.contains(std::string(toString(s))); };
  RunStatus status = RunStatus::Completed;
  // The first that applies: what is still going on, then the worst way a run ended.
  for (RunStatus s : {RunStatus::Running, RunStatus::Queued, RunStatus::Failed, RunStatus::Interrupted,
                      RunStatus::Cancelled}) {
    if (has(s)) {
      status = s;
      break;
    }
  }
  RunQuery runs;
  runs.study = study.study;
  runs.limit = 50;
  // "id": a study's id is its name (GET /api/studies/{id}).
  return {{"id", study.study},
          {"name", study.study},
          {"runs", total},
          {"by_status", std::move(byStatus)},
          {"status", toString(status)},
          {"progress", total ? double(ended) / double(total) : 0.0},
          {"runs_url", "/api/runs?" + runQueryString(runs, 0)},
          {"source", "imported"}};
}

void addTimeLeft(nlohmann::json& study, const StudyPace& pace, int slots) {
  if (pace.unfinished == 0) {
    study["seconds_left"] = 0.0;
    study["seconds_left_basis"] = "done";
    return;
  }
  if (pace.unestimated > 0) {
    study["seconds_left"] = nullptr;
    study["seconds_left_basis"] = "unknown";
    return;
  }
  const bool measured = pace.finished > 0 && pace.finishedEstimated > 0;
  const double factor = measured ? pace.finishedWall / pace.finishedEstimated : 1.0;
  const double parallel = static_cast<double>(std::min<std::int64_t>(std::max(1, slots), pace.unfinished));
  study["seconds_left"] = factor * pace.unfinishedEstimated / parallel;
  study["seconds_left_basis"] = measured ? "measured" : "estimate";
  study["pace"] = {{"wall_over_estimate", factor}, {"runs_measured", pace.finished}, {"parallel", parallel}};
}

bool underWay(const nlohmann::json& study) {
  const auto& by = study["by_status"];
  return by.contains(std::string(toString(RunStatus::Queued))) || by.contains(std::string(toString(RunStatus::Running)));
}

void addLaunch(nlohmann::json& study, const StudyRecord& launched, bool detail) {
  study["source"] = launched.source;
  study["created_at"] = isoTime(launched.createdAt);
  study["cancelled"] = launched.status == "cancelled";
  if (!detail) return;
  study["run_parameters"] = nlohmann::json::parse(launched.runs, nullptr, false);
}

std::string withSpec(const nlohmann::json& study, const StudyRecord& launched) {
  std::string text = study.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  text.pop_back();  // the object's closing brace
  // (stored as the ordered dump of a spec that parsed: valid JSON)
  return text + ",\"spec\":" + launched.spec + "}";
}

}  // namespace grainlab::server

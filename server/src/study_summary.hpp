#pragma once
// A study as GET /api/studies shows it: the runs it holds counted by status, one status for
// the whole (as runs have it) and its progress. Studies are, for now, the sweeps imported
// into the database: a run's `study` names the sweep it came from.
#include <nlohmann/json.hpp>

#include "repository.hpp"

namespace grainlab::server {

/// {"name", "runs", "by_status": {"completed": 11, ...}, "status", "progress", "runs_url"}.
/// status: running or queued while any run is; else failed, interrupted or cancelled if
/// any run ended so (in that order); else completed. progress: the share of runs ended.
nlohmann::json studyJson(const StudyCounts& study);

/// What a study launched here adds (POST /api/studies): "source": "launched" (else
/// "imported"), "created_at", "cancelled"; with `detail` its "run_parameters"
/// ([{"id", "name", "parameters": {path: value}}] in the spec's order).
void addLaunch(nlohmann::json& study, const StudyRecord& launched, bool detail);
/// The study's JSON text with the launched study's "spec" last, as it was posted: its "vary"
/// in the order given, which is the order of its runs (a parsed nlohmann::json would sort it).
std::string withSpec(const nlohmann::json& study, const StudyRecord& launched);

}  // namespace grainlab::server

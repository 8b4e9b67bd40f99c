#pragma once
// A study as GET /api/studies shows it: the runs it holds counted by status, one status for
// the whole (as runs have it) and its progress. Studies are, for now, the sweeps imported
// into the database: a run's `study` names the sweep it came from.
#include <nlohmann/json.hpp>

#include "repository.hpp"

namespace grainlab::server {

/// {"id" (= name), "name", "runs", "by_status": {"completed": 11, ...}, "status", "progress", "runs_url"}.
/// status: running or queued while any run is; else failed, interrupted or cancelled if
/// any run ended so (in that order); else completed. progress: the share of runs ended.
nlohmann::json studyJson(const StudyCounts& study);

/// The study's time left: "seconds_left", the wall time its queued and running runs still
/// need at the measured pace, and "seconds_left_basis" saying what it rests on. The work left
/// is the runs' estimated seconds (the part of a running run not yet done); the pace is the
/// wall time the study's completed runs took over their estimates (1 until one has
/// completed: "estimate"; then "measured"); `slots` runs go at once (grainlab serve
/// --max-concurrent). 0 with no run queued or running; null if a run left has no estimate.
void addTimeLeft(nlohmann::json& study, const StudyPace& pace, int slots);
/// Whether the study (studyJson) has a run queued or running: only then is its pace read.
bool underWay(const nlohmann::json& study);

/// What a study with a row adds (launched here, POST /api/studies, or an imported sweep's):
/// "source": "launched" or "imported" (also without a row: a sweep imported before schema 10),
/// "created_at", "cancelled"; with `detail` its "run_parameters"
/// ([{"id", "name", "parameters": {path: value}}] in the spec's order).
void addLaunch(nlohmann::json& study, const StudyRecord& launched, bool detail);
/// The study's JSON text with the launched study's "spec" last, as it was posted: its "vary"
/// in the order given, which is the order of its runs (a parsed nlohmann::json would sort it).
std::string withSpec(const nlohmann::json& study, const StudyRecord& launched);

}  // namespace grainlab::server

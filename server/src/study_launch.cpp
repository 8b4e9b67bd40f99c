// POST /api/studies and its cancel: a sweep spec, the JSON `grainlab sweep` reads (parsed and
// expanded by grainlab::studies, the same code), becomes a study of queued runs. Every run is
// admitted as POST /api/runs admits one before anything is stored, and the study and its runs
// are stored in one transaction: a study is launched whole or not at all.
#include <cctype>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/errors.hpp"
#include "grainlab/studies/scene_path.hpp"
#include "grainlab/studies/sweep_spec.hpp"
#include "api_types.hpp"
#include "repository.hpp"
#include "run_service.hpp"
#include "study_name.hpp"

namespace grainlab::server {
namespace {

// The field a run's refusal is reported on: the varied path it comes from ("vary.PATH", as
// `grainlab sweep` names it), else runs[K].FIELD.
std::string runField(const std::string& field, std::size_t k, const std::vector<studies::SweepAxis>& axes) {
  for (const studies::SweepAxis& axis : axes) {
    // (the scene parser writes stages[2].x, the cost estimate stages.2.x)
    for (const std::string& name : {studies::sceneFieldName(axis.path), axis.path}) {
      if (field == name || field.starts_with(name + ".") || field.starts_with(name + "[")) return "vary." + axis.path;
    }
  }
  return "runs[" + std::to_string(k) + "]" + (field.empty() ? "" : "." + field);
}

std::string describe(const studies::SweepRun& run) {
  std::string text;
  for (const auto& [path, value] : run.parameters) text += (text.empty() ? "" : ", ") + path + " = " + value.dump();
  return text;
}

}  // namespace

std::string RunService::launchStudy(const std::string& body) {
  const nlohmann::ordered_json spec = nlohmann::ordered_json::parse(body, nullptr, false);
  if (spec.is_discarded()) throw ApiError(400, "the body is not valid JSON", "(json)");
  if (!spec.is_object()) throw ApiError(400, "expected a sweep spec: {name, base, vary, mode}", "(json)");
  if (spec.contains("paper")) return launchPaperStudy(spec);  // study_paper.cpp
  if (spec.contains("tradeoff")) return launchTradeoffStudy(spec);  // study_tradeoff.cpp
  const std::string name = studyName(spec);
  if (spec.contains("prepare"))
    throw ApiError(400,
                   "a study launched on the server does not prepare specimens once per seed: run it with "
                   "grainlab sweep and import it (POST /api/sweeps/import)",
                   "prepare");
  studies::SweepSpec sweep;
  try {
    sweep = studies::parseSweepSpec(spec);
  } catch (const SceneError& e) {
    throw ApiError(400, e.reason(), e.field());
  }
  // Room for every run: the free run slots and the queue's free places. A study larger than
  // an idle server holds is a spec this server will never take (400, counted before any
  // scene is built); one that fits an idle server but not now may come back later (429, as
  // a run does).
  std::size_t count = sweep.mode == studies::SweepMode::Zip ? sweep.axes.front().values.size() : 1;
  if (sweep.mode == studies::SweepMode::Grid)
    for (const studies::SweepAxis& axis : sweep.axes) count *= axis.values.size();  // <= kMaxSweepRuns
  const std::size_t ceiling = static_cast<std::size_t>(manager_.maxConcurrent() + std::max(0, options_.maxQueuedRuns));
  if (count > ceiling)
    throw ApiError(400,
                   "the study has " + std::to_string(count) + " runs; this server holds at most " +
                       std::to_string(ceiling) + " at once (" + std::to_string(manager_.maxConcurrent()) +
                       " running, " + std::to_string(options_.maxQueuedRuns) +
                       " queued: grainlab serve --max-concurrent, --max-queued)",
                   "vary");
  std::vector<studies::SweepRun> runs;
  try {
    runs = studies::expandSweep(sweep);
  } catch (const SceneError& e) {
    throw ApiError(400, e.reason(), e.field());
  }

  const std::string preset = spec["base"].contains("preset") ? spec["base"]["preset"].get<std::string>() : "";
  std::vector<StudyRun> planned;
  planned.reserve(runs.size());
  for (studies::SweepRun& run : runs) {
    nlohmann::json parameters = nlohmann::json::object();
    for (const auto& [path, value] : run.parameters) parameters[path] = value;
    planned.push_back({std::move(run.scene), run.id, preset, std::move(parameters), describe(run)});
  }
  return storeStudy(name, spec, std::move(planned), "vary", [&](const std::string& field, std::size_t k) {
    return runField(field, k, sweep.axes);
  });
}

std::string RunService::storeStudy(const std::string& name, const nlohmann::ordered_json& spec, std::vector<StudyRun> runs,
                                   const std::string& roomField,
                                   const std::function<std::string(const std::string&, std::size_t)>& fieldOf) {
  std::lock_guard lock(studyMutex_);
  if (!repo_.launchedStudies(name).empty() || !repo_.studies(name).empty())
    throw ApiError(409, "a study named '" + name + "' exists already", "name");
  const long room = std::max(0, manager_.maxConcurrent() - manager_.running()) +
                    std::max(0L, static_cast<long>(options_.maxQueuedRuns) - static_cast<long>(manager_.queued()));
  if (static_cast<long>(runs.size()) > room)
    throw ApiError(429, "the run queue has room for " + std::to_string(room) + " runs, the study has " +
                            std::to_string(runs.size()) + "; try again when runs have finished",
                   roomField);

  std::vector<AdmittedRun> admitted;
  std::vector<RunRecord> records;
  nlohmann::json listed = nlohmann::json::array();
  admitted.reserve(runs.size());
  for (std::size_t k = 0; k < runs.size(); ++k) {
    nlohmann::json scene = std::move(runs[k].scene);
    scene["name"] = name + "/" + runs[k].id;
    try {
      admitted.push_back(admit(std::move(scene), runs[k].preset));
    } catch (const ApiError& e) {
      throw ApiError(e.status(), "run " + std::to_string(k + 1) + " (" + runs[k].description + "): " + e.what(),
                     fieldOf(e.field(), k));
    }
    admitted.back().record.study = name;
    records.push_back(admitted.back().record);
    listed.push_back({{"name", admitted.back().record.name}, {"parameters", std::move(runs[k].parameters)}});
  }

  StudyRecord launched;
  launched.name = name;
  launched.spec = spec.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  launched.runs = listed.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  launched.createdAt = unixNow();
  std::vector<std::int64_t> ids;
  try {
    ids = repo_.insertStudy(launched, records).get();
  } catch (const std::exception& e) {
    throw ApiError(503, "the study could not be stored (" + std::string(e.what()) + ")");
  }
  for (std::size_t k = 0; k < ids.size(); ++k) {
    try {
      startAdmitted(ids[k], admitted[k]);
    } catch (const ApiError&) {
      // Lost the queue's room to runs posted meanwhile (or the server is stopping): take the
      // whole study back, the runs already queued or started included.
      for (std::size_t j = 0; j < ids.size(); ++j) {
        try {
          if (j < k) remove(ids[j]);
          else repo_.deleteRun(ids[j]);
        } catch (const std::exception&) {
          // Gone already (deleted meanwhile): nothing of it to take back.
        }
      }
      repo_.deleteStudy(name);
      repo_.flush().get();
      throw;
    }
  }
  return name;
}

std::pair<int, std::string> RunService::cancelStudy(const std::string& name) {
  std::lock_guard lock(studyMutex_);
  const bool launched = !repo_.launchedStudies(name).empty();
  if (!launched && repo_.studies(name).empty()) throw ApiError(404, "no study '" + name + "'", "study");
  // The queued ones first, so that none of them starts in a slot a cancelled run frees.
  int ended = 0, stopping = 0;
  for (const RunStatus status : {RunStatus::Queued, RunStatus::Running}) {
    RunQuery query;
    query.study = name;
    query.statuses = {status};
    query.descending = false;
    for (const RunRecord& run : repo_.listRuns(query).runs) {
      try {
        (cancel(run.id).first == 202 ? stopping : ended) += 1;
      } catch (const ApiError& e) {
        if (e.status() != 409 && e.status() != 404) throw;  // it ended (or went) meanwhile
      }
    }
  }
  // An interrupted run is the study's unfinished work too: cancelled with it, so that no later
  // `--resume-interrupted` runs it on. What it stored is kept, and its checkpoint, for
  // POST /api/studies/{name}/resume (study_resume.cpp).
  RunQuery interrupted;
  interrupted.study = name;
  interrupted.statuses = {RunStatus::Interrupted};
  for (const RunRecord& run : repo_.listRuns(interrupted).runs) {
    if (live(run.id)) continue;  // resumed meanwhile: the passes above see it next time
    RunEnd end;
    end.status = RunStatus::Cancelled;
    end.error = "cancelled with its study while interrupted (" + run.error + ")";
    end.stage = run.stage;
    end.finishedAt = unixNow();
    end.wallSeconds = run.wallSeconds;
    end.cpuSeconds = run.cpuSeconds;
    end.steps = run.steps;
    end.particles = run.particles;
    end.peakPhiMobDeg = run.peakPhiMobDeg;
    end.warnings = run.warnings;
    repo_.finishRun(run.id, end, nullptr);
    ++ended;
  }
  if (ended + stopping == 0) throw ApiError(409, "study '" + name + "' has no queued, running or interrupted run", "study");
  if (launched) repo_.setStudyStatus(name, "cancelled");
  repo_.flush().get();
  return {stopping > 0 ? 202 : 200, studyText(name)};
}

}  // namespace grainlab::server

#include "run_service.hpp"
#include "study_summary.hpp"
#include "sweep_import.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <limits>
#include <numeric>

#include "grainlab/errors.hpp"
#include "grainlab/observer_tee.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/specimen.hpp"
#include "grainlab/studies/tradeoff/shearing_clock.hpp"
#include "grainlab/thread_cpu_clock.hpp"
#include "grainlab/validity.hpp"
#include "api_types.hpp"
#include "import_root.hpp"
#include "live_run.hpp"
#include "outgoing.hpp"
#include "repository.hpp"
#include "stream_hub.hpp"
#include "stream_observer.hpp"
#include "wall_time_limit.hpp"

namespace grainlab::server {
namespace {

nlohmann::json orNull(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json timeOrNull(const std::optional<double>& v) {
  return v ? nlohmann::json(isoTime(*v)) : nlohmann::json(nullptr);
}

std::string notFound(std::int64_t id) { return "no run " + std::to_string(id); }

// The value of `work`, or a 400 for the scene at fault: a SceneError names its field,
// anything else is reported against `otherField`.
template <class Work>
auto badSceneAs400(Work&& work, const char* otherField) {
  try {
    return work();
  } catch (const SceneError& e) {
    throw ApiError(400, e.reason(), e.field());
  } catch (const std::exception& e) {
    throw ApiError(400, e.what(), otherField);
  }
}

}  // namespace

double unixNow() {
  using namespace std::chrono;
  return duration<double>(system_clock::now().time_since_epoch()).count();
}

std::string isoTime(double unixSeconds) {
  const auto whole = static_cast<std::time_t>(std::floor(unixSeconds));
  const int millis = std::clamp(static_cast<int>((unixSeconds - std::floor(unixSeconds)) * 1000), 0, 999);
  std::tm tm{};
  gmtime_r(&whole, &tm);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900,
                tm.tm_mon + 1, tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, millis);
  return buffer;
}

int estimateParticles(const Scene& scene) {
  double count = static_cast<double>(scene.particles.size());
  // The generator's own plan (the scene parsed, so the recipe is valid).
  if (scene.assembly) count += plannedParticleCount(*scene.assembly);
  return static_cast<int>(std::min(count, 2e9));
}

RunService::RunService(Repository& repo, StreamHub& hub, const ServeOptions& options)
    : repo_(repo),
      hub_(hub),
      options_(options),
      run_(options.runFunction ? options.runFunction : RunFunction([](const RunRequest& r, RunObserver& o) {
        return r.resume ? grainlab::resumeRun(r.checkpoint.path, o, r.checkpoint, r.stageDirectory)
                        : grainlab::runScene(r.scene, o, {}, r.checkpoint, r.stageDirectory);
      })),
      checkpointDir_(options.checkpointDir.empty() ? options.db + ".checkpoints" : options.checkpointDir),
      specimens_(checkpointDir_),
      manager_(options.maxConcurrentRuns, static_cast<std::size_t>(std::max(0, options.maxQueuedRuns))),
      startedAt_(unixNow()) {
  requeueStored();
}

std::string RunService::checkpointPath(std::int64_t id) const {
  return (std::filesystem::path(checkpointDir_) / ("run-" + std::to_string(id) + ".bin")).string();
}

bool RunService::hasCheckpoint(std::int64_t id) const {
  const std::string path = checkpointPath(id);
  return std::filesystem::exists(path) || std::filesystem::exists(path + ".previous");
}

void RunService::removeCheckpoint(std::int64_t id) const {
  std::error_code ec;
  for (const char* suffix : {"", ".previous", ".tmp", ".refused"})
    std::filesystem::remove(checkpointPath(id) + suffix, ec);
}

void RunService::requeueStored() {
  std::error_code ec;
  std::filesystem::create_directories(checkpointDir_, ec);
  specimens_.removeStale();
  // Only the runs that may need it: queued or interrupted, oldest first (runs_by_status).
  RunQuery waiting;
  waiting.statuses = {RunStatus::Queued, RunStatus::Interrupted};
  waiting.descending = false;
  for (const RunRecord& listed : repo_.listRuns(waiting).runs) {
    if (listed.status == RunStatus::Interrupted && hasCheckpoint(listed.id)) {
      if (!options_.resumeInterrupted) {
        std::cerr << "grainlab serve: run " << listed.id << " (" << listed.name << ") was interrupted at step "
                  << listed.steps << "; resume it with POST /api/runs/" << listed.id
                  << "/resume, the dashboard, or grainlab serve --resume-interrupted\n";
        continue;
      }
      try {
        resume(listed.id);
        std::cerr << "grainlab serve: resuming run " << listed.id << " (" << listed.name << ")\n";
      } catch (const std::exception& e) {
        std::cerr << "grainlab serve: cannot resume run " << listed.id << ": " << e.what() << "\n";
      }
      continue;
    }
    if (listed.status != RunStatus::Queued) continue;
    RunEnd end;
    end.status = RunStatus::Interrupted;
    end.finishedAt = unixNow();
    try {
      const auto record = repo_.findRun(listed.id);  // the list leaves the scenes out
      Scene scene = parseScene(nlohmann::json::parse(record->scene));
      specimens_.pointAtOwnCopy(scene, listed.id);
      const auto submitted = enqueue(listed.id, listed.particles, std::move(scene), hasCheckpoint(listed.id));
      if (submitted == RunManager::Submit::Started || submitted == RunManager::Submit::Queued) continue;
      end.error = "the run queue was full when the server restarted";
    } catch (const std::exception& e) {
      end.error = std::string("its stored scene could not be queued again: ") + e.what();
    }
    repo_.finishRun(listed.id, end, nullptr);
  }
  // A trade-off study whose references all ended before the server stopped, its other
  // settings not yet queued, queues them now (study_tradeoff.cpp).
  for (const StudyRecord& study : repo_.launchedStudies()) {
    try {
      continueTradeoffStudy(study.name);
    } catch (const std::exception& e) {
      std::cerr << "grainlab serve: study " << study.name << ": " << e.what() << "\n";
    }
  }
}

RunManager::Submit RunService::enqueue(std::int64_t id, int particles, Scene scene, bool resume) {
  auto run = std::make_shared<LiveRun>(id);
  run->update([&](LiveRun::State& s) { s.particles = particles; });
  {
    std::lock_guard lock(liveMutex_);
    live_[id] = run;
  }
  hub_.open(id);
  hub_.publish(id, makeOutgoing(statusMessage(id, RunStatus::Queued, 0, {}, 0, {}), MessageKind::Status));
  const auto submitted = manager_.submit(id, [this, run, resume, scene = std::move(scene)] { execute(run, scene, resume); });
  if (submitted == RunManager::Submit::QueueFull || submitted == RunManager::Submit::ShuttingDown) {
    forget(id);
    hub_.close(id);
  }
  return submitted;
}

RunService::~RunService() { shutdown(); }

std::int64_t RunService::create(const std::string& body) {
  nlohmann::json request = nlohmann::json::parse(body, nullptr, false);
  if (request.is_discarded())
    throw ApiError(400, "the body is not valid JSON", "(json)");
  if (!request.is_object())
    throw ApiError(400, "expected a scene object or {\"preset\": NAME}", "(json)");

  std::string preset;
  nlohmann::json sceneJson;
  if (request.contains("preset")) {
    if (request.size() != 1)
      throw ApiError(400, "a preset request has the one key \"preset\"; send a whole scene to change it",
                     "preset");
    if (!request["preset"].is_string()) throw ApiError(400, "must be a preset name (a string)", "preset");
    preset = request["preset"].get<std::string>();
    try {
      sceneJson = presetScene(preset);
    } catch (const SceneError& e) {
      throw ApiError(400, e.reason(), e.field());
    }
  } else {
    sceneJson = std::move(request);
  }
  AdmittedRun run = admit(std::move(sceneJson), std::move(preset));
  if (static_cast<int>(manager_.queued()) >= options_.maxQueuedRuns &&
      manager_.running() >= manager_.maxConcurrent())
    throw ApiError(429, "the run queue is full (" + std::to_string(options_.maxQueuedRuns) +
                            " waiting); try again when a run has finished");
  std::int64_t id = 0;
  try {
    id = repo_.insertRun(run.record).get();
  } catch (const std::exception&) {
    throw ApiError(503, "the run could not be stored (" + repo_.lastWriteError() + ")");
  }
  try {
    startAdmitted(id, run);
  } catch (const ApiError&) {
    repo_.deleteRun(id).get();  // take it back whole
    throw;
  }
  return id;
}

RunService::AdmittedRun RunService::admit(nlohmann::json sceneJson, std::string preset) {
  RunRecord record;
  record.preset = std::move(preset);
  // The parser promises SceneError; anything else still means the scene is bad.
  Scene scene = badSceneAs400([&] { return parseScene(sceneJson); }, "(json)");
  // A stored run's stage, linked here for this run; never a file the request names.
  std::optional<StagedSpecimen> specimen;
  if (scene.startFrom) {
    RunOrigin origin;
    specimen.emplace(specimens_.stage(scene, storedRun(scene.startFrom->runId), origin));
    record.origin = origin;
  }

  const int particles = estimateParticles(scene);
  if (particles > options_.maxParticles)
    throw ApiError(503,
                   "this server runs at most " + std::to_string(options_.maxParticles) +
                       " particles per run; the scene has about " + std::to_string(particles),
                   "particles");
  // A scene whose cost is absurd (a stiffness of 1e30 N/m steps at 1e-17 s) would hold a run
  // slot at 0 % for ever: refuse it now, naming the field that drives the cost.
  // Building the world can also refuse the scene (particles overlapping by half at the start).
  // Past the validity envelope's hard limits the results would mean nothing: refused by field.
  // A prepared specimen is checked here: missing, unreadable, or one the scene does not fit.
  const ValidityAssessment validity = badSceneAs400(
      [&] {
        try {
          return assessSceneValidity(scene, std::numeric_limits<double>::infinity());
        } catch (const SceneError& e) {
          if (!record.origin) throw;
          throw SceneError(e.field(), specimens_.withoutPaths(e.reason(), scene, *record.origin));
        }
      },
      "(scene)");
  if (!validity.refusals.empty()) throw ApiError(400, validity.refusalMessage(), validity.refusals.front().field);
  const RunCost& cost = validity.cost;
  if (cost.certainSeconds() > options_.maxRunSeconds)
    throw ApiError(400,
                   "the run would take about " + humanDuration(cost.certainSeconds()) + " (" + cost.describe() +
                       "), more than this server's limit of " + humanDuration(options_.maxRunSeconds) +
                       " (grainlab serve --max-run-seconds)",
                   cost.field);

  record.name = scene.name;
  record.scene = sceneJson.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  record.status = RunStatus::Queued;
  record.particles = particles;
  record.estimatedSeconds = cost.certainSeconds();
  record.warnings = warningsJson(validity.warnings).dump();
  record.createdAt = unixNow();
  return AdmittedRun{std::move(record), std::move(scene), std::move(specimen)};
}

void RunService::startAdmitted(std::int64_t id, AdmittedRun& run) {
  removeCheckpoint(id);  // ids are never reused; this is for a database replaced under old files
  specimens_.remove(id);
  if (run.specimen) {
    try {
      specimens_.adopt(run.scene, *run.specimen, id);
    } catch (const std::exception& e) {
      throw ApiError(503, std::string("the specimen could not be kept for the run (") + e.what() + ")");
    }
  }
  if (const auto submitted = enqueue(id, run.record.particles, std::move(run.scene));
      submitted == RunManager::Submit::QueueFull || submitted == RunManager::Submit::ShuttingDown) {
    // Lost a race for the last queue slot (or the server is stopping).
    if (submitted == RunManager::Submit::ShuttingDown) throw ApiError(503, "the server is shutting down");
    throw ApiError(429, "the run queue is full; try again when a run has finished");
  }
}

nlohmann::json RunService::resume(std::int64_t id) {
  const RunRecord record = require(id);
  const std::string what = "run " + std::to_string(id) + " (" + std::string(toString(record.status)) + ")";
  if (live(id)) throw ApiError(409, what + " is not stopped");
  if (record.status == RunStatus::Completed || record.status == RunStatus::Cancelled || !hasCheckpoint(id))
    throw ApiError(409, what + " has no checkpoint to resume from");
  Scene scene = badSceneAs400([&] { return parseScene(nlohmann::json::parse(record.scene)); }, "(scene)");
  // Committed before the run is live: the database's "interrupted" would otherwise outrank
  // the live state in what GET answers (an ended state in the database wins).
  repo_.requeueRun(id);
  repo_.flush().get();
  const auto submitted = enqueue(id, record.particles, std::move(scene), true);
  if (submitted == RunManager::Submit::ShuttingDown) throw ApiError(503, "the server is shutting down");
  if (submitted == RunManager::Submit::QueueFull) {
    RunEnd end;  // as it was: still resumable later
    end.status = record.status;
    end.error = record.error;
    end.stage = record.stage;
    end.finishedAt = record.finishedAt.value_or(unixNow());
    end.steps = record.steps;
    end.particles = record.particles;
    repo_.finishRun(id, end, nullptr);
    throw ApiError(429, "the run queue is full; try again when a run has finished");
  }
  return get(id);
}

void RunService::execute(const std::shared_ptr<LiveRun>& run, const Scene& scene, bool resume) {
  const std::int64_t id = run->id();
  const double startedAt = unixNow();
  run->update([&](LiveRun::State& s) {
    s.status = RunStatus::Running;
    s.startedAt = startedAt;
  });
  repo_.markStarted(id, startedAt);
  hub_.publish(id, makeOutgoing(statusMessage(id, RunStatus::Running, 0, {}, 0, {}), MessageKind::Status));

  StreamObserver::Settings settings;
  settings.framesPerSecond = options_.framesPerSecond;
  settings.replayFrameEvery = options_.replayFrameEvery;
  StreamObserver observer(*run, repo_, hub_, format_, settings);

  RunSummary summary;
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = threadCpuSeconds();
  std::optional<double> preparationCpu;
  std::string study;  // the study the run belongs to, if any
  if (run->stopRequested()) {
    summary.status = RunStatus::Cancelled;  // stopped between leaving the queue and starting
  } else {
    try {
      WallTimeLimit limit(options_.maxRunSeconds);
      DatabaseWatch database(repo_);
      tradeoff::ShearingClock shearingClock(tradeoff::shearingStageName(scene));
      ObserverTee watched{&observer, &limit, &database, &shearingClock};
      const auto stored = repo_.findRun(id);  // the scene as submitted goes into the checkpoint
      if (stored) study = stored->study;
      const CheckpointPolicy checkpoint{checkpointPath(id), scene.output.checkpointEverySeconds,
                                        stored ? stored->scene : std::string()};
      summary = run_(RunRequest{scene, checkpoint, resume, specimens_.runFolder(id)}, watched);
      // A resumed run's clock started at its checkpoint: its preparation's cost is not known.
      if (!resume && std::isfinite(shearingClock.reached())) preparationCpu = shearingClock.reached() - cpu0;
      if (stored && stored->origin) summary.error = specimens_.withoutPaths(summary.error, scene, *stored->origin);
      if (summary.status == RunStatus::Interrupted && limit.exceeded() && !run->stopRequested()) {
        summary.status = RunStatus::Failed;
        summary.error = "stopped after " + humanDuration(limit.seconds()) +
                        ", the server's wall-time limit for a run (grainlab serve --max-run-seconds)";
      }
      if (summary.status == RunStatus::Cancelled && database.failed() && !run->stopRequested()) {
        summary.status = RunStatus::Failed;
        summary.error = "stopped: the database could not be written (" + repo_.lastWriteError() +
                        "); what the run stored before is kept";
      }
    } catch (const std::exception& e) {
      summary.status = RunStatus::Failed;
      summary.error = e.what();
    } catch (...) {
      summary.status = RunStatus::Failed;
      summary.error = "the simulation stopped with an unknown error";
    }
  }
  // The server's own clock around the whole run, observers included: what streaming costs
  // shows up here.
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = threadCpuSeconds() - cpu0;

  RunEnd end;
  end.status = summary.status;
  if (!hasEnded(end.status)) {
    end.error = "the engine reported status '" + std::string(toString(end.status)) + "'";
    end.status = RunStatus::Failed;
  }
  if (!summary.error.empty()) end.error = summary.error;
  if (end.status == RunStatus::Failed && end.error.empty()) end.error = "the simulation failed";
  if (end.status == RunStatus::Interrupted && end.error.empty()) {
    end.error = hasCheckpoint(id) ? "the server stopped before the run ended; it can be resumed"
                                  : "the server stopped before the run ended (no checkpoint: it cannot be resumed)";
  }
  // Cancelled means not wanted, unless the run is a study's: the study may be resumed
  // (POST /api/studies/{name}/resume), from here. Deleting the run drops it.
  if (end.status == RunStatus::Cancelled) {
    const auto stored = repo_.findRun(id);
    if (!stored || stored->study.empty()) removeCheckpoint(id);
  }
  const auto state = run->state();
  end.stage = state.stage;
  end.finishedAt = unixNow();
  end.wallSeconds = wall;
  end.cpuSeconds = cpu;
  end.preparationCpuSeconds = preparationCpu;
  end.steps = summary.steps > 0 ? summary.steps : state.steps;
  end.particles = summary.particles > 0 ? summary.particles : state.particles;
  if (end.status == RunStatus::Completed || summary.peakPhiMobDeg != 0) end.peakPhiMobDeg = summary.peakPhiMobDeg;
  end.warnings = warningsJson(summary.warnings).dump();

  if (run->deleted()) {
    // Queued after the run's last writes, so nothing of it is left behind. The live entry
    // (marked deleted, so the API hides the run) stays until the rows are gone.
    removeCheckpoint(id);
    specimens_.remove(id);
    hub_.close(id);
    repo_.deleteRun(id, [this, id] { forget(id); });
    return;
  }
  // Queued before the end, so whoever sees the run ended finds it stored.
  repo_.setVoidRatio(id, summary.voidRatioAfterConsolidation);
  repo_.finishRun(id, end, [this, run, end] { published(run, end); });
  // A trade-off study queues its other settings once its references have ended (and one
  // waiting for room tries again as any run ends).
  continueTradeoffStudies(study);
}

void RunService::published(const std::shared_ptr<LiveRun>& run, const RunEnd& end) {
  // Runs once the end is durable (whoever sees "completed" finds the whole series stored),
  // or once the database has refused it (a full disk).
  run->update([&](LiveRun::State& s) {
    s.status = end.status;
    s.error = end.error;
    if (end.status == RunStatus::Completed) s.progress = 1;
  });
  const auto s = run->state();
  hub_.publish(run->id(), makeOutgoing(statusMessage(run->id(), end.status, s.progress, end.stage,
                                                     end.steps, end.error),
                                       MessageKind::Status));
  hub_.close(run->id());
  // An end the database could not take (a full disk) is kept live, so the API still tells
  // it, until a restart finds the run unfinished and marks it interrupted.
  const auto stored = repo_.findRun(run->id());
  const bool ended = stored && hasEnded(stored->status);
  bool deleted;
  {
    std::lock_guard lock(liveMutex_);
    deleted = run->deleted();
    if (ended && !deleted) live_.erase(run->id());
  }
  // DELETE arrived while the end was being written: the live entry hides the run until its
  // rows are gone (erased before that, the stored rows would show for a moment).
  if (deleted) repo_.deleteRun(run->id(), [this, id = run->id()] { forget(id); });
}

std::shared_ptr<LiveRun> RunService::live(std::int64_t id) {
  std::lock_guard lock(liveMutex_);
  auto it = live_.find(id);
  return it == live_.end() ? nullptr : it->second;
}

void RunService::forget(std::int64_t id) {
  std::lock_guard lock(liveMutex_);
  live_.erase(id);
}

nlohmann::json RunService::runJson(const RunRecord& r, bool withScene) {
  RunRecord merged = r;
  bool cancelRequested = false;
  if (auto run = live(r.id)) {
    const auto s = run->state();
    // The database lags the live state by up to a second; a terminal state in the database
    // (the commit already happened) wins.
    if (!hasEnded(merged.status)) {
      merged.status = s.status;
      merged.progress = s.progress;
      merged.stage = s.stage;
      merged.steps = s.steps;
      merged.particles = s.particles;
      if (s.startedAt) merged.startedAt = s.startedAt;
      if (!s.error.empty()) merged.error = s.error;
    }
    cancelRequested = run->stopRequested();
  }
  nlohmann::json j = {
      {"id", merged.id},
      {"name", merged.name},
      {"preset", merged.preset.empty() ? nlohmann::json(nullptr) : nlohmann::json(merged.preset)},
      {"status", toString(merged.status)},
      {"progress", merged.progress},
      {"stage", merged.stage},
      {"particles", merged.particles},
      {"steps", merged.steps},
      {"created_at", isoTime(merged.createdAt)},
      {"started_at", timeOrNull(merged.startedAt)},
      {"finished_at", timeOrNull(merged.finishedAt)},
      {"queue_seconds", merged.startedAt ? nlohmann::json(*merged.startedAt - merged.createdAt)
                                         : nlohmann::json(nullptr)},
      {"wall_seconds", orNull(merged.wallSeconds)},
      {"cpu_seconds", orNull(merged.cpuSeconds)},
      {"preparation_cpu_seconds", orNull(merged.preparationCpuSeconds)},
      {"estimated_seconds", orNull(merged.estimatedSeconds)},
      {"peak_phi_mob_deg", orNull(merged.peakPhiMobDeg)},
      {"error", merged.error.empty() ? nlohmann::json(nullptr) : nlohmann::json(merged.error)},
  };
  const nlohmann::json warnings = nlohmann::json::parse(merged.warnings, nullptr, false);
  j["warnings"] = warnings.is_array() ? warnings : nlohmann::json::array();
  if (cancelRequested) j["cancel_requested"] = true;
  j["resumable"] = !live(r.id) && merged.status != RunStatus::Completed && merged.status != RunStatus::Cancelled &&
                   hasCheckpoint(r.id);
  j["origin"] = merged.producedBy;
  j["study"] = merged.study.empty() ? nlohmann::json(nullptr) : nlohmann::json(merged.study);
  j["started_from"] = merged.origin ? nlohmann::json{{"run_id", merged.origin->runId}, {"stage", merged.origin->stage}}
                                    : nlohmann::json(nullptr);
  if (withScene) {
    j["specimen_stages"] = specimens_.keptStages(merged);
    auto scene = nlohmann::json::parse(merged.scene, nullptr, false);
    j["scene"] = scene.is_discarded() ? nlohmann::json(nullptr) : scene;
  }
  return j;
}

std::optional<RunRecord> RunService::storedRun(std::int64_t id) {
  auto run = live(id);
  if (run && run->deleted()) return std::nullopt;
  auto record = repo_.findRun(id);
  if (record && run && !hasEnded(record->status)) {
    const auto s = run->state();  // the database lags the live state
    record->status = s.status;
    record->stage = s.stage;
  }
  return record;
}

RunRecord RunService::require(std::int64_t id) {
  auto run = live(id);
  if (run && run->deleted()) throw ApiError(404, notFound(id));
  auto record = repo_.findRun(id);
  if (!record) throw ApiError(404, notFound(id));
  return *record;
}

bool RunService::exists(std::int64_t id) {
  try {
    require(id);
    return true;
  } catch (const ApiError&) {
    return false;
  }
}

nlohmann::json RunService::list(const RunQuery& query) {
  nlohmann::json runs = nlohmann::json::array();
  const RunPage page = repo_.listRuns(query);
  for (const RunRecord& record : page.runs) {
    auto run = live(record.id);
    if (run && run->deleted()) continue;  // on its way out: its rows go in the next write
    runs.push_back(runJson(record, false));
  }
  const std::int64_t end = query.offset + (query.limit ? *query.limit : page.total);
  return {{"runs", std::move(runs)},
          {"total", page.total},
          {"offset", query.offset},
          {"limit", query.limit ? nlohmann::json(*query.limit) : nlohmann::json(nullptr)},
          {"next", query.limit && end < page.total ? nlohmann::json("/api/runs?" + runQueryString(query, end))
                                                   : nlohmann::json(nullptr)}};
}

nlohmann::json RunService::studies() {
  // Imported sweeps have runs only; a launched study is listed even once its runs are deleted.
  std::map<std::string, nlohmann::json> byName;
  for (const StudyCounts& study : repo_.studies()) {
    byName[study.study] = studyJson(study);
    addTimeLeft(byName[study.study], underWay(byName[study.study]) ? repo_.studyPace(study.study) : StudyPace{},
                manager_.maxConcurrent());
  }
  for (const StudyRecord& launched : repo_.launchedStudies()) {
    auto& study = byName[launched.name];
    if (study.is_null()) {
      study = studyJson(StudyCounts{launched.name, {}});
      addTimeLeft(study, StudyPace{}, manager_.maxConcurrent());
    }
    addLaunch(study, launched, false);
  }
  nlohmann::json out = nlohmann::json::array();
  for (auto& [name, study] : byName) out.push_back(std::move(study));
  return {{"studies", std::move(out)}};
}

nlohmann::json RunService::study(const std::string& name) {
  const auto counts = repo_.studies(name);
  const auto launched = repo_.launchedStudies(name);
  if (counts.empty() && launched.empty()) throw ApiError(404, "no study '" + name + "'", "study");
  nlohmann::json study = studyJson(counts.empty() ? StudyCounts{name, {}} : counts.front());
  addTimeLeft(study, underWay(study) ? repo_.studyPace(name) : StudyPace{}, manager_.maxConcurrent());
  if (!launched.empty()) addLaunch(study, launched.front(), true);
  return study;
}

std::string RunService::studyText(const std::string& name) {
  const nlohmann::json summary = study(name);
  const auto launched = repo_.launchedStudies(name);
  return launched.empty() ? summary.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)
                          : withSpec(summary, launched.front());
}

nlohmann::json RunService::get(std::int64_t id) { return runJson(require(id), true); }

nlohmann::json RunService::series(std::int64_t id) {
  require(id);
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& s : repo_.samples(id)) rows.push_back(format_.rowArray(s));
  return {{"id", id}, {"columns", format_.columns()}, {"rows", std::move(rows)}};
}

std::string RunService::seriesCsv(std::int64_t id) {
  require(id);
  std::string csv = format_.csvHeader();
  for (const auto& s : repo_.samples(id)) csv += format_.csvRow(s);
  return csv;
}

std::string RunService::histograms(std::int64_t id, bool latestOnly) {
  require(id);
  // The stored messages are JSON already: splice them rather than parse and re-dump.
  std::string out = "{\"id\":" + std::to_string(id) + ",\"histograms\":[";
  bool first = true;
  for (const auto& h : repo_.histograms(id, latestOnly)) {
    if (!first) out += ',';
    out += h;
    first = false;
  }
  out += "]}";
  return out;
}

nlohmann::json RunService::frameIndex(std::int64_t id) {
  require(id);
  nlohmann::json frames = nlohmann::json::array();
  for (const auto& f : repo_.frames(id))
    frames.push_back({{"index", f.seq}, {"step", f.step}, {"time", f.time}, {"bytes", f.bytes}});
  return {{"id", id}, {"frames", std::move(frames)}};
}

std::string RunService::frame(std::int64_t id, std::int64_t index, std::int64_t step) {
  require(id);
  auto bytes = repo_.frame(id, index, step);
  if (!bytes)
    throw ApiError(404, index >= 0 ? "run " + std::to_string(id) + " has no frame " + std::to_string(index)
                                   : "run " + std::to_string(id) + " has no frame at or before step " +
                                         std::to_string(step));
  return *bytes;
}

std::string RunService::shapes(std::int64_t id) {
  require(id);
  auto shapes = repo_.shapes(id);
  if (!shapes) throw ApiError(404, "run " + std::to_string(id) + " has not built its particles yet");
  return *shapes;
}

std::pair<int, nlohmann::json> RunService::cancel(std::int64_t id) {
  auto record = require(id);
  auto run = live(id);
  if (!run) throw ApiError(409, "run " + std::to_string(id) + " has already ended (" + std::string(toString(record.status)) + ")");
  if (manager_.removeQueued(id)) {
    run->requestStop(StopReason::Cancel);
    RunEnd end;
    end.status = RunStatus::Cancelled;
    end.finishedAt = unixNow();
    repo_.finishRun(id, end, [this, run, end] { published(run, end); });
    repo_.flush().get();
    return {200, get(id)};
  }
  run->requestStop(StopReason::Cancel);
  return {202, get(id)};
}

void RunService::remove(std::int64_t id) {
  require(id);
  std::shared_ptr<LiveRun> run;
  {
    std::lock_guard lock(liveMutex_);
    if (auto it = live_.find(id); it != live_.end()) {
      run = it->second;
      run->markDeleted();
    }
  }
  if (run && !manager_.removeQueued(id)) return;  // running: whoever ends it deletes it
  if (run) {
    hub_.close(id);
    forget(id);
  }
  removeCheckpoint(id);
  specimens_.remove(id);
  repo_.deleteRun(id).get();
}

bool RunService::watch(std::int64_t id, const std::shared_ptr<StreamSink>& sink) {
  if (!exists(id)) return false;
  if (hub_.subscribe(id, sink)) return true;
  // Ended: the hub closes a channel only after the end is committed, so the database has it all.
  auto record = repo_.findRun(id);
  if (!record) return false;
  if (auto shapes = repo_.shapes(id)) sink->deliver(makeOutgoing(*shapes, MessageKind::Shapes));
  sink->deliver(makeOutgoing(statusMessage(id, record->status, record->progress, record->stage,
                                           record->steps, record->error),
                             MessageKind::Status));
  std::int64_t seq = 0;
  for (const auto& s : repo_.samples(id)) {
    nlohmann::json m = {{"type", "sample"}, {"seq", s.seq}, {"row", format_.rowObject(s)}};
    sink->deliver(makeOutgoing(m.dump(), MessageKind::Sample));
    ++seq;
  }
  auto latest = repo_.histograms(id, true);
  if (!latest.empty()) sink->deliver(makeOutgoing(latest.front(), MessageKind::Histogram));
  if (auto frame = repo_.lastFrame(id)) sink->deliver(makeOutgoing(*frame, MessageKind::Frame));
  sink->finish();
  return true;
}

nlohmann::json RunService::health() {
  return {{"status", "ok"},
          {"version", "0.1.0"},
          {"schema_version", Repository::schemaVersion()},
          {"uptime_seconds", unixNow() - startedAt_},
          {"runs",
           {{"running", manager_.running()},
            {"queued", manager_.queued()},
            {"max_concurrent", manager_.maxConcurrent()},
            {"max_queued", options_.maxQueuedRuns}}},
          {"watchers", hub_.subscribers()},
          {"limits", {{"max_particles", options_.maxParticles}, {"max_body_bytes", options_.maxBodyBytes},
                      {"max_run_seconds", options_.maxRunSeconds}}}};
}

void RunService::shutdown() {
  {
    std::lock_guard lock(liveMutex_);
    if (stopped_) return;
    stopped_ = true;
    for (auto& [id, run] : live_) run->requestStop(StopReason::Shutdown);
  }
  for (const auto id : manager_.shutdown()) {
    // Never started: it stays queued in the database, and the next server queues it again.
    forget(id);
    hub_.close(id);
  }
  // Every finish callback refers to this object: let them all run before it goes.
  repo_.flush().get();
}

}  // namespace grainlab::server

namespace grainlab::server {

nlohmann::json RunService::importSweep(const std::string& body) {
  nlohmann::json request;
  try {
    request = nlohmann::json::parse(body);
  } catch (const nlohmann::json::exception& e) {
    throw ApiError(400, std::string("not valid JSON: ") + e.what(), "(json)");
  }
  if (!request.is_object() || !request.contains("dir") || !request["dir"].is_string())
    throw ApiError(400, "give the sweep folder's path on the server's machine as a string", "dir");
  // Off unless a root was given; outside it, one answer for every path, existing or not.
  if (options_.importRoot.empty())
    throw ApiError(404, "importing sweeps is off on this server (start it with --import-root DIR)", "dir");
  const auto dir = underImportRoot(options_.importRoot, request["dir"].get<std::string>());
  if (!dir) throw ApiError(403, "dir must be a folder under this server's import root", "dir");
  try {
    const SweepImport outcome = server::importSweep(repo_, *dir);
    return {{"imported", outcome.ids.size()}, {"ids", outcome.ids}, {"already_there", outcome.alreadyThere},
            {"not_finished", outcome.notFinished}};
  } catch (const std::invalid_argument& e) {
    throw ApiError(400, e.what(), "dir");
  }
}

}  // namespace grainlab::server

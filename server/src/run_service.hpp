#pragma once
// The service layer between the routes and the storage: creates runs from scene JSON, runs
// them through the RunManager with a StreamObserver each, answers questions about them by
// merging the database with the live state, and attaches stream watchers. Refusals are thrown
// as ApiError with the HTTP status they deserve.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "grainlab/server/serve.hpp"
#include "run_manager.hpp"
#include "run_query.hpp"
#include "run_record.hpp"
#include "series_format.hpp"
#include "specimen_source.hpp"

namespace grainlab::server {

class LiveRun;
class Repository;
class StreamHub;
class StreamSink;
struct RunEnd;

class RunService {
 public:
  RunService(Repository& repo, StreamHub& hub, const ServeOptions& options);
  /// Calls shutdown().
  ~RunService();
  RunService(const RunService&) = delete;
  RunService& operator=(const RunService&) = delete;

  /// A scene object or {"preset": NAME}; returns the new run's id. 400 for a bad scene (nothing
  /// stored), 503 past the particle limit, 429 when the queue is full. A scene may start from a
  /// stored run's stage (start_from.run_id, SpecimenSource), never from a file it names.
  std::int64_t create(const std::string& body);
  /// {"runs": [...], "total", "offset", "limit", "next"}: the runs the query asks for,
  /// without their scenes; `next` the path of the page after this one, or null.
  nlohmann::json list(const RunQuery& query = {});
  /// {"studies": [study, ...]} by name (study_summary.hpp); study(name) one of them, 404 if
  /// no run belongs to it.
  nlohmann::json studies();
  nlohmann::json study(const std::string& name);
  /// The body of GET /api/studies/{name}: study(name) with a launched study's "spec" as posted.
  std::string studyText(const std::string& name);
  /// POST /api/studies (study_launch.cpp): a sweep spec, the JSON of `grainlab sweep`, becomes a
  /// study of queued runs. Every run is admitted as create() admits one before anything is
  /// stored: refused whole with 400 naming the spec's field or runs[K].FIELD, 429 when the
  /// queue has no room for all of it now, 503 past the particle limit; 409 for a name in use.
  /// Returns the new study's name.
  std::string launchStudy(const std::string& body);
  /// POST /api/studies/{name}/cancel: cancels its queued and running runs as cancel() does,
  /// and its interrupted ones (their checkpoints dropped). 200 when every one of them ended
  /// at once, 202 when a running one was asked to stop; 404 unknown, 409 when none was left.
  /// Returns the status and the study's body (studyText).
  std::pair<int, std::string> cancelStudy(const std::string& name);
  /// 404 for an unknown id.
  nlohmann::json get(std::int64_t id);
  nlohmann::json series(std::int64_t id);
  std::string seriesCsv(std::int64_t id);
  /// Stored histogram messages ({"id", "histograms": [...]}), or only the latest.
  std::string histograms(std::int64_t id, bool latestOnly);
  nlohmann::json frameIndex(std::int64_t id);
  /// A stored frame by its index, or (index < 0) the last one at or before `step`.
  std::string frame(std::int64_t id, std::int64_t index, std::int64_t step);
  std::string shapes(std::int64_t id);
  /// Returns the status code (200 cancelled now, 202 stop requested) and the run.
  std::pair<int, nlohmann::json> cancel(std::int64_t id);
  /// Continues an interrupted run (or one stopped at the wall-time limit) from its checkpoint:
  /// it is queued again and, once it runs, appends to its series as if it had never stopped.
  /// 404 unknown, 409 if it is queued or running or has no checkpoint, 429 queue full.
  nlohmann::json resume(std::int64_t id);
  /// Deletes a run with everything stored for it; a live run is stopped first.
  void remove(std::int64_t id);
  bool exists(std::int64_t id);
  /// Streams the run to the sink: live if it is queued or running, else what is stored
  /// followed by finish(). False for an unknown id.
  bool watch(std::int64_t id, const std::shared_ptr<StreamSink>& sink);
  nlohmann::json health();
  /// {"dir": PATH}: a `grainlab sweep` folder on this machine into the database (400 if it is
  /// not one); returns {"imported", "ids", "already_there", "not_finished"}.
  nlohmann::json importSweep(const std::string& body);
  /// Stops every run (they end `interrupted`), waits for the workers and the database.
  void shutdown();

 private:
  /// A run that passed admission: parsed, its specimen staged, within the particle and cost
  /// limits; ready to be stored and queued.
  struct AdmittedRun {
    RunRecord record;
    Scene scene;
    std::optional<StagedSpecimen> specimen;
  };
  /// Every check POST /api/runs makes of a scene but the queue's room; throws ApiError.
  AdmittedRun admit(nlohmann::json sceneJson, std::string preset);
  /// A stored admitted run: its specimen kept, queued. Throws ApiError (503, 429) having
  /// taken nothing back; the caller deletes the run.
  void startAdmitted(std::int64_t id, AdmittedRun& run);
  void execute(const std::shared_ptr<LiveRun>& run, const Scene& scene, bool resume);
  /// Queues again, in their order, the runs the database holds as queued: they were waiting
  /// when the server last stopped or was killed (a queued run with a checkpoint was waiting
  /// to resume, and resumes). Interrupted runs with a checkpoint are listed on stderr, and
  /// resumed too with ServeOptions::resumeInterrupted.
  void requeueStored();
  /// Makes a stored or new run live and hands it to the queue; if the queue refuses it
  /// (full, or shutting down), the run is not live. `resume`: from its checkpoint.
  RunManager::Submit enqueue(std::int64_t id, int particles, Scene scene, bool resume = false);
  /// The run's checkpoint file (it may not exist).
  std::string checkpointPath(std::int64_t id) const;
  /// A checkpoint (or the one before it) is there to resume from.
  bool hasCheckpoint(std::int64_t id) const;
  void removeCheckpoint(std::int64_t id) const;
  /// After a run's end is committed: tell the watchers, drop the live state.
  void published(const std::shared_ptr<LiveRun>& run, const RunEnd& end);
  std::shared_ptr<LiveRun> live(std::int64_t id);
  void forget(std::int64_t id);
  nlohmann::json runJson(const RunRecord& record, bool withScene);
  RunRecord require(std::int64_t id);
  /// The run with its live status and stage; nothing if unknown (or being deleted).
  std::optional<RunRecord> storedRun(std::int64_t id);

  Repository& repo_;
  StreamHub& hub_;
  ServeOptions options_;
  RunFunction run_;
  SeriesFormat format_;
  std::string checkpointDir_;
  SpecimenSource specimens_;  ///< the stages' ends runs keep, and the specimens runs start from
  RunManager manager_;
  std::mutex liveMutex_;
  std::map<std::int64_t, std::shared_ptr<LiveRun>> live_;
  bool stopped_ = false;
  std::mutex studyMutex_;  ///< one study launched or cancelled at a time
  double startedAt_;
};

/// Unix seconds now (wall clock).
double unixNow();
/// "2025-01-31T12:00:00.123Z".
std::string isoTime(double unixSeconds);
/// Particles the scene will have: explicit ones plus the generated specimen and its boundary
/// ring, as the generator plans them (plannedParticleCount).
int estimateParticles(const Scene& scene);

}  // namespace grainlab::server

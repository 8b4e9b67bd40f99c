#pragma once
// The service layer between the routes and the storage: creates runs from scene JSON, runs
// them through the RunManager with a StreamObserver each, answers questions about them by
// merging the database with the live state, and attaches stream watchers. Refusals are thrown
// as ApiError with the HTTP status they deserve.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

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
  /// POST /api/studies with {"paper": {"seeds": N, "quick": bool}} (study_paper.cpp): the
  /// paper's six assemblies × N seeds, as `grainlab paper` runs them. Refused by field
  /// (paper.seeds, paper.quick, an unknown key) as a sweep spec is.
  std::string launchPaperStudy(const nlohmann::ordered_json& spec);
  /// POST /api/studies with {"tradeoff": {"seeds": N, "quick", "presets", "axes"}}
  /// (study_tradeoff.cpp): `grainlab tradeoff --seeds N`'s runs, planned by its code. The
  /// references are queued now; the other settings once every reference has ended
  /// (continueTradeoffStudy). Refused by field (tradeoff.seeds, tradeoff.presets[K],
  /// tradeoff.axes, runs[K].FIELD) before anything is stored.
  std::string launchTradeoffStudy(const nlohmann::ordered_json& spec);
  /// A trade-off study's second phase: once every reference run of it has ended, its other
  /// runs are admitted (a paired one starting from its seed's reference, start_from.run_id)
  /// and queued; one that cannot be (its reference failed) is stored failed, saying why.
  /// Does nothing for another study, or before, or after. Waits (and is asked again as any
  /// run ends) while the queue has no room for all of them. Called as each of its runs ends.
  void continueTradeoffStudy(const std::string& name);
  /// continueTradeoffStudy for the run's study and for every study waiting for room.
  void continueTradeoffStudies(const std::string& study);
  /// GET /api/studies/{name}/tradeoff: the trade-off table judged by `grainlab tradeoff`'s
  /// code once every run has ended, and kept: {"panels": [...], "csv": tradeoff.csv's text,
  /// "runs_csv"}. 404 unknown, 409 not a trade-off study or runs left.
  std::string studyTradeoff(const std::string& name);
  /// GET /api/studies/{name}/findings (study_findings.cpp): a paper study's findings, computed
  /// once all its runs have ended by the code `grainlab paper` uses, and kept: {"findings":
  /// [...], "csv": findings.csv's text}. 404 unknown, 409 not a paper study or runs left.
  std::string studyFindings(const std::string& name);
  /// POST /api/studies/{name}/cancel: cancels its queued and running runs as cancel() does,
  /// and its interrupted ones (their checkpoints dropped). 200 when every one of them ended
  /// at once, 202 when a running one was asked to stop; 404 unknown, 409 when none was left.
  /// Returns the status and the study's body (studyText).
  std::pair<int, std::string> cancelStudy(const std::string& name);
  /// POST /api/studies/{name}/resume (study_resume.cpp): its cancelled and interrupted runs
  /// queued again, each from its checkpoint where it has one (a study's cancelled run keeps
  /// its checkpoint for this), else from the start. 202 with the study's body; 404 unknown,
  /// 409 when no run is left to resume, 429 when the queue has no room for all of them.
  std::pair<int, std::string> resumeStudy(const std::string& name);
  /// DELETE /api/studies/{name} (study_delete.cpp): every run of it as remove() deletes one,
  /// then the study's row. 204 once all is gone, 202 if a running run is still stopping (it
  /// deletes itself when it has); 404 unknown.
  int deleteStudy(const std::string& name);
  /// GET /api/studies/{name}/bands (study_bands_service.cpp): its completed runs' ensemble
  /// bands of `quantity` (default phi) against axial strain, grouped by the varied path
  /// `group` (default the first that is not the seed; "" one group). 404 unknown study, 400
  /// naming a bad parameter.
  std::string studyBands(const std::string& name, const QueryParameters& query);
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
  /// One run of a study about to be launched: its scene (named NAME/id when stored), the
  /// preset it came from, the values it was given and how a refusal names it.
  struct StudyRun {
    nlohmann::json scene;
    std::string id;
    std::string preset;
    nlohmann::json parameters;
    std::string description;
  };
  /// Admits every run as create() does, then stores the study and its runs in one go and
  /// queues them (study_launch.cpp): whole or not at all. `fieldOf(field, k)` names a refusal
  /// of run k; `roomField` a queue without room. Returns the name.
  std::string storeStudy(const std::string& name, const nlohmann::ordered_json& spec, std::vector<StudyRun> runs,
                         const std::string& roomField,
                         const std::function<std::string(const std::string&, std::size_t)>& fieldOf);
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
  /// Trade-off studies whose references have ended but whose other runs found no room in the
  /// queue: tried again as any run ends (study_tradeoff.cpp).
  std::mutex waitingMutex_;
  std::set<std::string> waitingTradeoffs_;
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

#pragma once
// The runs database. Reads happen on the caller's thread through a small pool of read-only
// connections (WAL lets them run beside the writer); every write goes through ONE writer
// thread, which commits whatever has queued up in one transaction. Writes are applied in the
// order they were queued, so "the run finished" is never committed before its last sample.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "run_query.hpp"
#include "run_record.hpp"

namespace grainlab::server {

class Database;

/// How a run ended, as written once by finishRun().
struct RunEnd {
  RunStatus status = RunStatus::Failed;
  std::string error;
  std::string stage;
  double finishedAt = 0;
  std::optional<double> wallSeconds;
  std::optional<double> cpuSeconds;
  std::optional<double> preparationCpuSeconds;  ///< of cpuSeconds, before the shearing stage
  std::int64_t steps = 0;
  int particles = 0;
  std::optional<double> peakPhiMobDeg;
  std::string warnings = "[]";  ///< the validity envelope's, as summary.json's "warnings" (JSON)
};

/// A page of the runs list and how many runs match the query in all.
struct RunPage {
  std::vector<RunRecord> runs;
  std::int64_t total = 0;
};

/// A study's runs counted by status ("completed" -> 12, ...).
struct StudyCounts {
  std::string study;
  std::map<std::string, std::int64_t> byStatus;
};

/// What a study's time left is estimated from: its runs' estimated wall times
/// (RunRecord::estimatedSeconds) and the wall times its completed runs took.
struct StudyPace {
  std::int64_t finished = 0;         ///< completed runs with an estimate and a wall time
  double finishedEstimated = 0;      ///< their estimates, summed
  double finishedWall = 0;           ///< their wall times, summed
  std::int64_t unfinished = 0;       ///< queued and running runs
  std::int64_t unestimated = 0;      ///< of those, the ones without an estimate
  double unfinishedEstimated = 0;    ///< Σ estimate × (1 − progress) over the unfinished
};

/// A study launched on this server (POST /api/studies): the spec as given, its runs as a JSON
/// array ([{"id", "name", "parameters": {path: value}}], in the spec's order) and what was
/// asked of it: "launched" or "cancelled".
struct StudyRecord {
  std::string name;
  std::string spec;
  std::string runs = "[]";
  double createdAt = 0;
  std::string status = "launched";
  /// "launched" here (POST /api/studies) or "imported" (a `grainlab sweep` folder, sweep_import).
  std::string source = "launched";
};

class Repository {
 public:
  /// Who opens the database: the server owns its runs; a tool beside it (grainlab import)
  /// must not touch runs a live server may be running.
  enum class Opener { Server, Tool };
  /// Opens or creates the file (and its parent directory) and applies the migrations. The
  /// server also marks every run that was running as interrupted: no process is running it
  /// now. Queued runs stay queued: the server queues them again (RunService).
  explicit Repository(const std::string& path, Opener opener = Opener::Server);
  /// Commits what is queued, then closes.
  ~Repository();
  Repository(const Repository&) = delete;
  Repository& operator=(const Repository&) = delete;

  /// The schema version this code writes (PRAGMA user_version).
  static int schemaVersion();

  // ---- reads (any thread) ----
  /// Every run, oldest first, without its scene (RunRecord::scene is empty).
  std::vector<RunRecord> listRuns();
  /// The runs a query asks for (one page of them if it has a limit), without their scenes,
  /// and how many match in all; both read in one transaction.
  RunPage listRuns(const RunQuery& query);
  /// SQLite's EXPLAIN QUERY PLAN of the query's page (or count) statement, one line per step:
  /// what tests and benchmarks check to see an index serve it.
  std::string queryPlan(const RunQuery& query, bool count);
  /// The ids of the runs with exactly this name (runs_by_name), oldest first.
  std::vector<std::int64_t> runIdsNamed(const std::string& name);
  /// The studies (imported sweeps) with their runs counted by status, by name; `only`: just
  /// that one (none if no run belongs to it).
  std::vector<StudyCounts> studies(const std::string& only = {});
  /// The sums a study's time left is estimated from (one pass over its runs).
  StudyPace studyPace(const std::string& study);
  /// The studies launched here, by name; `only`: just that one (none if it was not launched).
  std::vector<StudyRecord> launchedStudies(const std::string& only = {});
  std::optional<RunRecord> findRun(std::int64_t id);
  std::vector<SampleRecord> samples(std::int64_t id);
  /// Histogram messages' JSON in sample order; `latestOnly` keeps the last one.
  std::vector<std::string> histograms(std::int64_t id, bool latestOnly);
  std::vector<FrameInfo> frames(std::int64_t id);
  /// The stored frame with this seq, or the last one at or before `step` when seq < 0.
  std::optional<std::string> frame(std::int64_t id, std::int64_t seq, std::int64_t step);
  std::optional<std::string> lastFrame(std::int64_t id);
  std::optional<std::string> shapes(std::int64_t id);

  // ---- writes (queued to the writer thread, applied in order) ----
  /// Resolves to the new run's id (never reused) once it is committed; run.id is ignored.
  std::future<std::int64_t> insertRun(const RunRecord& run);
  /// A launched study and its runs in one go (their `study` set by the caller): resolves to
  /// the runs' ids in order, or throws with nothing stored (a name already taken, a full disk).
  /// study.runs' entries get their run's "id".
  std::future<std::vector<std::int64_t>> insertStudy(const StudyRecord& study, const std::vector<RunRecord>& runs);
  /// More runs for a launched study (a trade-off study's second phase, study_tradeoff.cpp):
  /// `entries` a JSON array of {"name", "parameters"}, one per run, appended to its list with
  /// the runs' ids; all or nothing, as insertStudy.
  std::future<std::vector<std::int64_t>> appendStudyRuns(const std::string& name, const std::string& entries,
                                                         const std::vector<RunRecord>& runs);
  /// An imported sweep's row (study.source is taken as "imported"): inserted, or its spec and
  /// runs replaced if the sweep was imported before. A launched study of that name is left as
  /// it is (the caller refuses the import first).
  /// Resolves to true once committed (or throws: nothing stored).
  std::future<bool> putImportedStudy(const StudyRecord& study);
  void setStudyStatus(const std::string& name, const std::string& status);
  /// A paper study's findings, once computed (study_findings.cpp); studyFindings() reads them.
  void setStudyFindings(const std::string& name, const std::string& findings);
  std::optional<std::string> studyFindings(const std::string& name);
  /// A run's void ratio after consolidation (RunSummary's; -1 or none when it has none), as
  /// summary.json keeps it: what a paper study's finding 7 judges.
  void setVoidRatio(std::int64_t id, double voidRatio);
  std::optional<double> voidRatio(std::int64_t id);
  /// The study's row only (its runs are deleted one by one): a launch taken back.
  void deleteStudy(const std::string& name);
  void markStarted(std::int64_t id, double startedAt);
  void updateProgress(std::int64_t id, double progress, const std::string& stage,
                      std::int64_t steps);
  void setShapes(std::int64_t id, int particles, std::string shapesJson);
  void appendSample(std::int64_t id, SampleRecord sample);
  void appendHistogram(std::int64_t id, std::int64_t seq, std::int64_t step, std::string json);
  void appendFrame(std::int64_t id, std::int64_t seq, std::int64_t step, double time,
                   std::string bytes);
  /// `afterCommit` runs on the writer thread once the end is durable, or once it is known
  /// that it could not be stored (a full disk: findRun still shows the run unfinished).
  void finishRun(std::int64_t id, RunEnd end, std::function<void()> afterCommit);
  /// An interrupted (or failed) run about to resume: queued again, its error and end cleared.
  void requeueRun(std::int64_t id);
  /// Deletes the samples and histograms from seq `samples` on and the frames from seq
  /// `frames` on: what a run stored after the checkpoint it resumes from.
  void truncateRun(std::int64_t id, std::int64_t samples, std::int64_t frames);
  /// Resolves to whether a run was deleted (with its series, histograms and frames).
  /// `afterDelete`, if given, runs on the writer's thread once the deletion is committed or
  /// refused: a caller that cannot wait on the future (it runs there too) learns it this way.
  std::future<bool> deleteRun(std::int64_t id, std::function<void()> afterDelete = {});
  /// Resolves once everything queued before it is committed.
  std::future<void> flush();

  /// Writes that failed so far (a statement or a whole batch's commit: a full disk), and the
  /// last one's reason. A run stops when this moves (RunService), rather than go on while
  /// nothing of it is stored.
  std::uint64_t writeFailures() const { return writeFailures_.load(); }
  std::string lastWriteError() const;

 private:
  struct Writer;
  struct Reader;
  using Job = std::function<void(Writer&)>;

  class ReaderLease;
  ReaderLease lease();
  void enqueue(Job job);
  void writerLoop();

  std::string path_;
  std::unique_ptr<Writer> writer_;

  std::mutex readersMutex_;
  std::vector<std::unique_ptr<Reader>> idleReaders_;

  std::atomic<std::uint64_t> writeFailures_{0};
  mutable std::mutex writeErrorMutex_;
  std::string lastWriteError_;
  std::uint64_t reportedFailures_ = 0;  // writer thread: failures up to the last episode's end
  std::string reservePath_;             // the space held for a full disk (repository.cpp), if any
  void writeFailed(const std::string& what);
  void holdReserve();
  bool releaseReserve();  ///< true if it freed the reserve now

  std::mutex jobsMutex_;
  std::condition_variable jobsReady_;
  std::deque<Job> jobs_;
  bool stopping_ = false;
  std::thread writerThread_;
};

}  // namespace grainlab::server

#include "repository.hpp"

#include <fcntl.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cstring>
#include <exception>
#include <stdexcept>
#include <filesystem>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "sqlite.hpp"

namespace grainlab::server {
namespace {

// Disk space the server holds beside its database (`<db>.reserve`) and gives up when the
// disk is full, so that the ends of the runs it then stops can still be written: a run's
// end is one row, a few 4 KiB pages in the WAL.
constexpr off_t kReserveBytes = 256 << 10;

// Schema migrations: entry k takes user_version k to k + 1. Append, never edit.
constexpr const char* kMigrations[] = {
    R"sql(
    CREATE TABLE runs (
      id                INTEGER PRIMARY KEY AUTOINCREMENT,  -- ids are never reused
      name              TEXT NOT NULL,
      preset            TEXT NOT NULL DEFAULT '',
      scene             TEXT NOT NULL,
      status            TEXT NOT NULL,
      error             TEXT NOT NULL DEFAULT '',
      stage             TEXT NOT NULL DEFAULT '',
      progress          REAL NOT NULL DEFAULT 0,
      particles         INTEGER NOT NULL DEFAULT 0,
      steps             INTEGER NOT NULL DEFAULT 0,
      created_at        REAL NOT NULL,
      started_at        REAL,
      finished_at       REAL,
      wall_seconds      REAL,
      peak_phi_mob_deg  REAL,
      shapes            TEXT
    );
    CREATE TABLE samples (
      run_id  INTEGER NOT NULL,
      seq     INTEGER NOT NULL,
      step    INTEGER NOT NULL,
      time    REAL NOT NULL,
      stage   TEXT NOT NULL,
      vals    BLOB NOT NULL,          -- little-endian float64, one per Sample::values entry
      PRIMARY KEY (run_id, seq)
    );
    CREATE TABLE histograms (
      run_id  INTEGER NOT NULL,
      seq     INTEGER NOT NULL,
      step    INTEGER NOT NULL,
      data    TEXT NOT NULL,          -- the stream's "histogram" message
      PRIMARY KEY (run_id, seq)
    );
    CREATE TABLE frames (
      run_id  INTEGER NOT NULL,
      seq     INTEGER NOT NULL,
      step    INTEGER NOT NULL,
      time    REAL NOT NULL,
      data    BLOB NOT NULL,          -- the stream's binary frame
      PRIMARY KEY (run_id, seq)
    );
    )sql",
    // 1 -> 2: the simulation thread's CPU time, beside its wall time.
    "ALTER TABLE runs ADD COLUMN cpu_seconds REAL;",
    // 2 -> 3: the wall time the run was estimated to need when it was queued.
    "ALTER TABLE runs ADD COLUMN estimated_seconds REAL;",
    // 3 -> 4: the validity envelope's warnings, a JSON array (docs/validity.md).
    "ALTER TABLE runs ADD COLUMN warnings TEXT;",
    // 4 -> 5: the stored run (and its stage) a run started from: start_from.run_id.
    "ALTER TABLE runs ADD COLUMN origin_run_id INTEGER; ALTER TABLE runs ADD COLUMN origin_stage TEXT;",
    // 5 -> 6: the program that produced the run: 'grainlab', or 'lammps' for an imported LAMMPS run.
    "ALTER TABLE runs ADD COLUMN produced_by TEXT NOT NULL DEFAULT 'grainlab';",
    // 6 -> 7: the study a run belongs to (the sweep it was imported from), and the indexes that
    // serve a page of the runs list (RunQuery) without reading every run: one per sort key and
    // one per filter, each ending in (created_at, id), the order ties are broken in. Walking an index, SQLite reads a run's row only for the runs on the page, so a
    // deep page skips index entries, not rows (a row holds its scene and shapes, kilobytes).
    // Runs imported before this are
    // recognised by what importSweep writes: a "SWEEP/ID" name, started and finished at the
    // moment they were created.
    R"sql(
    ALTER TABLE runs ADD COLUMN study TEXT NOT NULL DEFAULT '';
    UPDATE runs SET study = substr(name, 1, instr(name, '/') - 1)
      WHERE instr(name, '/') > 1 AND started_at = created_at AND finished_at = created_at;
    CREATE INDEX runs_by_created_at ON runs (created_at, id);
    CREATE INDEX runs_by_status ON runs (status, created_at, id);
    CREATE INDEX runs_by_preset ON runs (preset, created_at, id);
    CREATE INDEX runs_by_study ON runs (study, created_at, id);
    CREATE INDEX runs_by_study_status ON runs (study, status);
    CREATE INDEX runs_by_name ON runs (name, created_at, id);
    CREATE INDEX runs_by_wall_seconds ON runs (wall_seconds, created_at, id);
    CREATE INDEX runs_by_peak_phi_mob_deg ON runs (peak_phi_mob_deg, created_at, id);
    )sql",
    // 7 -> 8: studies launched on this server (POST /api/studies): the sweep spec as given, its
    // runs with the values each was given (JSON), and what was asked of it ('launched' or
    // 'cancelled'); the runs' own states give its progress. Imported sweeps have no row here.
    R"sql(
    CREATE TABLE studies (
      name        TEXT PRIMARY KEY,
      spec        TEXT NOT NULL,
      runs        TEXT NOT NULL,
      created_at  REAL NOT NULL,
      status      TEXT NOT NULL
    );
    )sql",
    // 8 -> 9: the paper studies (POST /api/studies {"paper": ...}): a run's void ratio after
    // consolidation, which finding 7 judges (summary.json's), and a study's findings once
    // computed (JSON, study_findings.cpp).
    R"sql(
    ALTER TABLE runs ADD COLUMN void_ratio_after_consolidation REAL;
    ALTER TABLE studies ADD COLUMN findings TEXT;
    )sql",
    // 9 -> 10: imported sweeps become studies (sweep_import.cpp): a row with the sweep's spec and
    // each run's values, as a launched study has, and where the row came from: 'launched' (every
    // row before this) or 'imported'. And the part of a run's CPU time spent before its shearing
    // stage (preparing or loading its specimen), which a trade-off study's costs are split by.
    R"sql(
    ALTER TABLE studies ADD COLUMN source TEXT NOT NULL DEFAULT 'launched';
    ALTER TABLE runs ADD COLUMN preparation_cpu_seconds REAL;
    )sql",
};

// Every statement the server runs, by name.
namespace sql {
// The list leaves the scene out (it can be megabytes of particles); readRun sees it empty.
// listQuery() adds the filters, the order and the page.
constexpr const char* kListColumns =
    "SELECT id, name, preset, '' AS scene, status, error, stage, progress, particles, steps, "
    "created_at, started_at, finished_at, wall_seconds, peak_phi_mob_deg, cpu_seconds, estimated_seconds, warnings, "
    "origin_run_id, origin_stage, study, produced_by, preparation_cpu_seconds FROM runs";
constexpr const char* kRunIdsNamed = "SELECT id FROM runs WHERE name = :name ORDER BY id";
// Imported sweeps and how many of their runs stand in each status (runs_by_study_status).
constexpr const char* kStudyCounts =
    "SELECT study, status, COUNT(*) FROM runs WHERE study > '' GROUP BY study, status ORDER BY study";
constexpr const char* kOneStudyCounts =
    "SELECT study, status, COUNT(*) FROM runs WHERE study = :study GROUP BY study, status";
// A study's pace: its completed runs' estimates against their wall times, and the estimated
// work its queued and running runs have left (runs_by_study).
constexpr const char* kStudyPace =
    "SELECT "
    "COALESCE(SUM(status = 'completed' AND estimated_seconds > 0 AND wall_seconds IS NOT NULL), 0), "
    "COALESCE(SUM(CASE WHEN status = 'completed' AND estimated_seconds > 0 AND wall_seconds IS NOT NULL "
    "THEN estimated_seconds END), 0), "
    "COALESCE(SUM(CASE WHEN status = 'completed' AND estimated_seconds > 0 AND wall_seconds IS NOT NULL "
    "THEN wall_seconds END), 0), "
    "COALESCE(SUM(status IN ('queued', 'running')), 0), "
    "COALESCE(SUM(status IN ('queued', 'running') AND estimated_seconds IS NULL), 0), "
    "COALESCE(SUM(CASE WHEN status IN ('queued', 'running') "
    "THEN estimated_seconds * (1 - MIN(MAX(progress, 0), 1)) END), 0) "
    "FROM runs WHERE study = :study";
constexpr const char* kLaunchedStudies = "SELECT name, spec, runs, created_at, status, source FROM studies ORDER BY name";
constexpr const char* kOneLaunchedStudy =
    "SELECT name, spec, runs, created_at, status, source FROM studies WHERE name = :name";
constexpr const char* kInsertStudy =
    "INSERT INTO studies (name, spec, runs, created_at, status, source) "
    "VALUES (:name, :spec, :runs, :created_at, :status, :source)";
// An imported sweep's row, written again as each import finds more of its runs; never a
// launched study's.
constexpr const char* kPutImportedStudy =
    "INSERT INTO studies (name, spec, runs, created_at, status, source) "
    "VALUES (:name, :spec, :runs, :created_at, 'launched', 'imported') "
    "ON CONFLICT (name) DO UPDATE SET spec = excluded.spec, runs = excluded.runs WHERE studies.source = 'imported'";
constexpr const char* kStudyRuns = "SELECT runs FROM studies WHERE name = :name";
constexpr const char* kSetStudyRuns = "UPDATE studies SET runs = :runs WHERE name = :name";
constexpr const char* kSetStudyFindings = "UPDATE studies SET findings = :findings WHERE name = :name";
constexpr const char* kStudyFindings = "SELECT findings FROM studies WHERE name = :name AND findings IS NOT NULL";
constexpr const char* kSetVoidRatio = "UPDATE runs SET void_ratio_after_consolidation = :e WHERE id = :id";
constexpr const char* kVoidRatio =
    "SELECT void_ratio_after_consolidation FROM runs WHERE id = :id AND void_ratio_after_consolidation IS NOT NULL";
constexpr const char* kSetStudyStatus = "UPDATE studies SET status = :status WHERE name = :name";
constexpr const char* kDeleteStudy = "DELETE FROM studies WHERE name = :name";
constexpr const char* kFindRun =
    "SELECT id, name, preset, scene, status, error, stage, progress, particles, steps, "
    "created_at, started_at, finished_at, wall_seconds, peak_phi_mob_deg, cpu_seconds, estimated_seconds, warnings, "
    "origin_run_id, origin_stage, study, produced_by, preparation_cpu_seconds FROM runs WHERE id = :id";
constexpr const char* kSamples =
    "SELECT seq, step, time, stage, vals FROM samples WHERE run_id = :id ORDER BY seq";
constexpr const char* kHistograms =
    "SELECT data FROM histograms WHERE run_id = :id ORDER BY seq";
constexpr const char* kLatestHistogram =
    "SELECT data FROM histograms WHERE run_id = :id ORDER BY seq DESC LIMIT 1";
constexpr const char* kFrames =
    "SELECT seq, step, time, length(data) FROM frames WHERE run_id = :id ORDER BY seq";
constexpr const char* kFrameBySeq = "SELECT data FROM frames WHERE run_id = :id AND seq = :seq";
constexpr const char* kFrameAtStep =
    "SELECT data FROM frames WHERE run_id = :id AND step <= :step ORDER BY seq DESC LIMIT 1";
constexpr const char* kLastFrame =
    "SELECT data FROM frames WHERE run_id = :id ORDER BY seq DESC LIMIT 1";
constexpr const char* kShapes = "SELECT shapes FROM runs WHERE id = :id AND shapes IS NOT NULL";

constexpr const char* kInsertRun =
    "INSERT INTO runs (name, preset, scene, status, particles, created_at, estimated_seconds, warnings, "
    "origin_run_id, origin_stage, study, produced_by) "
    "VALUES (:name, :preset, :scene, :status, :particles, :created_at, :estimated_seconds, :warnings, "
    ":origin_run_id, :origin_stage, :study, :produced_by)";
constexpr const char* kMarkStarted =
    "UPDATE runs SET status = 'running', started_at = :started_at WHERE id = :id";
constexpr const char* kUpdateProgress =
    "UPDATE runs SET progress = :progress, stage = :stage, steps = :steps WHERE id = :id";
constexpr const char* kSetShapes =
    "UPDATE runs SET shapes = :shapes, particles = :particles WHERE id = :id";
constexpr const char* kInsertSample =
    "INSERT OR REPLACE INTO samples (run_id, seq, step, time, stage, vals) "
    "VALUES (:id, :seq, :step, :time, :stage, :vals)";
constexpr const char* kInsertHistogram =
    "INSERT OR REPLACE INTO histograms (run_id, seq, step, data) VALUES (:id, :seq, :step, :data)";
constexpr const char* kInsertFrame =
    "INSERT OR REPLACE INTO frames (run_id, seq, step, time, data) "
    "VALUES (:id, :seq, :step, :time, :data)";
constexpr const char* kFinishRun =
    "UPDATE runs SET status = :status, error = :error, stage = :stage, finished_at = :finished_at, "
    "wall_seconds = :wall_seconds, cpu_seconds = :cpu_seconds, preparation_cpu_seconds = :preparation_cpu_seconds, "
    "steps = :steps, particles = :particles, "
    "peak_phi_mob_deg = :peak, warnings = :warnings, progress = CASE WHEN :status = 'completed' THEN 1 ELSE progress END "
    "WHERE id = :id";
constexpr const char* kDeleteRun = "DELETE FROM runs WHERE id = :id";
// A resumed run waits in the queue again; its end is not known any more.
constexpr const char* kRequeueRun =
    "UPDATE runs SET status = 'queued', error = '', finished_at = NULL WHERE id = :id";
// What a run stored past its checkpoint: the resumed run stores it again.
constexpr const char* kTruncateSamples = "DELETE FROM samples WHERE run_id = :id AND seq >= :from";
constexpr const char* kTruncateHistograms = "DELETE FROM histograms WHERE run_id = :id AND seq >= :from";
constexpr const char* kTruncateFrames = "DELETE FROM frames WHERE run_id = :id AND seq >= :from";
constexpr const char* kDeleteSamples = "DELETE FROM samples WHERE run_id = :id";
constexpr const char* kDeleteHistograms = "DELETE FROM histograms WHERE run_id = :id";
constexpr const char* kDeleteFrames = "DELETE FROM frames WHERE run_id = :id";
// Only runs that were running: a queued run is queued again by the server (RunService).
constexpr const char* kInterruptUnfinished =
    "UPDATE runs SET status = 'interrupted', "
    "error = 'the server stopped before the run ended' "
    "WHERE status = 'running'";
}  // namespace sql

// A read transaction for the statements of one call; ended however the call ends (a reader
// must go back to the pool with none open).
class ReadSnapshot {
 public:
  explicit ReadSnapshot(Database& db) : db_(db) { db_.exec("BEGIN"); }
  ~ReadSnapshot() {
    try {
      db_.exec("COMMIT");
    } catch (const std::exception&) {
      // A read transaction has nothing to lose; SQLite ends it when the commit fails.
    }
  }
  ReadSnapshot(const ReadSnapshot&) = delete;
  ReadSnapshot& operator=(const ReadSnapshot&) = delete;

 private:
  Database& db_;
};

// The statement for one RunQuery: WHERE from its filters, ORDER BY its key then created_at and
// id (an index on (key, created_at, id) serves it), LIMIT/OFFSET for its page. `count` gives
// COUNT(*) instead of rows. Parameters are bound by bindRunQuery; values never enter the text.
std::string listQuery(const RunQuery& q, bool count) {
  std::string where;
  auto clause = [&](const std::string& c) { where += (where.empty() ? " WHERE " : " AND ") + c; };
  if (!q.statuses.empty()) {
    std::string in;
    for (std::size_t i = 0; i < q.statuses.size(); ++i) in += (i ? ", :s" : ":s") + std::to_string(i);
    clause("status IN (" + in + ")");
  }
  if (!q.preset.empty()) clause("preset = :preset");
  if (!q.study.empty()) clause("study = :study");
  // LIKE is case-insensitive for ASCII; the user's % and _ are escaped to mean themselves.
  if (!q.nameContains.empty()) clause("name LIKE :name_pattern ESCAPE '\\'");
  if (count) return "SELECT COUNT(*) FROM runs" + where;
  const std::string direction = q.descending ? " DESC" : " ASC";
  // Ties go by creation, then id, in the same direction: one index walk serves the order.
  std::string text = std::string(sql::kListColumns) + where + " ORDER BY ";
  if (q.sort != RunSortKey::CreatedAt) text += std::string(sortKeyName(q.sort)) + direction + ", ";
  text += "created_at" + direction + ", id" + direction;
  if (q.limit || q.offset > 0) text += " LIMIT :limit OFFSET :offset";
  return text;
}

void bindRunQuery(StatementUse& use, const RunQuery& q, bool count) {
  for (std::size_t i = 0; i < q.statuses.size(); ++i)
    use.bindText((":s" + std::to_string(i)).c_str(), toString(q.statuses[i]));
  if (!q.preset.empty()) use.bindText(":preset", q.preset);
  if (!q.study.empty()) use.bindText(":study", q.study);
  if (!q.nameContains.empty()) {
    std::string pattern = "%";
    for (char c : q.nameContains) {
      if (c == '%' || c == '_' || c == '\\') pattern += '\\';
      pattern += c;
    }
    use.bindText(":name_pattern", pattern + "%");
  }
  if (!count && (q.limit || q.offset > 0)) use.bind(":limit", q.limit.value_or(-1)).bind(":offset", q.offset);
}

void bindOptional(StatementUse& use, const char* name, const std::optional<double>& value) {
  if (value) use.bind(name, *value);
  else use.bindNull(name);
}

// A new run's row (sql::kInsertRun); returns its id.
std::int64_t insertRunRow(Statement& statement, Database& db, const RunRecord& run) {
  auto use = statement.use();
  use.bindText(":name", run.name)
      .bindText(":preset", run.preset)
      .bindText(":scene", run.scene)
      .bindText(":status", std::string(toString(run.status)))
      .bind(":particles", run.particles)
      .bind(":created_at", run.createdAt);
  bindOptional(use, ":estimated_seconds", run.estimatedSeconds);
  use.bindText(":warnings", run.warnings);
  if (run.origin) use.bind(":origin_run_id", run.origin->runId).bindText(":origin_stage", run.origin->stage);
  else use.bindNull(":origin_run_id").bindNull(":origin_stage");
  use.bindText(":study", run.study);
  use.bindText(":produced_by", run.producedBy);
  use.run();
  return db.lastInsertId();
}

std::optional<double> optionalAt(StatementUse& use, int column) {
  if (use.isNull(column)) return std::nullopt;
  return use.doubleAt(column);
}

RunRecord readRun(StatementUse& use) {
  RunRecord r;
  r.id = use.int64At(0);
  r.name = use.textAt(1);
  r.preset = use.textAt(2);
  r.scene = use.textAt(3);
  // A status this code does not know (a newer server's) reads as failed, not as a crash.
  r.status = parseRunStatus(use.textAt(4)).value_or(RunStatus::Failed);
  r.error = use.textAt(5);
  r.stage = use.textAt(6);
  r.progress = use.doubleAt(7);
  r.particles = static_cast<int>(use.int64At(8));
  r.steps = use.int64At(9);
  r.createdAt = use.doubleAt(10);
  r.startedAt = optionalAt(use, 11);
  r.finishedAt = optionalAt(use, 12);
  r.wallSeconds = optionalAt(use, 13);
  r.peakPhiMobDeg = optionalAt(use, 14);
  r.cpuSeconds = optionalAt(use, 15);
  r.estimatedSeconds = optionalAt(use, 16);
  if (!use.isNull(17)) r.warnings = use.textAt(17);
  if (!use.isNull(18)) r.origin = RunOrigin{use.int64At(18), use.isNull(19) ? std::string() : use.textAt(19)};
  r.study = use.textAt(20);
  r.producedBy = use.textAt(21);
  r.preparationCpuSeconds = optionalAt(use, 22);
  return r;
}

// Doubles are stored as their bytes (the machine is little-endian, as the frame format is).
std::string packValues(const std::vector<double>& values) {
  std::string bytes(values.size() * sizeof(double), '\0');
  if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

std::vector<double> unpackValues(const std::string& bytes) {
  std::vector<double> values(bytes.size() / sizeof(double));
  if (!values.empty()) std::memcpy(values.data(), bytes.data(), values.size() * sizeof(double));
  return values;
}

}  // namespace

// A read connection with its statements, prepared on first use.
struct Repository::Reader {
  explicit Reader(const std::string& path) : db(path, false) {}
  Statement& statement(const char* text) {
    auto it = statements.find(text);
    if (it == statements.end())
      it = statements.emplace(text, std::make_unique<Statement>(db, text)).first;
    return *it->second;
  }
  // A statement built for a query (listQuery): few distinct texts, kept like the others; the
  // map's key holds the text the Statement points at.
  Statement& statement(const std::string& text) {
    auto it = built.find(text);
    if (it == built.end()) {
      if (built.size() >= kMaxBuiltStatements) built.clear();
      it = built.emplace(text, nullptr).first;
      it->second = std::make_unique<Statement>(db, it->first.c_str());
    }
    return *it->second;
  }
  static constexpr std::size_t kMaxBuiltStatements = 64;
  Database db;
  std::map<const char*, std::unique_ptr<Statement>> statements;
  std::map<std::string, std::unique_ptr<Statement>> built;
};

// Borrows a reader for one call and gives it back.
class Repository::ReaderLease {
 public:
  ReaderLease(Repository& repo, std::unique_ptr<Reader> reader)
      : repo_(repo), reader_(std::move(reader)) {}
  ~ReaderLease() {
    std::lock_guard lock(repo_.readersMutex_);
    repo_.idleReaders_.push_back(std::move(reader_));
  }
  Statement& statement(const char* text) { return reader_->statement(text); }
  Statement& statement(const std::string& text) { return reader_->statement(text); }
  Database& db() { return reader_->db; }

 private:
  Repository& repo_;
  std::unique_ptr<Reader> reader_;
};

// The writer's connection and statements; touched only by the writer thread.
struct Repository::Writer {
  explicit Writer(const std::string& path) : db(path, true) {}
  Statement& statement(const char* text) {
    auto it = statements.find(text);
    if (it == statements.end())
      it = statements.emplace(text, std::make_unique<Statement>(db, text)).first;
    return *it->second;
  }
  Database db;
  std::map<const char*, std::unique_ptr<Statement>> statements;
  std::vector<std::function<void()>> afterCommit;
  bool committed = true;  // while afterCommit runs: whether the transaction was committed

  /// Gives `done` its value once the batch is committed, or an error if it could not be.
  template <class T>
  void resolveAfterCommit(std::shared_ptr<std::promise<T>> done, T value) {
    afterCommit.push_back([done, value = std::move(value), this] {
      if (committed) return done->set_value(value);
      done->set_exception(std::make_exception_ptr(std::runtime_error("the database could not be written")));
    });
  }
  /// Gives `done` the exception being handled, after the batch (a refused batch runs its
  /// jobs again, so it is told once, then).
  template <class T>
  void rejectAfterCommit(std::shared_ptr<std::promise<T>> done) {
    afterCommit.push_back([done, error = std::current_exception()] { done->set_exception(error); });
  }
};

Repository::Repository(const std::string& path, Opener opener) : path_(path) {
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);

  writer_ = std::make_unique<Writer>(path);
  Database& db = writer_->db;
  db.exec("PRAGMA journal_mode = WAL");
  // WAL with NORMAL sync survives a killed process (not a power cut) at a fraction of the cost.
  db.exec("PRAGMA synchronous = NORMAL");
  const auto version = db.userVersion();
  constexpr auto count = static_cast<std::int64_t>(std::size(kMigrations));
  if (version > count)
    throw SqliteError(path + " has schema version " + std::to_string(version) +
                      ", newer than this program's " + std::to_string(count));
  for (auto v = version; v < count; ++v) {
    db.exec("BEGIN IMMEDIATE");
    try {
      db.exec(kMigrations[v]);
      db.exec(("PRAGMA user_version = " + std::to_string(v + 1)).c_str());
      db.exec("COMMIT");
    } catch (...) {
      db.exec("ROLLBACK");
      throw;
    }
  }
  if (opener == Opener::Server) {
    auto use = writer_->statement(sql::kInterruptUnfinished).use();
    use.run();
    holdReserve();
  }
  writerThread_ = std::thread([this] { writerLoop(); });
}

Repository::~Repository() {
  {
    std::lock_guard lock(jobsMutex_);
    stopping_ = true;
  }
  jobsReady_.notify_all();
  writerThread_.join();
}

int Repository::schemaVersion() { return static_cast<int>(std::size(kMigrations)); }

void Repository::enqueue(Job job) {
  {
    std::lock_guard lock(jobsMutex_);
    jobs_.push_back(std::move(job));
  }
  jobsReady_.notify_one();
}

void Repository::holdReserve() {
  const std::string reserve = path_ + ".reserve";
  const int fd = ::open(reserve.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return;
  const bool held = ::posix_fallocate(fd, 0, kReserveBytes) == 0;
  ::close(fd);
  if (held) reservePath_ = reserve;
  else ::unlink(reserve.c_str());  // no room for it now: the next start tries again
}

bool Repository::releaseReserve() {
  if (reservePath_.empty()) return false;
  ::unlink(reservePath_.c_str());
  std::cerr << "grainlab serve: the disk is full: " << reservePath_ << " (" << kReserveBytes / 1024
            << " KiB held for this) is released so that the runs' ends can be recorded\n";
  reservePath_.clear();
  return true;
}

void Repository::writeFailed(const std::string& what) {
  {
    std::lock_guard lock(writeErrorMutex_);
    lastWriteError_ = what;
  }
  // Said once per episode (a full disk fails every batch until space is freed).
  if (writeFailures_++ == reportedFailures_) std::cerr << "grainlab serve: " << what << "\n";
}

std::string Repository::lastWriteError() const {
  std::lock_guard lock(writeErrorMutex_);
  return lastWriteError_;
}

void Repository::writerLoop() {
  Writer& w = *writer_;
  // Runs jobs in one transaction; false if it could not be committed (then none of it was).
  auto transaction = [&](std::deque<Job>::iterator begin, std::deque<Job>::iterator end) {
    w.afterCommit.clear();
    try {
      w.db.exec("BEGIN IMMEDIATE");
      for (auto job = begin; job != end; ++job) {
        try {
          (*job)(w);
        } catch (const std::exception& e) {
          writeFailed(std::string("database write failed: ") + e.what());
        }
        // SQLite may have rolled the whole transaction back (a full disk): the jobs after
        // this one would each commit on their own, and run again below. The batch failed.
        if (sqlite3_get_autocommit(w.db.handle())) throw SqliteError("the transaction was rolled back");
      }
      w.db.exec("COMMIT");
      return true;
    } catch (const std::exception& e) {
      writeFailed(std::string("database commit failed: ") + e.what());
      try {
        w.db.exec("ROLLBACK");
      } catch (const std::exception&) {
        // Nothing was open: the BEGIN itself failed, or SQLite rolled back already.
      }
      return false;
    }
  };
  auto callBack = [&](bool committed) {
    w.committed = committed;
    auto callbacks = std::move(w.afterCommit);
    w.afterCommit.clear();
    for (auto& callback : callbacks) callback();
  };
  for (;;) {
    std::deque<Job> batch;
    {
      std::unique_lock lock(jobsMutex_);
      jobsReady_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
      if (jobs_.empty()) return;  // stopping with nothing left
      batch.swap(jobs_);
    }
    // One transaction per batch: a run's samples arrive many per second, and one COMMIT per
    // row would cost a WAL sync each.
    const auto failuresBefore = writeFailures_.load();
    const bool committed = transaction(batch.begin(), batch.end());
    // Refused whole (a full disk): one transaction per job, in the space the reserve held,
    // so that the small writes that matter most (a run's end, a new run) still get in.
    // Jobs can run again: what a failed transaction did is rolled back, callbacks included.
    if (const bool freed = !committed && releaseReserve(); !committed && (batch.size() > 1 || freed)) {
      for (auto job = batch.begin(); job != batch.end(); ++job) callBack(transaction(job, job + 1));
    } else {
      callBack(committed);
    }
    if (writeFailures_.load() == failuresBefore && failuresBefore > reportedFailures_) {
      std::cerr << "grainlab serve: database writes work again after " << failuresBefore - reportedFailures_
                << " failed\n";
      reportedFailures_ = failuresBefore;
    }
  }
}

Repository::ReaderLease Repository::lease() {
  std::unique_ptr<Reader> reader;
  {
    std::lock_guard lock(readersMutex_);
    if (!idleReaders_.empty()) {
      reader = std::move(idleReaders_.back());
      idleReaders_.pop_back();
    }
  }
  if (!reader) reader = std::make_unique<Reader>(path_);
  return ReaderLease(*this, std::move(reader));
}

std::vector<RunRecord> Repository::listRuns() {
  RunQuery everyRun;
  everyRun.descending = false;
  return listRuns(everyRun).runs;
}

RunPage Repository::listRuns(const RunQuery& query) {
  auto reader = lease();
  RunPage page;
  // One read transaction: the page and the count see the same database.
  ReadSnapshot snapshot(reader.db());
  {
    auto use = reader.statement(listQuery(query, false)).use();
    bindRunQuery(use, query, false);
    while (use.step()) page.runs.push_back(readRun(use));
  }
  {
    auto use = reader.statement(listQuery(query, true)).use();
    bindRunQuery(use, query, true);
    if (use.step()) page.total = use.int64At(0);
  }
  return page;
}

std::string Repository::queryPlan(const RunQuery& query, bool count) {
  auto reader = lease();
  auto use = reader.statement("EXPLAIN QUERY PLAN " + listQuery(query, count)).use();
  bindRunQuery(use, query, count);
  std::string plan;
  while (use.step()) plan += use.textAt(3) + "\n";
  return plan;
}

std::vector<std::int64_t> Repository::runIdsNamed(const std::string& name) {
  auto reader = lease();
  auto use = reader.statement(sql::kRunIdsNamed).use();
  use.bindText(":name", name);
  std::vector<std::int64_t> ids;
  while (use.step()) ids.push_back(use.int64At(0));
  return ids;
}

std::vector<StudyCounts> Repository::studies(const std::string& only) {
  auto reader = lease();
  auto use = reader.statement(only.empty() ? sql::kStudyCounts : sql::kOneStudyCounts).use();
  if (!only.empty()) use.bindText(":study", only);
  std::vector<StudyCounts> out;
  while (use.step()) {
    const std::string study = use.textAt(0);
    if (out.empty() || out.back().study != study) out.push_back({study, {}});
    out.back().byStatus[use.textAt(1)] = use.int64At(2);
  }
  return out;
}

StudyPace Repository::studyPace(const std::string& study) {
  auto reader = lease();
  auto use = reader.statement(sql::kStudyPace).use();
  use.bindText(":study", study);
  StudyPace pace;
  if (!use.step()) return pace;
  pace.finished = use.int64At(0);
  pace.finishedEstimated = use.doubleAt(1);
  pace.finishedWall = use.doubleAt(2);
  pace.unfinished = use.int64At(3);
  pace.unestimated = use.int64At(4);
  pace.unfinishedEstimated = use.doubleAt(5);
  return pace;
}

std::optional<RunRecord> Repository::findRun(std::int64_t id) {
  auto reader = lease();
  auto use = reader.statement(sql::kFindRun).use();
  use.bind(":id", id);
  if (!use.step()) return std::nullopt;
  return readRun(use);
}

std::vector<SampleRecord> Repository::samples(std::int64_t id) {
  auto reader = lease();
  auto use = reader.statement(sql::kSamples).use();
  use.bind(":id", id);
  std::vector<SampleRecord> rows;
  while (use.step()) {
    SampleRecord s;
    s.seq = use.int64At(0);
    s.step = use.int64At(1);
    s.time = use.doubleAt(2);
    s.stage = use.textAt(3);
    s.values = unpackValues(use.blobAt(4));
    rows.push_back(std::move(s));
  }
  return rows;
}

std::vector<std::string> Repository::histograms(std::int64_t id, bool latestOnly) {
  auto reader = lease();
  auto use = reader.statement(latestOnly ? sql::kLatestHistogram : sql::kHistograms).use();
  use.bind(":id", id);
  std::vector<std::string> out;
  while (use.step()) out.push_back(use.textAt(0));
  return out;
}

std::vector<FrameInfo> Repository::frames(std::int64_t id) {
  auto reader = lease();
  auto use = reader.statement(sql::kFrames).use();
  use.bind(":id", id);
  std::vector<FrameInfo> out;
  while (use.step())
    out.push_back({use.int64At(0), use.int64At(1), use.doubleAt(2), use.int64At(3)});
  return out;
}

std::optional<std::string> Repository::frame(std::int64_t id, std::int64_t seq,
                                             std::int64_t step) {
  auto reader = lease();
  auto use = reader.statement(seq >= 0 ? sql::kFrameBySeq : sql::kFrameAtStep).use();
  use.bind(":id", id);
  if (seq >= 0) use.bind(":seq", seq);
  else use.bind(":step", step);
  if (!use.step()) return std::nullopt;
  return use.blobAt(0);
}

std::optional<std::string> Repository::lastFrame(std::int64_t id) {
  auto reader = lease();
  auto use = reader.statement(sql::kLastFrame).use();
  use.bind(":id", id);
  if (!use.step()) return std::nullopt;
  return use.blobAt(0);
}

std::optional<std::string> Repository::shapes(std::int64_t id) {
  auto reader = lease();
  auto use = reader.statement(sql::kShapes).use();
  use.bind(":id", id);
  if (!use.step()) return std::nullopt;
  return use.textAt(0);
}

std::future<std::int64_t> Repository::insertRun(const RunRecord& run) {
  auto done = std::make_shared<std::promise<std::int64_t>>();
  auto future = done->get_future();
  enqueue([run, done](Writer& w) {
    std::int64_t id = 0;
    try {
      id = insertRunRow(w.statement(sql::kInsertRun), w.db, run);
    } catch (...) {
      w.rejectAfterCommit(done);
      return;
    }
    w.resolveAfterCommit(done, id);
  });
  return future;
}

std::future<std::vector<std::int64_t>> Repository::insertStudy(const StudyRecord& study,
                                                              const std::vector<RunRecord>& runs) {
  auto done = std::make_shared<std::promise<std::vector<std::int64_t>>>();
  auto future = done->get_future();
  enqueue([study, runs, done](Writer& w) {
    std::vector<std::int64_t> ids;
    // All or nothing inside the batch's transaction: a study is never stored in part.
    w.db.exec("SAVEPOINT study");
    try {
      for (const RunRecord& run : runs) ids.push_back(insertRunRow(w.statement(sql::kInsertRun), w.db, run));
      nlohmann::json listed = nlohmann::json::parse(study.runs);
      for (std::size_t k = 0; k < ids.size() && k < listed.size(); ++k) listed[k]["id"] = ids[k];
      auto use = w.statement(sql::kInsertStudy).use();
      use.bindText(":name", study.name)
          .bindText(":spec", study.spec)
          .bindText(":runs", listed.dump())
          .bind(":created_at", study.createdAt)
          .bindText(":status", study.status)
          .bindText(":source", study.source);
      use.run();
      w.db.exec("RELEASE study");
    } catch (...) {
      try {
        w.db.exec("ROLLBACK TO study");
        w.db.exec("RELEASE study");
      } catch (const std::exception&) {
        // SQLite rolled the whole transaction back already (a full disk).
      }
      w.rejectAfterCommit(done);
      return;
    }
    w.resolveAfterCommit(done, std::move(ids));
  });
  return future;
}

std::future<std::vector<std::int64_t>> Repository::appendStudyRuns(const std::string& name, const std::string& entries,
                                                                  const std::vector<RunRecord>& runs) {
  auto done = std::make_shared<std::promise<std::vector<std::int64_t>>>();
  auto future = done->get_future();
  enqueue([name, entries, runs, done](Writer& w) {
    std::vector<std::int64_t> ids;
    // All or nothing, as insertStudy: the study's list never names a run that is not stored.
    w.db.exec("SAVEPOINT study_runs");
    try {
      nlohmann::json listed;
      {
        auto read = w.statement(sql::kStudyRuns).use();
        read.bindText(":name", name);
        if (!read.step()) throw std::runtime_error("no study '" + name + "'");
        listed = nlohmann::json::parse(read.textAt(0));
      }
      const nlohmann::json added = nlohmann::json::parse(entries);
      for (const RunRecord& run : runs) ids.push_back(insertRunRow(w.statement(sql::kInsertRun), w.db, run));
      for (std::size_t k = 0; k < ids.size() && k < added.size(); ++k) {
        listed.push_back(added[k]);
        listed.back()["id"] = ids[k];
      }
      auto use = w.statement(sql::kSetStudyRuns).use();
      use.bindText(":name", name).bindText(":runs", listed.dump());
      use.run();
      w.db.exec("RELEASE study_runs");
    } catch (...) {
      try {
        w.db.exec("ROLLBACK TO study_runs");
        w.db.exec("RELEASE study_runs");
      } catch (const std::exception&) {
        // SQLite rolled the whole transaction back already (a full disk).
      }
      w.rejectAfterCommit(done);
      return;
    }
    w.resolveAfterCommit(done, std::move(ids));
  });
  return future;
}

std::future<bool> Repository::putImportedStudy(const StudyRecord& study) {
  auto done = std::make_shared<std::promise<bool>>();
  auto future = done->get_future();
  enqueue([study, done](Writer& w) {
    try {
      auto use = w.statement(sql::kPutImportedStudy).use();
      use.bindText(":name", study.name).bindText(":spec", study.spec).bindText(":runs", study.runs).bind(":created_at", study.createdAt);
      use.run();
    } catch (...) {
      w.rejectAfterCommit(done);
      return;
    }
    w.resolveAfterCommit(done, true);
  });
  return future;
}

void Repository::setStudyStatus(const std::string& name, const std::string& status) {
  enqueue([=](Writer& w) {
    auto use = w.statement(sql::kSetStudyStatus).use();
    use.bindText(":name", name).bindText(":status", status);
    use.run();
  });
}

void Repository::setStudyFindings(const std::string& name, const std::string& findings) {
  enqueue([=](Writer& w) {
    auto use = w.statement(sql::kSetStudyFindings).use();
    use.bindText(":name", name).bindText(":findings", findings);
    use.run();
  });
}

std::optional<std::string> Repository::studyFindings(const std::string& name) {
  auto reader = lease();
  auto use = reader.statement(sql::kStudyFindings).use();
  use.bindText(":name", name);
  if (!use.step()) return std::nullopt;
  return use.textAt(0);
}

void Repository::setVoidRatio(std::int64_t id, double voidRatio) {
  enqueue([=](Writer& w) {
    auto use = w.statement(sql::kSetVoidRatio).use();
    use.bind(":id", id).bind(":e", voidRatio);
    use.run();
  });
}

std::optional<double> Repository::voidRatio(std::int64_t id) {
  auto reader = lease();
  auto use = reader.statement(sql::kVoidRatio).use();
  use.bind(":id", id);
  if (!use.step()) return std::nullopt;
  return use.doubleAt(0);
}

void Repository::deleteStudy(const std::string& name) {
  enqueue([=](Writer& w) {
    auto use = w.statement(sql::kDeleteStudy).use();
    use.bindText(":name", name);
    use.run();
  });
}

std::vector<StudyRecord> Repository::launchedStudies(const std::string& only) {
  auto reader = lease();
  auto use = reader.statement(only.empty() ? sql::kLaunchedStudies : sql::kOneLaunchedStudy).use();
  if (!only.empty()) use.bindText(":name", only);
  std::vector<StudyRecord> out;
  while (use.step())
    out.push_back({use.textAt(0), use.textAt(1), use.textAt(2), use.doubleAt(3), use.textAt(4), use.textAt(5)});
  return out;
}

void Repository::markStarted(std::int64_t id, double startedAt) {
  enqueue([=](Writer& w) {
    auto use = w.statement(sql::kMarkStarted).use();
    use.bind(":id", id).bind(":started_at", startedAt);
    use.run();
  });
}

void Repository::updateProgress(std::int64_t id, double progress, const std::string& stage,
                                std::int64_t steps) {
  enqueue([=](Writer& w) {
    auto use = w.statement(sql::kUpdateProgress).use();
    use.bind(":id", id).bind(":progress", progress).bindText(":stage", stage).bind(":steps", steps);
    use.run();
  });
}

void Repository::setShapes(std::int64_t id, int particles, std::string shapesJson) {
  enqueue([=, json = std::move(shapesJson)](Writer& w) {
    auto use = w.statement(sql::kSetShapes).use();
    use.bind(":id", id).bind(":particles", particles).bindText(":shapes", json);
    use.run();
  });
}

void Repository::appendSample(std::int64_t id, SampleRecord sample) {
  enqueue([id, s = std::move(sample)](Writer& w) {
    auto use = w.statement(sql::kInsertSample).use();
    use.bind(":id", id)
        .bind(":seq", s.seq)
        .bind(":step", s.step)
        .bind(":time", s.time)
        .bindText(":stage", s.stage)
        .bindBlob(":vals", packValues(s.values));
    use.run();
  });
}

void Repository::appendHistogram(std::int64_t id, std::int64_t seq, std::int64_t step,
                                 std::string json) {
  enqueue([=, data = std::move(json)](Writer& w) {
    auto use = w.statement(sql::kInsertHistogram).use();
    use.bind(":id", id).bind(":seq", seq).bind(":step", step).bindText(":data", data);
    use.run();
  });
}

void Repository::appendFrame(std::int64_t id, std::int64_t seq, std::int64_t step, double time,
                             std::string bytes) {
  enqueue([=, data = std::move(bytes)](Writer& w) {
    auto use = w.statement(sql::kInsertFrame).use();
    use.bind(":id", id).bind(":seq", seq).bind(":step", step).bind(":time", time).bindBlob(
        ":data", data);
    use.run();
  });
}

void Repository::finishRun(std::int64_t id, RunEnd end, std::function<void()> afterCommit) {
  enqueue([id, end = std::move(end), after = std::move(afterCommit)](Writer& w) {
    {
      auto use = w.statement(sql::kFinishRun).use();
      use.bind(":id", id)
          .bindText(":status", std::string(toString(end.status)))
          .bindText(":error", end.error)
          .bindText(":stage", end.stage)
          .bind(":finished_at", end.finishedAt)
          .bind(":steps", end.steps)
          .bind(":particles", end.particles);
      bindOptional(use, ":wall_seconds", end.wallSeconds);
      bindOptional(use, ":cpu_seconds", end.cpuSeconds);
      bindOptional(use, ":preparation_cpu_seconds", end.preparationCpuSeconds);
      bindOptional(use, ":peak", end.peakPhiMobDeg);
      use.bindText(":warnings", end.warnings);
      use.run();
    }
    if (after) w.afterCommit.push_back(after);  // (a copy: a refused batch runs its jobs again)
  });
}

void Repository::requeueRun(std::int64_t id) {
  enqueue([=](Writer& w) {
    auto use = w.statement(sql::kRequeueRun).use();
    use.bind(":id", id);
    use.run();
  });
}

void Repository::truncateRun(std::int64_t id, std::int64_t samples, std::int64_t frames) {
  enqueue([=](Writer& w) {
    for (const char* text : {sql::kTruncateSamples, sql::kTruncateHistograms, sql::kTruncateFrames}) {
      auto use = w.statement(text).use();
      use.bind(":id", id).bind(":from", text == sql::kTruncateFrames ? frames : samples);
      use.run();
    }
  });
}

std::future<bool> Repository::deleteRun(std::int64_t id, std::function<void()> afterDelete) {
  auto done = std::make_shared<std::promise<bool>>();
  auto future = done->get_future();
  enqueue([id, done, after = std::move(afterDelete)](Writer& w) {
    bool deleted = false;
    try {
      for (const char* text :
           {sql::kDeleteSamples, sql::kDeleteHistograms, sql::kDeleteFrames, sql::kDeleteRun}) {
        auto use = w.statement(text).use();
        use.bind(":id", id);
        use.run();
        if (text == sql::kDeleteRun) deleted = w.db.changes() > 0;
      }
    } catch (...) {
      w.rejectAfterCommit(done);
      if (after) w.afterCommit.push_back(after);
      return;
    }
    w.afterCommit.push_back([done, deleted, &w] { done->set_value(deleted && w.committed); });
    if (after) w.afterCommit.push_back(after);
  });
  return future;
}

std::future<void> Repository::flush() {
  auto done = std::make_shared<std::promise<void>>();
  auto future = done->get_future();
  enqueue([done](Writer& w) { w.afterCommit.push_back([done] { done->set_value(); }); });
  return future;
}

}  // namespace grainlab::server

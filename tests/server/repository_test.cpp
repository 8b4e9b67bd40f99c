#include "repository.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "sqlite.hpp"

namespace grainlab::server {
namespace {

std::string freshDb(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("grainlab-repo-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto path = dir / (name + ".db");
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path.string() + suffix);
  return path.string();
}

// What a database from before studies looked like (schema 5): no study column, no list indexes,
// no studies table.
constexpr const char* kUndoStudies =
    "ALTER TABLE runs DROP COLUMN preparation_cpu_seconds; "  // schema 10
    "ALTER TABLE runs DROP COLUMN void_ratio_after_consolidation; "  // schema 9
    "DROP TABLE studies; DROP INDEX runs_by_created_at; DROP INDEX runs_by_status; DROP INDEX runs_by_preset; DROP INDEX runs_by_study; "
    "DROP INDEX runs_by_study_status; DROP INDEX runs_by_name; DROP INDEX runs_by_wall_seconds; "
    "DROP INDEX runs_by_peak_phi_mob_deg; ALTER TABLE runs DROP COLUMN study;";

RunRecord queued(const std::string& name) {
  RunRecord r;
  r.name = name;
  r.scene = R"({"name":")" + name + R"("})";
  r.createdAt = 1700000000.5;
  r.particles = 3;
  return r;
}

TEST(Repository, MigratesToTheCurrentSchemaInWalMode) {
  const auto path = freshDb("schema");
  { Repository repo(path); }
  Database db(path, false);
  EXPECT_EQ(db.userVersion(), Repository::schemaVersion());
  Statement mode(db, "PRAGMA journal_mode");
  auto use = mode.use();
  ASSERT_TRUE(use.step());
  EXPECT_EQ(use.textAt(0), "wal");
}

TEST(Repository, CreatesTheParentDirectory) {
  const auto dir = std::filesystem::path(freshDb("x")).parent_path() / "nested" / "deeper";
  std::filesystem::remove_all(dir.parent_path());
  Repository repo((dir / "g.db").string());
  EXPECT_TRUE(std::filesystem::exists(dir / "g.db"));
}

TEST(Repository, StoresARunWithItsSeriesFramesAndEnd) {
  Repository repo(freshDb("store"));
  const auto a = repo.insertRun(queued("a")).get();
  const auto b = repo.insertRun(queued("b")).get();
  EXPECT_LT(a, b);
  repo.markStarted(a, 1700000001.0);
  repo.appendSample(a, {0, 10, 0.5, "free", {1.0, 2.5, std::nan("")}});
  repo.appendSample(a, {1, 20, 1.0, "free", {3.0, 4.5, 6.0}});
  repo.appendHistogram(a, 1, 20, R"({"type":"histogram"})");
  repo.appendFrame(a, 0, 20, 1.0, std::string("\x01\x00\x02", 3));
  repo.setShapes(a, 3, R"({"type":"shapes"})");
  RunEnd end;
  end.status = RunStatus::Completed;
  end.finishedAt = 1700000002.0;
  end.wallSeconds = 0.75;
  end.cpuSeconds = 0.5;
  end.steps = 20;
  end.particles = 3;
  bool published = false;
  repo.finishRun(a, end, [&] { published = true; });
  repo.flush().get();
  EXPECT_TRUE(published);

  auto run = repo.findRun(a);
  ASSERT_TRUE(run);
  EXPECT_EQ(run->status, RunStatus::Completed);
  EXPECT_DOUBLE_EQ(run->progress, 1.0);
  EXPECT_DOUBLE_EQ(*run->wallSeconds, 0.75);
  EXPECT_DOUBLE_EQ(*run->cpuSeconds, 0.5);
  EXPECT_DOUBLE_EQ(*run->startedAt, 1700000001.0);
  EXPECT_EQ(run->scene, R"({"name":"a"})");

  auto samples = repo.samples(a);
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_EQ(samples[1].step, 20);
  EXPECT_EQ(samples[1].values, (std::vector<double>{3.0, 4.5, 6.0}));
  EXPECT_TRUE(std::isnan(samples[0].values[2]));
  EXPECT_EQ(repo.histograms(a, true).size(), 1u);
  EXPECT_EQ(*repo.frame(a, 0, 0), std::string("\x01\x00\x02", 3));
  EXPECT_EQ(*repo.frame(a, -1, 25), std::string("\x01\x00\x02", 3));
  EXPECT_FALSE(repo.frame(a, -1, 5));
  EXPECT_EQ(*repo.shapes(a), R"({"type":"shapes"})");
  EXPECT_EQ(repo.listRuns().size(), 2u);

  EXPECT_TRUE(repo.deleteRun(a).get());
  EXPECT_FALSE(repo.deleteRun(a).get());
  EXPECT_FALSE(repo.findRun(a));
  EXPECT_TRUE(repo.samples(a).empty());
  EXPECT_TRUE(repo.frames(a).empty());
}

TEST(Repository, ReopeningMarksRunningRunsInterruptedKeepsQueuedOnesAndTheirSeries) {
  const auto path = freshDb("reopen");
  std::int64_t running = 0, queuedId = 0, done = 0;
  {
    Repository repo(path);
    running = repo.insertRun(queued("running")).get();
    queuedId = repo.insertRun(queued("queued")).get();
    done = repo.insertRun(queued("done")).get();
    repo.markStarted(running, 1.0);
    repo.appendSample(running, {0, 1, 0.1, "free", {1.0}});
    RunEnd end;
    end.status = RunStatus::Completed;
    repo.finishRun(done, end, nullptr);
  }
  Repository repo(path);
  EXPECT_EQ(repo.findRun(running)->status, RunStatus::Interrupted);
  EXPECT_FALSE(repo.findRun(running)->error.empty());
  EXPECT_EQ(repo.findRun(queuedId)->status, RunStatus::Queued) << "the server queues it again";
  EXPECT_EQ(repo.findRun(done)->status, RunStatus::Completed);
  EXPECT_EQ(repo.samples(running).size(), 1u);
  // Ids are never reused, even after the newest run is deleted.
  EXPECT_TRUE(repo.deleteRun(done).get());
  EXPECT_GT(repo.insertRun(queued("next")).get(), done);
}

TEST(Repository, ReadsBetweenWritesLeaveNoStatementOpen) {
  // An un-reset read statement would keep a read transaction and fail the writer's COMMIT.
  Repository repo(freshDb("reset"));
  const auto id = repo.insertRun(queued("r")).get();
  for (int i = 0; i < 50; ++i) {
    repo.appendSample(id, {i, i, 0.1 * i, "free", {double(i)}});
    (void)repo.listRuns();
    (void)repo.samples(id);
    (void)repo.findRun(id);
  }
  repo.flush().get();
  EXPECT_EQ(repo.samples(id).size(), 50u);
}

TEST(Repository, UpgradesADatabaseFromBeforeCpuSecondsKeepingItsRuns) {
  const auto path = freshDb("upgrade");
  std::int64_t id = 0;
  {
    Repository repo(path);
    id = repo.insertRun(queued("old")).get();
    RunEnd end;
    end.status = RunStatus::Completed;
    end.finishedAt = 1700000002.0;
    end.wallSeconds = 0.75;
    repo.finishRun(id, end, {});
    repo.flush().get();
  }
  {
    // What a version-1 database looked like: no cpu_seconds, estimated_seconds, warnings nor
    // origin columns.
    Database db(path, true);
    db.exec(kUndoStudies);
    db.exec("ALTER TABLE runs DROP COLUMN produced_by; ALTER TABLE runs DROP COLUMN origin_stage; ALTER TABLE runs DROP COLUMN origin_run_id; "
            "ALTER TABLE runs DROP COLUMN warnings; ALTER TABLE runs DROP COLUMN estimated_seconds; "
            "ALTER TABLE runs DROP COLUMN cpu_seconds; PRAGMA user_version = 1;");
  }
  Repository repo(path);
  auto run = repo.findRun(id);
  ASSERT_TRUE(run);
  EXPECT_EQ(run->name, "old");
  EXPECT_DOUBLE_EQ(*run->wallSeconds, 0.75);
  EXPECT_FALSE(run->cpuSeconds);
  EXPECT_FALSE(run->estimatedSeconds);
  EXPECT_EQ(run->warnings, "[]");  // a run from before the envelope: none recorded
  EXPECT_FALSE(run->origin);       // nor started from a stored run
  EXPECT_EQ(run->producedBy, "grainlab");  // schema 6: every run before it was grainlab's own
  // Schema 5: the stored run and stage a run started from.
  RunRecord branched = queued("branched");
  branched.origin = RunOrigin{id, "consolidation"};
  const auto branchedId = repo.insertRun(branched).get();
  const auto stored = repo.findRun(branchedId);
  ASSERT_TRUE(stored && stored->origin);
  EXPECT_EQ(stored->origin->runId, id);
  EXPECT_EQ(stored->origin->stage, "consolidation");
  EXPECT_TRUE(repo.listRuns().back().origin);
  RunRecord imported = queued("imported");
  imported.producedBy = "lammps";
  EXPECT_EQ(repo.findRun(repo.insertRun(imported).get())->producedBy, "lammps");
  Database db(path, false);
  EXPECT_EQ(db.userVersion(), Repository::schemaVersion());
}

TEST(Repository, AStudyIsStoredWithItsRunsOrNotAtAll) {
  const auto path = freshDb("studies");
  Repository repo(path);
  StudyRecord study;
  study.name = "friction";
  study.spec = R"({"name":"friction"})";
  study.runs = R"([{"name":"friction/001"},{"name":"friction/002"}])";
  study.createdAt = 1700000000.0;
  std::vector<RunRecord> runs = {queued("friction/001"), queued("friction/002")};
  for (RunRecord& r : runs) r.study = "friction";
  const auto ids = repo.insertStudy(study, runs).get();
  ASSERT_EQ(ids.size(), 2u);
  EXPECT_EQ(repo.findRun(ids[1])->study, "friction");
  const auto stored = repo.launchedStudies("friction");
  ASSERT_EQ(stored.size(), 1u);
  // Each listed run carries the id it was given.
  EXPECT_EQ(stored[0].runs, R"([{"id":)" + std::to_string(ids[0]) + R"(,"name":"friction/001"},{"id":)" +
                                std::to_string(ids[1]) + R"(,"name":"friction/002"}])");
  EXPECT_EQ(stored[0].status, "launched");

  // The name is taken: the study and every one of its runs are refused, even the runs the
  // transaction had inserted before the study's row failed.
  runs.push_back(queued("friction/003"));
  EXPECT_THROW(repo.insertStudy(study, runs).get(), std::exception);
  EXPECT_EQ(repo.listRuns().size(), 2u);
  EXPECT_EQ(repo.launchedStudies().size(), 1u);
  // Writes queued in the same batch after it still go in.
  EXPECT_GT(repo.insertRun(queued("after")).get(), ids[1]);

  repo.setStudyStatus("friction", "cancelled");
  repo.flush().get();
  EXPECT_EQ(repo.launchedStudies("friction")[0].status, "cancelled");
  repo.deleteStudy("friction");
  repo.flush().get();
  EXPECT_TRUE(repo.launchedStudies().empty());
}

TEST(Repository, UpgradesSchema9StudiesToLaunchedOnesAndStoresImportedSweeps) {
  const auto path = freshDb("schema9");
  {
    Repository repo(path);
    StudyRecord study;
    study.name = "launched-before";
    study.spec = R"({"name":"launched-before"})";
    study.createdAt = 1700000000.0;
    repo.insertStudy(study, {}).get();
  }
  {
    // What a version-9 database looked like: studies without their source, runs without the
    // CPU time of their preparation.
    Database db(path, true);
    db.exec("ALTER TABLE studies DROP COLUMN source; ALTER TABLE runs DROP COLUMN preparation_cpu_seconds; "
            "PRAGMA user_version = 9;");
  }
  Repository repo(path);
  ASSERT_EQ(repo.launchedStudies("launched-before").size(), 1u);
  // Schema 10's run column: none before, stored with the run's end after.
  const auto before = repo.insertRun(queued("before")).get();
  EXPECT_FALSE(repo.findRun(before)->preparationCpuSeconds);
  RunEnd end;
  end.status = RunStatus::Completed;
  end.cpuSeconds = 2.5;
  end.preparationCpuSeconds = 1.5;
  repo.finishRun(before, end, {});
  repo.flush().get();
  EXPECT_DOUBLE_EQ(*repo.findRun(before)->preparationCpuSeconds, 1.5);
  EXPECT_DOUBLE_EQ(*repo.listRuns().back().preparationCpuSeconds, 1.5);
  EXPECT_EQ(repo.launchedStudies("launched-before")[0].source, "launched");  // every row before 10 was

  StudyRecord sweep;
  sweep.name = "friction";
  sweep.spec = R"({"name":"friction","vary":{"material.friction":[0.3]}})";
  sweep.runs = R"([{"id":1,"name":"friction/001","parameters":{"material.friction":0.3}}])";
  sweep.createdAt = 1700000001.0;
  EXPECT_TRUE(repo.putImportedStudy(sweep).get());
  auto stored = repo.launchedStudies("friction");
  ASSERT_EQ(stored.size(), 1u);
  EXPECT_EQ(stored[0].source, "imported");
  EXPECT_EQ(stored[0].runs, sweep.runs);
  // Imported again with more runs: the same row, its runs replaced.
  sweep.runs = R"([{"id":1,"name":"friction/001"},{"id":2,"name":"friction/002"}])";
  repo.putImportedStudy(sweep).get();
  ASSERT_EQ(repo.launchedStudies().size(), 2u);
  EXPECT_EQ(repo.launchedStudies("friction")[0].runs, sweep.runs);
  // Never over a launched study's row.
  sweep.name = "launched-before";
  repo.putImportedStudy(sweep).get();
  EXPECT_EQ(repo.launchedStudies("launched-before")[0].spec, R"({"name":"launched-before"})");
  EXPECT_EQ(repo.launchedStudies("launched-before")[0].source, "launched");
  Database db(path, false);
  EXPECT_EQ(db.userVersion(), Repository::schemaVersion());
}

TEST(Repository, AppendsRunsToAStudyWithTheirIds) {
  const auto path = freshDb("append");
  Repository repo(path);
  StudyRecord study;
  study.name = "tradeoff";
  study.spec = R"({"tradeoff":{"seeds":2}})";
  study.runs = R"([{"name":"tradeoff/ref"}])";
  RunRecord ref = queued("tradeoff/ref");
  ref.study = "tradeoff";
  const auto first = repo.insertStudy(study, {ref}).get();
  RunRecord later = queued("tradeoff/later");
  later.study = "tradeoff";
  const auto ids = repo.appendStudyRuns("tradeoff", R"([{"name":"tradeoff/later"}])", {later}).get();
  ASSERT_EQ(ids.size(), 1u);
  EXPECT_EQ(repo.findRun(ids[0])->study, "tradeoff");
  EXPECT_EQ(repo.launchedStudies("tradeoff")[0].runs, R"([{"id":)" + std::to_string(first[0]) +
                                                           R"(,"name":"tradeoff/ref"},{"id":)" + std::to_string(ids[0]) +
                                                           R"(,"name":"tradeoff/later"}])");
  // No such study: nothing stored.
  EXPECT_THROW(repo.appendStudyRuns("nothing", R"([{"name":"x"}])", {queued("x")}).get(), std::exception);
  EXPECT_EQ(repo.listRuns().size(), 2u);
}

TEST(Repository, RefusesADatabaseFromANewerProgram) {
  const auto path = freshDb("newer");
  {
    Database db(path, true);
    db.exec("PRAGMA user_version = 999");
  }
  EXPECT_THROW(Repository repo(path), SqliteError);
}

}  // namespace
}  // namespace grainlab::server

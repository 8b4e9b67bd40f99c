// GET /api/runs as pages over HTTP's shape (router, service and database together): the page
// holds `limit` runs whatever the number stored, its `next` links walk every run once, the
// answer's size does not grow with the database, and bad parameters are 400s naming them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "application.hpp"
#include "fake_run.hpp"
#include "repository.hpp"
#include "router.hpp"

namespace grainlab::server {
namespace {

using nlohmann::json;

class RunsPageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("grainlab-runs-page-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "web");
    ServeOptions o;
    o.db = (dir_ / "test.db").string();
    o.webRoot = (dir_ / "web").string();
    o.runFunction = testing::fakeRun({});
    app_ = std::make_unique<Application>(o);
  }
  void TearDown() override {
    app_.reset();
    std::filesystem::remove_all(dir_);
  }
  // Finished runs as a sweep import stores them: a name, a preset, an end with its figures.
  void store(int count) {
    Repository& repo = app_->repository();
    for (int i = 0; i < count; ++i) {
      RunRecord r;
      r.name = "sweep/run-" + std::to_string(stored_);
      r.study = "sweep";
      r.preset = "circular-quick";
      r.scene = "{}";
      r.particles = 250;
      r.createdAt = 1700000000.0 + stored_++;
      auto id = repo.insertRun(r);
      RunEnd end;
      end.status = stored_ % 10 == 0 ? RunStatus::Failed : RunStatus::Completed;
      end.error = end.status == RunStatus::Failed ? "diverged" : "";
      end.finishedAt = r.createdAt + 2;
      end.wallSeconds = 1.5 + 0.001 * stored_;
      end.steps = 161171;
      end.particles = 250;
      end.peakPhiMobDeg = 31.0 + 0.01 * (stored_ % 100);
      repo.finishRun(id.get(), end, nullptr);
    }
    repo.flush().get();
  }
  ApiResponse get(const std::string& target) { return app_->router().handle({"GET", target, {}}); }
  json getJson(const std::string& target) {
    const auto r = get(target);
    EXPECT_EQ(r.status, 200) << target << " -> " << r.body;
    return json::parse(r.body);
  }

  std::filesystem::path dir_;
  std::unique_ptr<Application> app_;
  int stored_ = 0;
};

TEST_F(RunsPageTest, APageDoesNotGrowWithTheRunsStored) {
  store(200);
  const auto small = get("/api/runs?limit=50");
  const json page = json::parse(small.body);
  EXPECT_EQ(page["runs"].size(), 50u);
  EXPECT_EQ(page["total"], 200);
  EXPECT_EQ(page["limit"], 50);
  EXPECT_EQ(page["offset"], 0);
  EXPECT_EQ(page["next"], "/api/runs?limit=50&offset=50&order=desc");

  store(1800);
  const auto large = get("/api/runs?limit=50");
  const json bigPage = json::parse(large.body);
  EXPECT_EQ(bigPage["runs"].size(), 50u);
  EXPECT_EQ(bigPage["total"], 2000);
  EXPECT_EQ(bigPage["runs"][0]["id"], 2000);  // newest first
  // Ten times the runs: the page is the same 50 runs' worth of bytes (ids and figures one
  // digit longer at most), where the whole list grows tenfold.
  const double growth = std::abs(double(large.body.size()) - double(small.body.size())) / double(small.body.size());
  EXPECT_LT(growth, 0.03) << small.body.size() << " bytes at 200 runs, " << large.body.size() << " at 2000";
  // Without a limit the list is every run, as it was before it had pages.
  EXPECT_EQ(getJson("/api/runs")["runs"].size(), 2000u);
}

TEST_F(RunsPageTest, NextLinksWalkEveryMatchingRunOnce) {
  store(230);
  std::set<std::int64_t> seen;
  std::int64_t previous = 1 << 30;
  std::string target = "/api/runs?limit=40&status=completed";
  int pages = 0;
  std::int64_t total = -1;
  while (!target.empty()) {
    const json page = getJson(target);
    total = page["total"].get<std::int64_t>();
    for (const auto& run : page["runs"]) {
      EXPECT_EQ(run["status"], "completed");
      EXPECT_EQ(run["study"], "sweep");
      const auto id = run["id"].get<std::int64_t>();
      EXPECT_LT(id, previous);  // newest first across the pages
      previous = id;
      EXPECT_TRUE(seen.insert(id).second) << "run " << id << " on two pages";
    }
    target = page["next"].is_null() ? "" : page["next"].get<std::string>();
    ++pages;
  }
  EXPECT_EQ(total, 207);  // every tenth run failed
  EXPECT_EQ(static_cast<std::int64_t>(seen.size()), total);
  EXPECT_EQ(pages, 6);
}

TEST_F(RunsPageTest, ABadParameterIsA400NamingIt) {
  store(3);
  for (const auto& [target, field] : std::vector<std::pair<std::string, std::string>>{
           {"/api/runs?limit=0", "limit"},
           {"/api/runs?limit=abc", "limit"},
           {"/api/runs?offset=-5", "offset"},
           {"/api/runs?status=finished", "status"},
           {"/api/runs?sort=particles", "sort"},
           {"/api/runs?order=sideways", "order"},
           {"/api/runs?cursor=7", "cursor"}}) {
    const auto r = get(target);
    EXPECT_EQ(r.status, 400) << target;
    EXPECT_EQ(json::parse(r.body)["field"], field) << target << " -> " << r.body;
  }
  // A name filter with LIKE's wildcards finds them as characters, and the link carries it.
  const json page = getJson("/api/runs?q=run-1&limit=1");
  EXPECT_EQ(page["total"], 1);
  EXPECT_EQ(page["runs"][0]["name"], "sweep/run-1");
  EXPECT_EQ(getJson("/api/runs?q=%25")["total"], 0);
  EXPECT_EQ(getJson("/api/runs?limit=1&q=sweep%2F")["next"], "/api/runs?limit=1&offset=1&q=sweep%2F&order=desc");
}

TEST_F(RunsPageTest, StudiesCountTheirRunsByStatus) {
  store(30);  // every tenth failed: 3 of 30
  RunRecord mine;
  mine.name = "a run of no study";
  mine.scene = "{}";
  app_->repository().insertRun(mine).get();
  const json studies = getJson("/api/studies")["studies"];
  ASSERT_EQ(studies.size(), 1u);  // the run of no study is in none
  const json& sweep = studies[0];
  EXPECT_EQ(sweep["name"], "sweep");
  EXPECT_EQ(sweep["runs"], 30);
  EXPECT_EQ(sweep["by_status"], json({{"completed", 27}, {"failed", 3}}));
  EXPECT_EQ(sweep["status"], "failed");  // ended, not all of it well
  EXPECT_EQ(sweep["progress"], 1.0);
  // Its runs are one link away, and carry their study.
  const json runs = getJson(sweep["runs_url"].get<std::string>());
  EXPECT_EQ(runs["total"], 30);
  EXPECT_EQ(runs["runs"][0]["study"], "sweep");
  EXPECT_EQ(getJson("/api/studies/sweep"), sweep);
  const auto unknown = get("/api/studies/nope");
  EXPECT_EQ(unknown.status, 404);
  EXPECT_EQ(json::parse(unknown.body)["field"], "study");
  EXPECT_EQ(getJson("/api/runs?study=nope")["total"], 0);
}

}  // namespace
}  // namespace grainlab::server

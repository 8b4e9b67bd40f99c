// The runs list as a query (GET /api/runs?...): pages that partition the runs, filters that
// agree with filtering every run by hand, orders with ties broken by id, the parameters
// refused by name, and SQLite's plan: an index serves every filter and order, so a page never
// sorts or reads every run.
#include "run_query.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "api_types.hpp"
#include "repository.hpp"
#include "sqlite.hpp"

namespace grainlab::server {
namespace {

std::string freshDb(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("grainlab-run-query-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto path = dir / (name + ".db");
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path.string() + suffix);
  return path.string();
}

constexpr RunStatus kEnds[] = {RunStatus::Completed, RunStatus::Failed, RunStatus::Cancelled};

// 60 runs: three presets, two studies and runs of none, ends that cycle, some still queued,
// wall times with ties (run i takes i % 7 s), names with upper case and a literal '%'.
std::vector<std::int64_t> fill(Repository& repo) {
  std::vector<std::int64_t> ids;
  for (int i = 0; i < 60; ++i) {
    RunRecord r;
    r.study = i % 3 == 0 ? "" : (i % 3 == 1 ? "alpha" : "beta");
    r.name = (r.study.empty() ? std::string("Run-") : r.study + "/") + std::to_string(i) + (i == 7 ? "%x" : "");
    r.preset = i % 4 == 0 ? "" : (i % 4 == 1 ? "circular-quick" : "elongated-bedding-30-quick");
    r.scene = "{}";
    r.createdAt = 1700000000.0 + i;
    ids.push_back(repo.insertRun(r).get());
    if (i % 5 == 4) continue;  // stays queued
    RunEnd end;
    end.status = kEnds[i % 3];
    end.finishedAt = r.createdAt + 1;
    end.wallSeconds = i % 7;
    end.peakPhiMobDeg = 20.0 + (i * 37) % 11;
    repo.finishRun(ids.back(), end, nullptr);
  }
  repo.flush().get();
  return ids;
}

std::vector<std::int64_t> idsOf(const std::vector<RunRecord>& runs) {
  std::vector<std::int64_t> ids;
  for (const auto& r : runs) ids.push_back(r.id);
  return ids;
}

TEST(RunQuery, PagesPartitionTheRunsNewestFirst) {
  Repository repo(freshDb("pages"));
  auto ids = fill(repo);
  std::reverse(ids.begin(), ids.end());
  RunQuery q;
  q.limit = 25;
  std::vector<std::int64_t> seen;
  for (q.offset = 0; q.offset < 100; q.offset += 25) {
    const RunPage page = repo.listRuns(q);
    EXPECT_EQ(page.total, 60);
    EXPECT_EQ(page.runs.size(), static_cast<std::size_t>(std::clamp<std::int64_t>(60 - q.offset, 0, 25)));
    for (const auto& r : page.runs) {
      seen.push_back(r.id);
      EXPECT_TRUE(r.scene.empty());  // the list never carries scenes
    }
  }
  EXPECT_EQ(seen, ids);
  // Without a limit: every run, as the list was before it had pages.
  EXPECT_EQ(idsOf(repo.listRuns(RunQuery{}).runs), ids);
}

TEST(RunQuery, FiltersAgreeWithFilteringEveryRunByHand) {
  Repository repo(freshDb("filters"));
  fill(repo);
  const auto all = repo.listRuns();
  auto byHand = [&](auto keep) {
    std::vector<std::int64_t> out;
    for (auto it = all.rbegin(); it != all.rend(); ++it)
      if (keep(*it)) out.push_back(it->id);
    return out;
  };
  auto check = [&](const RunQuery& q, const std::vector<std::int64_t>& expected, const char* what) {
    const RunPage page = repo.listRuns(q);
    EXPECT_EQ(idsOf(page.runs), expected) << what;
    EXPECT_EQ(page.total, static_cast<std::int64_t>(expected.size())) << what;
    EXPECT_FALSE(expected.empty()) << what << ": a filter that keeps nothing tests nothing";
  };
  RunQuery q;
  q.statuses = {RunStatus::Failed};
  check(q, byHand([](const RunRecord& r) { return r.status == RunStatus::Failed; }), "status=failed");
  q.statuses = {RunStatus::Queued, RunStatus::Cancelled};
  check(q, byHand([](const RunRecord& r) { return r.status == RunStatus::Queued || r.status == RunStatus::Cancelled; }),
        "status=queued,cancelled");
  q = {};
  q.preset = "circular-quick";
  check(q, byHand([](const RunRecord& r) { return r.preset == "circular-quick"; }), "preset");
  q = {};
  q.study = "beta";
  check(q, byHand([](const RunRecord& r) { return r.study == "beta"; }), "study");
  q = {};
  q.nameContains = "ALPHA/1";  // case-insensitive: alpha/1, alpha/10, alpha/13, ...
  check(q, byHand([](const RunRecord& r) { return r.name.starts_with("alpha/1"); }), "q, any case");
  q.nameContains = "%";  // the character itself, not LIKE's wildcard
  check(q, byHand([](const RunRecord& r) { return r.name.find('%') != std::string::npos; }), "q=%");
  q = {};
  q.study = "alpha";
  q.statuses = {RunStatus::Failed};
  q.preset = "elongated-bedding-30-quick";
  check(q, byHand([](const RunRecord& r) {
    return r.study == "alpha" && r.status == RunStatus::Failed && r.preset == "elongated-bedding-30-quick";
  }), "three filters at once");
  // A page of a filtered list: the total is every match, the page only its part.
  q = {};
  q.statuses = {RunStatus::Completed};
  q.limit = 3;
  q.offset = 2;
  const RunPage page = repo.listRuns(q);
  const auto completed = byHand([](const RunRecord& r) { return r.status == RunStatus::Completed; });
  EXPECT_EQ(page.total, static_cast<std::int64_t>(completed.size()));
  EXPECT_EQ(idsOf(page.runs), std::vector<std::int64_t>(completed.begin() + 2, completed.begin() + 5));
}

TEST(RunQuery, OrdersBreakTiesByIdInTheSameDirection) {
  Repository repo(freshDb("orders"));
  fill(repo);
  auto all = repo.listRuns();
  for (bool descending : {false, true}) {
    RunQuery q;
    q.sort = RunSortKey::WallSeconds;
    q.descending = descending;
    auto expected = all;
    // SQLite orders NULL (a queued run's wall time) before every number.
    std::stable_sort(expected.begin(), expected.end(), [&](const RunRecord& a, const RunRecord& b) {
      const auto key = [](const RunRecord& r) { return std::make_pair(r.wallSeconds.value_or(-1.0), r.id); };
      return descending ? key(a) > key(b) : key(a) < key(b);
    });
    EXPECT_EQ(idsOf(repo.listRuns(q).runs), idsOf(expected)) << (descending ? "desc" : "asc");
  }
  RunQuery byName;
  byName.sort = RunSortKey::Name;
  byName.descending = false;
  byName.limit = 60;
  const auto named = repo.listRuns(byName).runs;
  EXPECT_TRUE(std::is_sorted(named.begin(), named.end(),
                             [](const RunRecord& a, const RunRecord& b) { return a.name < b.name; }));
  EXPECT_EQ(named.size(), 60u);
}

// What SQLite will do for a page and its count. A page must walk an index in the order asked
// for (no "USE TEMP B-TREE FOR ORDER BY": that sorts every matching run first) and a filter
// must search its index rather than read every row. The name filter is a substring, which no
// B-tree index serves: it walks the runs newest first and stops when the page is full.
TEST(RunQuery, AnIndexServesEveryFilterAndOrder) {
  Repository repo(freshDb("plans"));
  fill(repo);
  RunQuery page;
  page.limit = 50;
  for (RunSortKey key : {RunSortKey::CreatedAt, RunSortKey::Name, RunSortKey::Status, RunSortKey::Preset, RunSortKey::WallSeconds,
                         RunSortKey::PeakPhiMobDeg}) {
    for (bool descending : {false, true}) {
      RunQuery q = page;
      q.sort = key;
      q.descending = descending;
      const std::string plan = repo.queryPlan(q, false);
      EXPECT_NE(plan.find("USING INDEX runs_by_" + std::string(sortKeyName(key))), std::string::npos)
          << sortKeyName(key) << ": " << plan;
      EXPECT_EQ(plan.find("TEMP B-TREE"), std::string::npos) << sortKeyName(key) << ": " << plan;
    }
  }
  struct Filter {
    const char* index;
    RunQuery query;
  };
  std::vector<Filter> filters(3, {"", page});
  filters[0].index = "runs_by_status";
  filters[0].query.statuses = {RunStatus::Failed};
  filters[1].index = "runs_by_preset";
  filters[1].query.preset = "circular-quick";
  filters[2].index = "runs_by_study";
  filters[2].query.study = "alpha";
  for (const auto& f : filters) {
    const std::string plan = repo.queryPlan(f.query, false);
    EXPECT_NE(plan.find(std::string("SEARCH runs USING INDEX ") + f.index), std::string::npos) << plan;
    EXPECT_EQ(plan.find("TEMP B-TREE"), std::string::npos) << plan;
    const std::string count = repo.queryPlan(f.query, true);
    EXPECT_NE(count.find(std::string("SEARCH runs USING COVERING INDEX ") + f.index), std::string::npos) << count;
  }
}

// A database from before studies gets the study column and the indexes; the runs a
// sweep import stored then (SWEEP/ID, started and finished when created) join their study,
// and a run a person named with a slash does not.
TEST(RunQuery, AnOlderDatabaseGainsTheIndexesAndItsImportedStudies) {
  const auto path = freshDb("upgrade");
  std::int64_t imported = 0, live = 0;
  {
    Repository repo(path);
    RunRecord r;
    r.name = "friction/0003";
    r.scene = "{}";
    r.createdAt = 1700000000.0;
    imported = repo.insertRun(r).get();
    repo.markStarted(imported, r.createdAt);
    RunEnd end;
    end.status = RunStatus::Completed;
    end.finishedAt = r.createdAt;
    repo.finishRun(imported, end, nullptr);
    r.name = "mine/first try";
    live = repo.insertRun(r).get();
    repo.markStarted(live, r.createdAt + 0.25);
    end.finishedAt = r.createdAt + 3;
    repo.finishRun(live, end, nullptr);
    repo.flush().get();
  }
  {
    Database db(path, true);
    db.exec("ALTER TABLE runs DROP COLUMN preparation_cpu_seconds; "  // schema 10
            "ALTER TABLE runs DROP COLUMN void_ratio_after_consolidation; "  // schema 9
            "DROP INDEX runs_by_created_at; DROP INDEX runs_by_status; DROP INDEX runs_by_preset; DROP INDEX runs_by_study; "
            "DROP INDEX runs_by_study_status; DROP INDEX runs_by_name; DROP INDEX runs_by_wall_seconds; "
            "DROP INDEX runs_by_peak_phi_mob_deg; ALTER TABLE runs DROP COLUMN study; DROP TABLE studies;");
    // The version before the one that adds them (schema 7).
    db.exec("PRAGMA user_version = 6");
  }
  Repository repo(path);
  EXPECT_EQ(repo.findRun(imported)->study, "friction");
  EXPECT_EQ(repo.findRun(live)->study, "");
  RunQuery q;
  q.study = "friction";
  EXPECT_EQ(idsOf(repo.listRuns(q).runs), std::vector<std::int64_t>{imported});
  EXPECT_NE(repo.queryPlan(q, false).find("runs_by_study"), std::string::npos);
}

TEST(RunQuery, ParametersAreReadAndBadOnesRefusedByName) {
  const RunQuery q = parseRunQuery({{"limit", "50"}, {"offset", "100"}, {"status", "failed,interrupted"},
                                    {"preset", "circular-quick"}, {"study", "s"}, {"q", "a b"}, {"sort", "name"}});
  EXPECT_EQ(q.limit, 50);
  EXPECT_EQ(q.offset, 100);
  EXPECT_EQ(q.statuses, (std::vector<RunStatus>{RunStatus::Failed, RunStatus::Interrupted}));
  EXPECT_EQ(q.sort, RunSortKey::Name);
  EXPECT_FALSE(q.descending);  // a to z unless asked otherwise
  EXPECT_TRUE(parseRunQuery({}).descending);  // newest first
  EXPECT_FALSE(parseRunQuery({}).limit);
  EXPECT_TRUE(parseRunQuery({{"q", ""}, {"status", ""}}).statuses.empty());  // an empty box filters nothing
  // The next page's link asks for the same runs: read back, it is the same query.
  const RunQuery again = [&] {
    QueryParameters p;
    const std::string link = runQueryString(q, 150);
    std::string_view rest = link;
    while (!rest.empty()) {
      const auto amp = rest.find('&');
      const auto pair = rest.substr(0, amp);
      const auto eq = pair.find('=');
      std::string value(pair.substr(eq + 1));
      if (value == "a%20b") value = "a b";
      p[std::string(pair.substr(0, eq))] = value;
      if (amp == std::string_view::npos) break;
      rest.remove_prefix(amp + 1);
    }
    return parseRunQuery(p);
  }();
  EXPECT_EQ(again.offset, 150);
  EXPECT_EQ(again.limit, q.limit);
  EXPECT_EQ(again.statuses, q.statuses);
  EXPECT_EQ(again.preset, q.preset);
  EXPECT_EQ(again.study, q.study);
  EXPECT_EQ(again.nameContains, q.nameContains);
  EXPECT_EQ(again.sort, q.sort);
  EXPECT_EQ(again.descending, q.descending);

  const std::pair<QueryParameters, const char*> bad[] = {
      {{{"limit", "0"}}, "limit"},           {{{"limit", "1001"}}, "limit"},
      {{{"limit", "ten"}}, "limit"},         {{{"limit", ""}}, "limit"},
      {{{"offset", "-1"}}, "offset"},        {{{"offset", "1e3"}}, "offset"},
      {{{"status", "done"}}, "status"},      {{{"status", "failed,"}}, "status"},
      {{{"sort", "id; DROP"}}, "sort"},      {{{"order", "up"}}, "order"},
      {{{"page", "2"}}, "page"},             {{{"q", std::string(300, 'x')}}, "q"},
  };
  for (const auto& [parameters, field] : bad) {
    try {
      parseRunQuery(parameters);
      ADD_FAILURE() << field << " was accepted";
    } catch (const ApiError& e) {
      EXPECT_EQ(e.status(), 400);
      EXPECT_EQ(e.field(), field) << e.what();
    }
  }
}

}  // namespace
}  // namespace grainlab::server

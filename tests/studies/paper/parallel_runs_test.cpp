// Runs side by side compute what they compute alone; identical seeds give identical runs (a
// zero-width band), distinct seeds distinct packings; concurrency is capped by the hardware;
// a bad scene fails by itself with its reason.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "grainlab/studies/paper/ensemble_series.hpp"
#include "grainlab/studies/paper/ensemble_stats.hpp"
#include "grainlab/studies/paper/parallel_runs.hpp"
#include "grainlab/studies/paper/run_loader.hpp"

#include "../../support/file_bytes.hpp"

namespace grainlab::report {
namespace {

namespace fs = std::filesystem;

using grainlab::testing::fileBytes;

class ParallelRuns : public ::testing::Test {
 protected:
  fs::path dir = fs::temp_directory_path() /
                 ("grainlab-parallel-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void TearDown() override { fs::remove_all(dir); }
};

// A planned run of `preset` into dir/<sub>, with the preset's scene and `seed`.
PlannedRun planned(const std::string& preset, int seed, const fs::path& dir) {
  PlannedRun r = planRuns({preset}, seed, dir.string()).back();
  return r;
}

TEST_F(ParallelRuns, ResultsDoNotDependOnHowManyRunAtOnce) {
  const auto alone = executeRuns({planned("circular-quick", 1, dir / "alone")}, 1, nullptr);
  const auto together =
      executeRuns({planned("circular-quick", 1, dir / "together"), planned("demo-pile", 1, dir / "together")}, 2, nullptr);
  ASSERT_EQ(alone.at(0).status, RunStatus::Completed) << alone[0].error;
  ASSERT_EQ(together.at(0).status, RunStatus::Completed) << together[0].error;
  EXPECT_EQ(alone[0].steps, together[0].steps);
  const fs::path a = dir / "alone" / "circular-quick" / "seed-1", b = dir / "together" / "circular-quick" / "seed-1";
  EXPECT_EQ(fileBytes(a / "series.csv"), fileBytes(b / "series.csv"));
  EXPECT_EQ(fileBytes(a / "roses.json"), fileBytes(b / "roses.json"));
  EXPECT_TRUE(fs::exists(dir / "together" / "demo-pile" / "seed-1" / "summary.json"));

  // Read back from its directory, the run gives the report its series and rose snapshots.
  const AssemblyResult back = loadAssemblyResult(a.string(), "circular-quick");
  EXPECT_EQ(back.summary.status, RunStatus::Completed);
  EXPECT_EQ(back.seed, 1);
  EXPECT_DOUBLE_EQ(back.summary.voidRatioAfterConsolidation, alone[0].voidRatioAfterConsolidation);
  ASSERT_GT(back.shearing.size(), 10u);
  ASSERT_EQ(back.roses.size(), roseStrains().size());
  for (const RoseSnapshot& r : back.roses) EXPECT_TRUE(r.histograms.has_value());
}

TEST_F(ParallelRuns, SeedsAreTheScenesAndTheirOwnFolders) {
  const auto plan = planRuns({"circular-quick", "elongated-random-quick"}, 3, (dir / "runs").string());
  ASSERT_EQ(plan.size(), 6u);
  EXPECT_EQ(plan[4].id, "elongated-random-quick/seed-2");
  EXPECT_EQ(plan[4].seed, 2);
  EXPECT_EQ(plan[4].scene.at("seed"), 2);
  EXPECT_EQ(fs::path(plan[4].dir), dir / "runs" / "elongated-random-quick" / "seed-2");
  EXPECT_THROW(planRuns({"circular-quick"}, 0, dir.string()), std::invalid_argument);
  fs::create_directories(dir / "runs" / "circular-quick" / "seed-3");
  fs::create_directories(dir / "runs" / "circular-quick" / "seed-12");
  fs::create_directories(dir / "runs" / "circular-quick" / "seed-x");
  EXPECT_EQ(seedsOnDisk((dir / "runs").string(), "circular-quick"), (std::vector<int>{3, 12}));
}

TEST_F(ParallelRuns, IdenticalSeedsGiveAZeroWidthBandDistinctSeedsANarrowingOne) {
  // Three runs of seed 1 side by side, and seeds 1-8 (circular-quick, a few seconds each): the
  // void ratio after consolidation, a cheap quantity, has an interval of zero width over the
  // copies, and over distinct seeds one that narrows from 2 seeds to 8 (t·s/√n: 12.7/√2 against
  // 2.36/√8, about ten times narrower for the same scatter).
  std::vector<PlannedRun> copies;
  for (int k = 0; k < 3; ++k) {
    PlannedRun r = planned("circular-quick", 1, dir / ("copy-" + std::to_string(k)));
    copies.push_back(r);
  }
  const auto seeds = planRuns({"circular-quick"}, 8, (dir / "seeds").string());
  std::vector<PlannedRun> all = copies;
  all.insert(all.end(), seeds.begin(), seeds.end());
  const auto summaries = executeRuns(all, 2, nullptr);
  std::vector<double> same, different;
  std::vector<AssemblyResult> copyRuns;
  for (size_t k = 0; k < all.size(); ++k) {
    ASSERT_EQ(summaries[k].status, RunStatus::Completed) << summaries[k].error;
    (k < copies.size() ? same : different).push_back(summaries[k].voidRatioAfterConsolidation);
    if (k < copies.size()) {
      copyRuns.push_back(loadAssemblyResult(all[k].dir, "circular-quick"));
      copyRuns.back().seed = static_cast<int>(k) + 1;  // as if three seeds, to form an ensemble
    }
  }
  const MeanInterval zero = meanInterval(same);
  EXPECT_EQ(zero.n, 3);
  EXPECT_EQ(zero.low, zero.mean);
  EXPECT_EQ(zero.high, zero.mean);
  const MeanInterval two = meanInterval({different[0], different[1]}), eight = meanInterval(different);
  EXPECT_GT(eight.halfWidth(), 0);
  EXPECT_LT(eight.halfWidth(), two.halfWidth());
  EXPECT_DOUBLE_EQ(different[0], same[0]);  // seed 1 is seed 1
  // The figures' band over the copies has zero width at every strain, in every column.
  const auto group = groupEnsembles(copyRuns);
  ASSERT_EQ(group.size(), 1u);
  for (const char* column : {"p", "void_ratio", "a_c", "omega_macro_deg"}) {
    const EnsembleBand b = ensembleColumn(group[0], column);
    ASSERT_FALSE(b.stats.empty());
    for (const MeanInterval& m : b.stats) {
      if (m.n < 2) continue;
      EXPECT_EQ(m.low, m.mean) << column;
      EXPECT_EQ(m.high, m.mean) << column;
    }
  }
}

TEST(ConcurrentRuns, NeverMoreThanTheHardwareNorTheRuns) {
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  EXPECT_EQ(concurrentRuns(0, 6), std::min(hardware, 6u));
  EXPECT_LE(concurrentRuns(64, 6), hardware);
  EXPECT_EQ(concurrentRuns(3, 1), 1u);
  EXPECT_EQ(concurrentRuns(1, 6), 1u);
  EXPECT_EQ(concurrentRuns(0, 0), 1u);
}

TEST_F(ParallelRuns, ABadSceneFailsAloneWithItsReason) {
  PlannedRun bad = planned("circular-quick", 1, dir / "bad");
  bad.scene["material"]["friction"] = -1;
  const auto results = executeRuns({bad, planned("demo-pile", 1, dir / "good")}, 1, nullptr);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].status, RunStatus::Failed);
  EXPECT_NE(results[0].error.find("friction"), std::string::npos) << results[0].error;
  EXPECT_EQ(results[1].status, RunStatus::Completed) << results[1].error;
  EXPECT_THROW(planRuns({"no-such-preset"}, 1, dir.string()), std::exception);
}

}  // namespace
}  // namespace grainlab::report

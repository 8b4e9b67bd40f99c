// Runs side by side compute what they compute alone; concurrency is capped by the hardware;
// a bad preset fails by itself with its reason.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "grainlab/report/parallel_runs.hpp"
#include "grainlab/report/run_loader.hpp"

namespace grainlab::report {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class ParallelRuns : public ::testing::Test {
 protected:
  fs::path dir = fs::temp_directory_path() /
                 ("grainlab-parallel-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void TearDown() override { fs::remove_all(dir); }
};

TEST_F(ParallelRuns, ResultsDoNotDependOnHowManyRunAtOnce) {
  const auto alone = runAssemblies({"circular-quick"}, (dir / "alone").string(), 1, nullptr);
  const auto together = runAssemblies({"circular-quick", "demo-pile"}, (dir / "together").string(), 2, nullptr);
  ASSERT_EQ(alone.at(0).summary.status, "completed") << alone[0].summary.error;
  ASSERT_EQ(together.at(0).summary.status, "completed") << together[0].summary.error;
  EXPECT_EQ(alone[0].summary.steps, together[0].summary.steps);
  ASSERT_GT(alone[0].shearing.size(), 10u);
  for (const std::string& name : seriesColumns()) {
    const auto a = alone[0].shearing.column(name), b = together[0].shearing.column(name);
    ASSERT_EQ(a.size(), b.size()) << name;
    // Bit for bit, NaN included.
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0) << name;
  }
  EXPECT_EQ(slurp(dir / "alone" / "circular-quick" / "series.csv"),
            slurp(dir / "together" / "circular-quick" / "series.csv"));
  EXPECT_TRUE(fs::exists(dir / "together" / "demo-pile" / "summary.json"));

  // Read back from its directory, the run gives the report the same series (to the 17 digits
  // series.csv keeps) and the same rose snapshots.
  const AssemblyResult back = loadAssemblyResult((dir / "alone" / "circular-quick").string(), "circular-quick");
  EXPECT_EQ(back.summary.status, "completed");
  EXPECT_DOUBLE_EQ(back.summary.voidRatioAfterConsolidation, alone[0].summary.voidRatioAfterConsolidation);
  ASSERT_EQ(back.shearing.size(), alone[0].shearing.size());
  for (const std::string& name : seriesColumns()) {
    const auto a = alone[0].shearing.column(name), b = back.shearing.column(name);
    for (size_t r = 0; r < a.size(); ++r) {
      if (std::isnan(a[r])) EXPECT_TRUE(std::isnan(b[r])) << name << " row " << r;
      else EXPECT_DOUBLE_EQ(a[r], b[r]) << name << " row " << r;
    }
  }
  ASSERT_EQ(back.roses.size(), alone[0].roses.size());
  for (size_t k = 0; k < back.roses.size(); ++k) {
    ASSERT_TRUE(back.roses[k].histograms.has_value());
    EXPECT_DOUBLE_EQ(back.roses[k].axialStrain, alone[0].roses[k].axialStrain);
    EXPECT_EQ(back.roses[k].histograms->count, alone[0].roses[k].histograms->count);
    EXPECT_EQ(back.roses[k].histograms->fn, alone[0].roses[k].histograms->fn);
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

TEST_F(ParallelRuns, AnUnknownPresetFailsAloneWithItsReason) {
  const auto results = runAssemblies({"no-such-preset"}, dir.string(), 1, nullptr);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].summary.status, "failed");
  EXPECT_NE(results[0].summary.error.find("no-such-preset"), std::string::npos) << results[0].summary.error;
}

}  // namespace
}  // namespace grainlab::report

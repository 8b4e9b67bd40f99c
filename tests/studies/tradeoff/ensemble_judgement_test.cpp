// The ensemble trade-off's plan and judgement apart from any run (what the CLI and the server
// both call): the quick plan on the timestep axis is a reference, the baseline and one more
// setting, each paired; and planted per-seed values give tradeoff.csv the closed-form paired
// bias, interval and cost, a failed run its count and reason, and the Pareto point the mean
// over seeds of the mean |angle difference|.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "grainlab/studies/tradeoff/ensemble_judgement.hpp"
#include "grainlab/studies/tradeoff/ensemble_plan.hpp"
#include "grainlab/studies/tradeoff/ensemble_quantities.hpp"

namespace grainlab::tradeoff {
namespace {

EnsemblePlan timestepPlan() {
  TradeoffOptions opt;
  opt.quick = true;
  opt.seeds = 2;
  opt.presets = {"circular-quick"};
  opt.axes = {"timestep_safety"};
  return planEnsemble(opt);
}

// One CSV line's cells (no quoted cells in the rows looked at here).
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  return out;
}

TEST(EnsemblePlan, QuickTimestepAxisIsAReferenceAndTwoPairedSettings) {
  const EnsemblePlan plan = timestepPlan();
  ASSERT_EQ(plan.runSetting.size(), 3u);
  EXPECT_EQ(plan.settings[plan.runSetting[0]].axis, "reference");
  EXPECT_EQ(plan.settings[plan.runSetting[1]].value, "0.2");
  EXPECT_EQ(plan.settings[plan.runSetting[2]].value, "0.4");
  for (size_t r = 0; r < 3; ++r) EXPECT_TRUE(plan.paired[r]) << r;
  EXPECT_EQ(plan.referenceRun(2), 0u);

  const auto preparing = ensembleRuns(plan, true);
  ASSERT_EQ(preparing.size(), 2u);  // the reference on seeds 1 and 2
  EXPECT_EQ(preparing[1].file, "run-00-seed-2.json");
  EXPECT_EQ(preparing[1].scene["seed"], 2);
  EXPECT_TRUE(preparing[0].scene["output"]["stage_checkpoints"].get<bool>());
  const auto testing = ensembleRuns(plan, false);
  ASSERT_EQ(testing.size(), 4u);
  EXPECT_EQ(testing[0].file, "run-01-seed-1.json");
  EXPECT_TRUE(testing[3].paired);
  EXPECT_FALSE(testing[0].scene.contains("start_from"));  // the caller names the specimen
  EXPECT_EQ(preparedStage("circular-quick"), "consolidation");
}

TEST(EnsembleJudgement, PlantedValuesGiveTheClosedFormTable) {
  const EnsemblePlan plan = timestepPlan();
  const size_t n = ensembleQuantities().size();
  auto run = [&](double value, double cpu) {
    EnsembleRunResult r;
    r.status = RunStatus::Completed;
    r.values.assign(n, value);
    r.cpuSeconds = cpu;
    r.preparationCpuSeconds = 0.001;
    r.lateralStressOff = 0.01;
    return r;
  };
  // Reference 10 on both seeds; the baseline (0.2) 11 and 13: differences 1 and 3.
  std::vector<std::vector<EnsembleRunResult>> results{
      {run(10, 4.0), run(10, 6.0)}, {run(11, 1.0), run(13, 2.0)}, {run(10, 0.5), run(10, 0.5)}};
  results[2][1].status = RunStatus::Failed;
  results[2][1].error = "boom";
  results[2][1].values.assign(n, std::nan(""));

  const EnsembleTables tables = judgeEnsemble(plan, results);
  std::stringstream csv(tables.tradeoff.text());
  std::string line;
  std::getline(csv, line);
  const std::vector<std::string> header = cells(line);
  auto column = [&](const std::string& name) {
    return static_cast<size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  bool seen = false, failedSeen = false;
  while (std::getline(csv, line)) {
    const std::vector<std::string> row = cells(line);
    if (row[column("axis")] != "timestep_safety") continue;
    if (row[column("value")] == "0.2" && row[column("quantity")] == "peak_phi_mob_deg") {
      seen = true;
      // mean 2, sd √2, t(1) = 12.706: 2 ± 12.706·√2/√2.
      EXPECT_DOUBLE_EQ(std::stod(row[column("bias")]), 2.0);
      EXPECT_NEAR(std::stod(row[column("bias_ci_low")]), 2.0 - 12.706, 1e-3);
      EXPECT_NEAR(std::stod(row[column("bias_ci_high")]), 2.0 + 12.706, 1e-3);
      EXPECT_NEAR(std::stod(row[column("sd")]), std::sqrt(2.0), 1e-9);
      EXPECT_DOUBLE_EQ(std::stod(row[column("cpu_s")]), 1.5);  // the mean of its runs'
      EXPECT_EQ(row[column("failed_runs")], "0");
    }
    if (row[column("value")] == "0.4" && !failedSeen) {
      failedSeen = true;
      EXPECT_EQ(row[column("failed_runs")], "1");
      EXPECT_EQ(row[column("note")], "boom");
    }
  }
  EXPECT_TRUE(seen && failedSeen);
  EXPECT_EQ(tables.study.failedRuns, 1u);
  ASSERT_EQ(tables.study.panels.size(), 1u);
  const ParetoPoint& baseline = tables.study.panels[0].points[1];
  EXPECT_EQ(baseline.label, "0.2");
  EXPECT_DOUBLE_EQ(baseline.seconds, 1.5);
  EXPECT_DOUBLE_EQ(baseline.error, 2.0);  // seeds' mean |difference| 1 and 3
  EXPECT_EQ(tables.runs.rows(), 6u);
}

}  // namespace
}  // namespace grainlab::tradeoff

// A run's cost estimated before its first step (grainlab/run_cost.hpp): the steps follow from
// the stages and the timestep in closed form, and a scene whose cost is absurd is refused
// before anything is written, naming the field that drives the cost.
#include <gtest/gtest.h>

#include <string>

#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

class CostProbe : public RunObserver {
 public:
  void onEstimate(const RunCost& c) override {
    cost = c;
    estimated = true;
  }
  void onStart(const Scene&, const World&) override { started = true; }
  void onProgress(double, std::string_view, const World&) override { ++progressCalls; }
  bool cancelRequested() override { return true; }  // a run that is not refused stops at once
  RunCost cost;
  bool estimated = false, started = false;
  int progressCalls = 0;
};

struct Outcome {
  RunSummary summary;
  CostProbe probe;
};

Outcome run(const nlohmann::json& scene, double limitSeconds) {
  Outcome o;
  RunLimits limits;
  limits.maxSeconds = limitSeconds;
  o.summary = runScene(parseScene(scene), o.probe, limits);
  return o;
}

const double kMonth = 30 * 86400.0;

TEST(RunCost, StepsFollowFromTheStagesAndTheTimestep) {
  // circular-quick: shearing to ε22 = 0.2 at 1 /s is certain (0.2 s); compaction and
  // consolidation end on criteria, within their 1 s time limits.
  Outcome o = run(presetScene("circular-quick"), kMonth);
  ASSERT_TRUE(o.probe.estimated);
  EXPECT_TRUE(o.probe.started) << "a normal run is not refused";
  EXPECT_FALSE(o.summary.refused);
  const RunCost& c = o.probe.cost;
  EXPECT_DOUBLE_EQ(c.certainTime, 0.2);
  EXPECT_DOUBLE_EQ(c.boundedTime, 2.0);
  EXPECT_NEAR(c.certainSteps(), 0.2 / c.timestep, 1e-9 * c.certainSteps());
  EXPECT_EQ(c.field, "stages.2.strain_rate");
  EXPECT_LT(c.certainSeconds(), 3600) << "a quick preset must not look like an hour's run";
}

TEST(RunCost, AnAbsurdStiffnessIsRefusedByName) {
  nlohmann::json scene = presetScene("circular-quick");
  scene["material"]["normal_stiffness"] = 1e30;
  scene["material"]["tangential_stiffness"] = 1e30;
  Outcome o = run(scene, kMonth);
  EXPECT_TRUE(o.summary.refused);
  EXPECT_EQ(o.summary.status, RunStatus::Failed);
  EXPECT_FALSE(o.probe.started) << "a refused run writes nothing";
  EXPECT_EQ(o.summary.steps, 0);
  EXPECT_EQ(o.summary.error.rfind("material.normal_stiffness: ", 0), 0u) << o.summary.error;
  EXPECT_NE(o.summary.error.find("years"), std::string::npos) << o.summary.error;
  // The timestep scales as 1/√k: 1e30 against the preset's stiffness.
  EXPECT_LT(o.probe.cost.timestep, 1e-15);
}

TEST(RunCost, AVanishingDensityIsRefusedByName) {
  nlohmann::json scene = presetScene("circular-quick");
  scene["material"]["density"] = 1e-30;
  Outcome o = run(scene, kMonth);
  EXPECT_TRUE(o.summary.refused);
  EXPECT_EQ(o.summary.error.rfind("material.density: ", 0), 0u) << o.summary.error;
}

TEST(RunCost, ACrawlingStrainRateIsRefusedByName) {
  nlohmann::json scene = presetScene("circular-quick");
  scene["stages"][2]["strain_rate"] = 1e-12;
  scene["stages"][2]["max_time"] = 1e15;
  Outcome o = run(scene, kMonth);
  EXPECT_TRUE(o.summary.refused);
  EXPECT_EQ(o.summary.error.rfind("stages.2.strain_rate: ", 0), 0u) << o.summary.error;
}

TEST(RunCost, WithoutALimitNothingIsRefused) {
  nlohmann::json scene = presetScene("circular-quick");
  scene["material"]["normal_stiffness"] = 1e30;
  scene["material"]["tangential_stiffness"] = 1e30;
  Outcome o = run(scene, std::numeric_limits<double>::infinity());
  EXPECT_FALSE(o.summary.refused);
  EXPECT_TRUE(o.probe.started);
  EXPECT_EQ(o.summary.status, RunStatus::Cancelled) << "it started, and the probe stopped it";
}

TEST(RunCost, DurationsReadForPeople) {
  EXPECT_EQ(humanDuration(40), "40 s");
  EXPECT_EQ(humanDuration(600), "10 min");
  EXPECT_EQ(humanDuration(5 * 3600), "5.0 h");
  EXPECT_EQ(humanDuration(10 * 86400), "10 days");
  EXPECT_EQ(humanDuration(3e8 * 365.25 * 86400), "3e+08 years");
}

}  // namespace
}  // namespace grainlab

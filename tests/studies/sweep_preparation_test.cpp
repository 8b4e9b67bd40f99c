// A sweep's "prepare": which stage the specimen is, which varied paths it refuses, and the
// preparations and start_from it plans (the runs themselves: tests/studies/sweep_prepare_test.sh).
#include <gtest/gtest.h>

#include "grainlab/errors.hpp"
#include "grainlab/studies/sweep_preparation.hpp"
#include "grainlab/studies/sweep_spec.hpp"

namespace grainlab::studies {
namespace {

using ojson = nlohmann::ordered_json;

ojson spec(ojson prepare, ojson vary) {
  return {{"base", {{"preset", "circular-quick"}}}, {"prepare", prepare}, {"vary", vary}};
}

// The field prepareSweep's refusal names, or "" if it accepts.
std::string refusal(const ojson& s) {
  const SweepSpec parsed = parseSweepSpec(s);
  std::vector<SweepRun> runs = expandSweep(parsed);
  try {
    prepareSweep(parsed, runs, "out");
  } catch (const SceneError& e) {
    return e.field();
  }
  return "";
}

TEST(SweepPreparation, OneSpecimenPerSeedAndEveryRunStartsFromItsOwn) {
  const SweepSpec parsed = parseSweepSpec(spec(ojson::object(), {{"seed", {4, 9}}, {"stages.2.strain_rate", {1.0, 2.0}}}));
  std::vector<SweepRun> runs = expandSweep(parsed);
  const SweepPreparation plan = prepareSweep(parsed, runs, "out");
  EXPECT_EQ(plan.stage, "consolidation");  // {}: the stage before the first shearing stage
  ASSERT_EQ(plan.specimens.size(), 2u);
  EXPECT_EQ(plan.specimens[0].dir, std::filesystem::path("out/specimens/seed-4"));
  EXPECT_EQ(plan.specimens[1].scene["seed"], 9);
  EXPECT_EQ(plan.specimens[1].scene["stages"].size(), 2u);  // stops after the prepared stage
  EXPECT_EQ(plan.specimens[1].scene["output"]["stage_checkpoints"], true);
  ASSERT_EQ(runs.size(), 4u);
  EXPECT_EQ(runs[2].scene["start_from"]["run"], "out/specimens/seed-9");
  EXPECT_EQ(runs[2].scene["start_from"]["stage"], "consolidation");
  EXPECT_EQ(runs[2].parameters.back().first, "specimen");
  EXPECT_EQ(runs[2].parameters.back().second, "specimens/seed-9");
}

TEST(SweepPreparation, RefusesWhatWouldChangeTheSpecimenNamingThePath) {
  const ojson stage = {{"stage", "consolidation"}};
  EXPECT_EQ(refusal(spec(stage, {{"stages.2.strain_rate", {1.0, 2.0}}, {"solver.timestep_safety", {0.1, 0.2}},
                                 {"output.sample_strain", {0.01}}})),
            "");
  EXPECT_EQ(refusal(spec(stage, {{"material.friction", {0.3, 0.5}}})), "vary.material.friction");
  EXPECT_EQ(refusal(spec(stage, {{"stages.1.pressure", {1e5, 2e5}}})), "vary.stages.1.pressure");
  EXPECT_EQ(refusal(spec(stage, {{"stages.0.void_ratio", {0.3, 0.4}}})), "vary.stages.0.void_ratio");
  EXPECT_EQ(refusal(spec(stage, {{"solver.engine", {"dem", "box2d"}}})), "vary.solver.engine");
  EXPECT_EQ(refusal(spec(stage, {{"boundary.type", {"membrane"}}})), "vary.boundary.type");
  // Prepared to compaction, the consolidation may vary.
  EXPECT_EQ(refusal(spec({{"stage", "compaction"}}, {{"stages.1.pressure", {1e5, 2e5}}})), "");
  EXPECT_EQ(refusal(spec({{"stage", "settling"}}, {{"seed", {1}}})), "prepare.stage");
  EXPECT_EQ(refusal(spec({{"stage", "shearing"}}, {{"seed", {1}}})), "prepare.stage");  // nothing after it
}

TEST(SweepPreparation, ABadPrepareIsRefusedByTheSpec) {
  auto field = [](const ojson& s) {
    try {
      parseSweepSpec(s);
    } catch (const SceneError& e) {
      return e.field();
    }
    return std::string();
  };
  EXPECT_EQ(field(spec(true, {{"seed", {1}}})), "prepare");
  EXPECT_EQ(field(spec({{"stages", "x"}}, {{"seed", {1}}})), "prepare");
  EXPECT_EQ(field(spec({{"stage", 2}}, {{"seed", {1}}})), "prepare.stage");
}

}  // namespace
}  // namespace grainlab::studies

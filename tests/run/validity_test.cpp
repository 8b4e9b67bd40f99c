// The validity envelope (grainlab/validity.hpp): the presets lie inside it, each quantity's
// limits are ordered, the field blamed is the one that drives the quantity (not another it is
// combined with), closed forms hold, and a run that fails names its likeliest field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "grainlab/presets.hpp"
#include "grainlab/validity.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

Scene preset(const std::string& name, void (*edit)(nlohmann::json&) = nullptr) {
  nlohmann::json j = presetScene(name);
  if (edit) edit(j);
  return parseScene(j);
}

const ValidityWarning* find(const std::vector<ValidityWarning>& list, const std::string& quantity) {
  for (const ValidityWarning& w : list)
    if (w.quantity == quantity) return &w;
  return nullptr;
}

TEST(Validity, TheQuickPresetsAndDemoAreInsideTheHardLimits) {
  for (const std::string& name : presetNames()) {
    if (name.find("-quick") == std::string::npos && name != "circular") continue;
    const ValidityAssessment a = assessSceneValidity(preset(name), std::numeric_limits<double>::infinity());
    EXPECT_TRUE(a.refusals.empty()) << name << ": " << a.refusalMessage();
    // Only the explicit demo pile starts with a particle in a wall (a soft warning).
    for (const ValidityWarning& w : a.warnings) EXPECT_EQ(w.quantity, "initial_overlap") << name << ": " << describe(w);
  }
}

TEST(Validity, SoftLimitsLieInsideHardOnes) {
  for (const ValidityQuantity& q : validityQuantities()) {
    EXPECT_TRUE(q.upper ? q.soft < q.hard : q.soft > q.hard) << q.name;
    EXPECT_FALSE(q.softReason.empty() || q.hardReason.empty() || q.definition.empty()) << q.name;
  }
}

TEST(Validity, InertialNumberIsTheClosedFormAndBlamesTheFieldThatDrivesIt) {
  // Sheared at 4 /s: I = ε̇ d √(ρ/p), d the specimen's mean equal-area diameter (4 mm discs).
  const ValidityAssessment fast = assessSceneValidity(
      preset("circular-quick", [](nlohmann::json& j) { j["stages"][2]["strain_rate"] = 4.0; }), 1e300);
  const ValidityWarning* w = find(fast.warnings, "inertial_number");
  ASSERT_TRUE(w);
  EXPECT_EQ(w->field, "stages[2].strain_rate");
  EXPECT_NEAR(w->value, 4 * 0.004 * std::sqrt(2650 / 300e3), 1e-12);
  EXPECT_TRUE(find(fast.warnings, "lateral_servo_inertial_number"));
  // The same inertial number from a density a million times quartz's: the density is named.
  const ValidityAssessment heavy = assessSceneValidity(
      preset("circular-quick", [](nlohmann::json& j) { j["material"]["density"] = 2650e6; }), 1e300);
  ASSERT_FALSE(heavy.refusals.empty());
  const ValidityWarning* r = find(heavy.refusals, "inertial_number");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->field, "material.density");
  // Constant volume has no lateral servo to outrun.
  const ValidityAssessment volume = assessSceneValidity(
      preset("constant-volume-circular-quick", [](nlohmann::json& j) { j["stages"][2]["strain_rate"] = 4.0; }), 1e300);
  EXPECT_TRUE(find(volume.warnings, "inertial_number"));
  EXPECT_FALSE(find(volume.warnings, "lateral_servo_inertial_number"));
}

TEST(Validity, OverlapBlamesStressOrStiffnessWhicheverIsOff) {
  const ValidityAssessment loud = assessSceneValidity(
      preset("circular-quick", [](nlohmann::json& j) { j["stages"][1]["pressure"] = 3e7; }), 1e300);
  const ValidityWarning* r = find(loud.refusals, "overlap");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->field, "stages[1].pressure");
  EXPECT_DOUBLE_EQ(r->value, 2 * 3e7 / 3e8);
  const ValidityAssessment soft = assessSceneValidity(
      preset("circular-quick", [](nlohmann::json& j) { j["material"]["normal_stiffness"] = 3e6; }), 1e300);
  r = find(soft.refusals, "overlap");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->field, "material.normal_stiffness");
}

TEST(Validity, TheCostsHardLimitIsTheCallers) {
  const Scene slow = preset("circular-quick", [](nlohmann::json& j) { j["stages"][2]["strain_rate"] = 1e-6; });
  EXPECT_TRUE(assessSceneValidity(slow, std::numeric_limits<double>::infinity()).refusals.empty());
  const ValidityAssessment limited = assessSceneValidity(slow, 86400);
  const ValidityWarning* r = find(limited.refusals, "estimated_seconds");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->field, "stages[2].strain_rate");
}

TEST(Validity, AFailingRunNamesTheFieldNearestItsLimit) {
  // Three discs apart, stepped at 0.4 of the critical timestep: past the soft limit, inside
  // the hard one, and nothing else near a limit.
  auto row = [](double safety) {
    return parseScene({{"particles", {{{"radius", 0.002}, {"position", {0, 0}}},
                                      {{"radius", 0.002}, {"position", {0.005, 0}}},
                                      {{"radius", 0.002}, {"position", {0.01, 0}}}}},
                       {"stages", {{{"type", "free"}, {"duration", 0.01}}}},
                       {"solver", {{"timestep_safety", safety}}}});
  };
  auto causeOf = [](const Scene& scene) {
    World world(scene.material);
    for (const ParticleSpec& p : scene.particles) world.addParticle(p);
    world.setTimestepSafety(scene.solver.timestepSafety);
    world.initialize();
    return likelyCause(scene, world);
  };
  const std::string cause = causeOf(row(0.4));
  EXPECT_EQ(cause.rfind("solver.timestep_safety (timestep_ratio 0.4", 0), 0u) << cause;
  // Well inside every limit, nothing stands out.
  EXPECT_EQ(causeOf(row(0.05)), "");
}

TEST(Validity, WarningsRoundTripThroughJson) {
  const std::vector<ValidityWarning> warnings{{"stages[2].strain_rate", "inertial_number", 0.0015, 1e-3, "fast", -1},
                                              {"stages[2].strain_rate", "lateral_stress_error", 0.48, 0.1, "off", 90673}};
  const nlohmann::json j = warningsJson(warnings);
  EXPECT_FALSE(j[0].contains("step"));
  EXPECT_EQ(j[1]["step"], 90673);
  const std::vector<ValidityWarning> back = warningsFromJson(j);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].field, "stages[2].strain_rate");
  EXPECT_EQ(back[1].step, 90673);
  EXPECT_EQ(back[0].step, -1);
}

}  // namespace
}  // namespace grainlab

// Scene JSON of the loading paths (docs/loading-paths.md): what each stage reads, and bad
// parameters refused by the field's name.
#include <gtest/gtest.h>

#include "../support/refused_field.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"

namespace grainlab {
namespace {

using nlohmann::json;

// A membrane scene whose third stage is `stage`.
json withStage(const json& stage) {
  json scene = presetScene("circular-quick");
  scene["stages"][2] = stage;
  return scene;
}

std::string fieldOf(const json& stage) { return testing::refusedField(withStage(stage)); }

TEST(LoadingPathScene, RotationReadsTwoOfRateTotalAndDuration) {
  StageSpec s = parseScene(withStage({{"type", "rotation"}, {"deviatoric_strain_rate", 0.5},
                                      {"rotation_rate_deg_per_s", 720}, {"total_rotation_deg", 360}}))
                    .stages[2];
  EXPECT_EQ(s.type, StageSpec::Type::Rotation);
  EXPECT_DOUBLE_EQ(s.duration, 0.5);
  EXPECT_DOUBLE_EQ(s.deviatoricStrainRate, 0.5);
  EXPECT_DOUBLE_EQ(s.initialDirectionDeg, 90);  // vertical compression, as the biaxial test
  EXPECT_DOUBLE_EQ(s.pressure, 300e3);
  s = parseScene(withStage({{"type", "rotation"}, {"deviatoric_strain_rate", 1}, {"total_rotation_deg", -90},
                            {"duration", 0.3}, {"mean_stress", 1e5}, {"initial_direction_deg", 30}}))
          .stages[2];
  EXPECT_DOUBLE_EQ(s.rotationRateDeg, -300);
  EXPECT_DOUBLE_EQ(s.pressure, 1e5);
  EXPECT_DOUBLE_EQ(s.initialDirectionDeg, 30);
  EXPECT_DOUBLE_EQ(s.maxTime, 0.6);
}

TEST(LoadingPathScene, RotationRefusesByName) {
  const json base = {{"type", "rotation"}, {"deviatoric_strain_rate", 0.5}, {"rotation_rate_deg_per_s", 100}};
  EXPECT_EQ(fieldOf(base), "stages[2].duration");  // a rate alone never ends
  json j = base;
  j.erase("deviatoric_strain_rate");
  j["duration"] = 1;
  EXPECT_EQ(fieldOf(j), "stages[2].deviatoric_strain_rate");
  j = base;
  j["duration"] = 1;
  j["total_rotation_deg"] = 100;
  EXPECT_EQ(fieldOf(j), "stages[2].duration");  // over-determined
  j = base;
  j["total_rotation_deg"] = -100;
  EXPECT_EQ(fieldOf(j), "stages[2].total_rotation_deg");  // opposite sign
  j = base;
  j["rotation_rate_deg_per_s"] = 0;
  j["duration"] = 1;
  EXPECT_EQ(fieldOf(j), "stages[2].rotation_rate_deg_per_s");
  j = base;
  j["duration"] = 1;
  j["mean_stress"] = 0;
  EXPECT_EQ(fieldOf(j), "stages[2].mean_stress");
  j = base;
  j["duration"] = 1;
  j["deviatoric_strain_rate"] = -1;
  EXPECT_EQ(fieldOf(j), "stages[2].deviatoric_strain_rate");
  j = base;
  j["duration"] = 1;
  j["strain_amplitude"] = 0.01;  // a cyclic stage's field
  EXPECT_EQ(fieldOf(j), "stages[2].strain_amplitude");
}

TEST(LoadingPathScene, CyclicNeedsOneKindOfLimit) {
  const StageSpec s = parseScene(withStage({{"type", "cyclic"}, {"strain_amplitude", 0.01}, {"cycles", 3},
                                            {"lateral", "constant_volume"}}))
                          .stages[2];
  EXPECT_EQ(s.type, StageSpec::Type::Cyclic);
  EXPECT_EQ(s.cycles, 3);
  EXPECT_EQ(s.lateral, StageSpec::Lateral::ConstantVolume);
  ASSERT_TRUE(s.strainAmplitude);
  EXPECT_DOUBLE_EQ(*s.strainAmplitude, 0.01);
  const StageSpec q = parseScene(withStage({{"type", "cyclic"}, {"q_over_p_limits", {-0.1, 0.3}}, {"cycles", 1}}))
                          .stages[2];
  ASSERT_TRUE(q.qOverPLimits);
  EXPECT_DOUBLE_EQ(q.qOverPLimits->first, -0.1);
  EXPECT_DOUBLE_EQ(q.qOverPLimits->second, 0.3);

  EXPECT_EQ(fieldOf({{"type", "cyclic"}, {"cycles", 1}}), "stages[2].strain_amplitude");
  EXPECT_EQ(fieldOf({{"type", "cyclic"}, {"cycles", 1}, {"strain_amplitude", 0.01}, {"q_over_p_limits", {0, 0.3}}}),
            "stages[2].strain_amplitude");
  EXPECT_EQ(fieldOf({{"type", "cyclic"}, {"strain_amplitude", 0.01}}), "stages[2].cycles");
  EXPECT_EQ(fieldOf({{"type", "cyclic"}, {"strain_amplitude", 0.01}, {"cycles", 0}}), "stages[2].cycles");
  EXPECT_EQ(fieldOf({{"type", "cyclic"}, {"strain_amplitude", 0.01}, {"cycles", 1.5}}), "stages[2].cycles");
  EXPECT_EQ(fieldOf({{"type", "cyclic"}, {"strain_amplitude", 0}, {"cycles", 1}}), "stages[2].strain_amplitude");
  EXPECT_EQ(fieldOf({{"type", "cyclic"}, {"q_over_p_limits", {0.3, 0.1}}, {"cycles", 1}}), "stages[2].q_over_p_limits");
  EXPECT_EQ(fieldOf({{"type", "cyclic"}, {"q_over_p_limits", {-0.3, -0.1}}, {"cycles", 1}}), "stages[2].q_over_p_limits");
  EXPECT_EQ(fieldOf({{"type", "cyclic"}, {"q_over_p_limits", {-1.5, 0.3}}, {"cycles", 1}}), "stages[2].q_over_p_limits");
  EXPECT_EQ(fieldOf({{"type", "cyclic"}, {"q_over_p_limits", 0.3}, {"cycles", 1}}), "stages[2].q_over_p_limits");
}

TEST(LoadingPathScene, SimpleShearAndLateral) {
  const StageSpec s = parseScene(withStage({{"type", "simple_shear"}, {"shear_rate", 2}, {"normal_stress", 2e5}}))
                          .stages[2];
  EXPECT_EQ(s.type, StageSpec::Type::SimpleShear);
  EXPECT_DOUBLE_EQ(s.shearRate, 2);
  EXPECT_DOUBLE_EQ(s.pressure, 2e5);
  EXPECT_DOUBLE_EQ(s.targetShearStrain, 0.2);
  EXPECT_EQ(fieldOf({{"type", "simple_shear"}}), "stages[2].shear_rate");
  EXPECT_EQ(fieldOf({{"type", "simple_shear"}, {"shear_rate", 0}}), "stages[2].shear_rate");
  EXPECT_EQ(fieldOf({{"type", "simple_shear"}, {"shear_rate", 1}, {"normal_stress", -1}}), "stages[2].normal_stress");
  EXPECT_EQ(fieldOf({{"type", "simple_shear"}, {"shear_rate", 1}, {"lateral", "constant_volume"}}), "stages[2].lateral");

  EXPECT_EQ(parseScene(withStage({{"type", "biaxial"}, {"lateral", "constant_volume"}})).stages[2].lateral,
            StageSpec::Lateral::ConstantVolume);
  EXPECT_EQ(parseScene(withStage({{"type", "biaxial"}})).stages[2].lateral, StageSpec::Lateral::ConstantStress);
  EXPECT_EQ(fieldOf({{"type", "biaxial"}, {"lateral", "drained"}}), "stages[2].lateral");
  EXPECT_EQ(fieldOf({{"type", "isotropic"}, {"lateral", "constant_volume"}}), "stages[2].lateral");
}

TEST(LoadingPathScene, PathsNeedTheMembrane) {
  json j = json::parse(R"({"particles": [{"shape": "disc", "radius": 0.002, "position": [0, 0]}]})");
  j["stages"] = {{{"type", "rotation"}, {"deviatoric_strain_rate", 1}, {"total_rotation_deg", 90}, {"duration", 1}}};
  try {
    parseScene(j);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.field(), "stages[0].type");
  }
}

TEST(LoadingPathScene, EveryPathPresetHasItsQuickAndFullVersions) {
  for (const char* name : {"rotation-circular", "rotation-elongated-random", "cyclic-circular", "simple-shear-circular",
                           "constant-volume-circular"}) {
    for (const std::string suffix : {"", "-quick"}) {
      const Scene s = parseScene(presetScene(name + suffix));
      ASSERT_EQ(s.stages.size(), 3u) << name << suffix;
      EXPECT_TRUE(isShearing(s.stages[2].type)) << name << suffix;
    }
  }
  EXPECT_EQ(parseScene(presetScene("constant-volume-circular-quick")).stages[2].lateral,
            StageSpec::Lateral::ConstantVolume);
}

}  // namespace
}  // namespace grainlab

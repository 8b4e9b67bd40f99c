// Scene JSON: defaults, and errors that name the field and the reason.
#include <gtest/gtest.h>

#include <set>

#include "../support/refused_field.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"

namespace grainlab {
namespace {

using nlohmann::json;

json oneDisc() {
  return json::parse(R"({"particles": [{"shape": "disc", "radius": 0.002, "position": [0, 0]}]})");
}

std::string fieldOf(const json& j) { return testing::refusedField(j); }

TEST(Scene, DefaultsFillOmittedKeys) {
  const Scene s = parseScene(oneDisc());
  EXPECT_EQ(s.particles.size(), 1u);
  EXPECT_EQ(s.material.density, 2650);
  EXPECT_EQ(s.material.friction, 0.5);
  ASSERT_EQ(s.stages.size(), 1u);
  EXPECT_EQ(s.stages[0].type, StageSpec::Type::Free);
}

TEST(Scene, ErrorsNameTheField) {
  json j = oneDisc();
  j["material"] = {{"friction", -1}};
  EXPECT_EQ(fieldOf(j), "material.friction");
  j = oneDisc();
  j["material"] = {{"restitution", 0}};
  EXPECT_EQ(fieldOf(j), "material.restitution");
  j = oneDisc();
  j["particles"][0]["radius"] = "big";
  EXPECT_EQ(fieldOf(j), "particles[0].radius");
  j = oneDisc();
  j["particles"][0]["colour"] = "red";
  EXPECT_EQ(fieldOf(j), "particles[0].colour");
  j = oneDisc();
  j["particles"].push_back({{"shape", "polygon"}, {"vertices", {{0, 0}, {1, 0}}}});
  EXPECT_EQ(fieldOf(j), "particles[1].vertices");
  j = oneDisc();
  j["particles"].push_back({{"shape", "polygon"}, {"vertices", {{0, 0}, {1, 0}, {0.5, 0.1}, {0.5, 1}}}});
  EXPECT_EQ(fieldOf(j), "particles[1].vertices");  // not convex
  j = oneDisc();
  j["stages"] = {{{"type", "biaxial"}}};
  EXPECT_EQ(fieldOf(j), "stages[0].type");  // needs a membrane
  j = oneDisc();
  j["stages"] = {{{"type", "free"}}};
  EXPECT_EQ(fieldOf(j), "stages[0].duration");
  j = oneDisc();
  j["solver"] = {{"timestep", -1e-6}};
  EXPECT_EQ(fieldOf(j), "solver.timestep");
  j = oneDisc();
  j["gravity"] = {0};
  EXPECT_EQ(fieldOf(j), "gravity");
  j = oneDisc();
  j["typo"] = 1;
  EXPECT_EQ(fieldOf(j), "typo");
  // Rolling resistance: not negative, a positive stiffness, and for discs in the dem engine.
  for (const char* key : {"rolling_friction", "rolling_stiffness_ratio", "rolling_damping"}) {
    j = oneDisc();
    j["material"] = {{key, -0.1}};
    EXPECT_EQ(fieldOf(j), std::string("material.") + key);
  }
  j = oneDisc();
  j["material"] = {{"rolling_stiffness_ratio", 0}};
  EXPECT_EQ(fieldOf(j), "material.rolling_stiffness_ratio");
  j = oneDisc();
  j["material"] = {{"rolling_friction", 0.1}};
  EXPECT_NO_THROW(parseScene(j));
  j["particles"].push_back({{"shape", "polygon"}, {"vertices", {{0, 0}, {1, 0}, {0, 1}}}, {"position", {5, 5}}});
  EXPECT_EQ(fieldOf(j), "material.rolling_friction");
  j = presetScene("elongated-random-quick");
  j["material"]["rolling_friction"] = 0.1;
  EXPECT_EQ(fieldOf(j), "material.rolling_friction");
  // Clumps resist rolling by their shape, and their contact loop has no rolling law.
  j = presetScene("clump-random-quick");
  j["material"]["rolling_friction"] = 0.1;
  EXPECT_EQ(fieldOf(j), "material.rolling_friction");
  j = oneDisc();
  j["material"] = {{"rolling_friction", 0.1}};
  j["solver"] = {{"engine", "box2d"}};
  EXPECT_EQ(fieldOf(j), "material.rolling_friction");
  EXPECT_EQ(fieldOf(json::object()), "particles");  // an empty scene is refused
  EXPECT_EQ(fieldOf(json::array()), "(scene)");
}

TEST(Scene, EveryPresetParses) {
  for (const std::string& name : presetNames()) {
    EXPECT_NO_THROW(parseScene(presetScene(name))) << name;
  }
  try {
    presetScene("no-such-preset");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.field(), "preset");
  }
}

// The stage types' one table: each name parses back to its type, the scene parser reads the
// presets' stages as the types their names give, and every type has a preset that uses it.
TEST(Scene, StageTypeNamesRoundTripAndEveryTypeHasAPreset) {
  std::set<StageSpec::Type> seen;
  for (StageSpec::Type t : stageTypes()) EXPECT_EQ(parseStageType(toString(t)), t) << toString(t);
  EXPECT_FALSE(parseStageType("biaxal").has_value());
  for (const std::string& name : presetNames()) {
    const json j = presetScene(name);
    const Scene scene = parseScene(j);
    ASSERT_EQ(scene.stages.size(), j["stages"].size()) << name;
    for (size_t k = 0; k < scene.stages.size(); ++k) {
      EXPECT_EQ(toString(scene.stages[k].type), j["stages"][k]["type"].get<std::string>()) << name;
      seen.insert(scene.stages[k].type);
    }
  }
  EXPECT_EQ(seen.size(), stageTypes().size());
  json unknown = oneDisc();
  unknown["stages"] = json::array({{{"type", "biaxal"}}});
  EXPECT_EQ(fieldOf(unknown), "stages[0].type");
}

}  // namespace
}  // namespace grainlab

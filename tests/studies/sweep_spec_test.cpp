// Sweep specs: dotted scene paths, the spec's form, and its expansion into validated runs.
#include <gtest/gtest.h>

#include <set>

#include "grainlab/errors.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/studies/scene_path.hpp"
#include "grainlab/studies/sweep_spec.hpp"

namespace grainlab::studies {
namespace {

using ojson = nlohmann::ordered_json;

// The field a SceneError names, or "" if none is thrown.
template <class F>
std::string errorField(F&& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.field();
  }
  return "";
}

TEST(ScenePath, SetsNestedKeysAndArrayEntries) {
  nlohmann::json scene = {{"material", {{"friction", 0.5}}}, {"stages", {{{"type", "free"}}, {{"type", "free"}}}}};
  setAtPath(scene, "material.friction", 0.3);
  setAtPath(scene, "stages.1.duration", 0.01);
  setAtPath(scene, "seed", 7);
  setAtPath(scene, "output.vtk_every", 5);  // a missing object is created
  EXPECT_EQ(scene["material"]["friction"], 0.3);
  EXPECT_EQ(scene["stages"][1]["duration"], 0.01);
  EXPECT_FALSE(scene["stages"][0].contains("duration"));
  EXPECT_EQ(scene["seed"], 7);
  EXPECT_EQ(scene["output"]["vtk_every"], 5);
}

TEST(ScenePath, RefusesWhatCannotBeAField) {
  nlohmann::json scene = {{"seed", 1}, {"stages", {{{"type", "free"}}}}};
  EXPECT_THROW(setAtPath(scene, "stages.3.duration", 1), std::invalid_argument);  // out of range
  EXPECT_THROW(setAtPath(scene, "stages.first.duration", 1), std::invalid_argument);  // not an index
  EXPECT_THROW(setAtPath(scene, "seed.value", 1), std::invalid_argument);  // through a number
  EXPECT_THROW(setAtPath(scene, "material..friction", 1), std::invalid_argument);
  EXPECT_EQ(sceneFieldName("stages.2.strain_rate"), "stages[2].strain_rate");
  EXPECT_EQ(sceneFieldName("material.friction"), "material.friction");
}

ojson spec(ojson vary, const char* mode = nullptr) {
  ojson s = {{"base", {{"preset", "circular-quick"}}}, {"vary", std::move(vary)}};
  if (mode) s["mode"] = mode;
  return s;
}

TEST(SweepSpec, GridIsEveryCombinationWithTheLastAxisFastest) {
  const SweepSpec s = parseSweepSpec(spec({{"material.friction", {0.3, 0.5, 0.7}}, {"seed", {1, 2}}}));
  const std::vector<SweepRun> runs = expandSweep(s);
  ASSERT_EQ(runs.size(), 6u);
  const double friction[] = {0.3, 0.3, 0.5, 0.5, 0.7, 0.7};
  const int seed[] = {1, 2, 1, 2, 1, 2};
  std::set<std::string> ids;
  for (size_t k = 0; k < runs.size(); ++k) {
    EXPECT_EQ(runs[k].scene["material"]["friction"].get<double>(), friction[k]) << k;
    EXPECT_EQ(runs[k].scene["seed"].get<int>(), seed[k]) << k;
    EXPECT_EQ(runs[k].parameters.size(), 2u);
    EXPECT_EQ(parseScene(runs[k].scene).seed, static_cast<std::uint64_t>(seed[k]));
    ids.insert(runs[k].id);
    EXPECT_EQ(runs[k].id.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.-_="),
              std::string::npos)
        << runs[k].id;
  }
  EXPECT_EQ(ids.size(), runs.size());
  EXPECT_EQ(runs[3].id, "004-friction=0.5-seed=2");
}

TEST(SweepSpec, ZipTakesTheListsInLockstep) {
  const std::vector<SweepRun> runs =
      expandSweep(parseSweepSpec(spec({{"seed", {3, 4}}, {"stages.2.strain_rate", {1.0, 2.0}}}, "zip")));
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1].scene["seed"], 4);
  EXPECT_EQ(runs[1].scene["stages"][2]["strain_rate"], 2.0);
  EXPECT_EQ(errorField([] { parseSweepSpec(spec({{"seed", {1, 2}}, {"material.friction", {0.3}}}, "zip")); }),
            "vary.material.friction");
}

TEST(SweepSpec, ABadSpecNamesItsField) {
  EXPECT_EQ(errorField([] { parseSweepSpec(spec({{"seed", ojson::array()}})); }), "vary.seed");
  EXPECT_EQ(errorField([] { parseSweepSpec(spec({{"seed", 3}})); }), "vary.seed");
  EXPECT_EQ(errorField([] { parseSweepSpec(spec(ojson::object())); }), "vary");
  EXPECT_EQ(errorField([] { parseSweepSpec(spec({{"seed", {1}}}, "diagonal")); }), "mode");
  EXPECT_EQ(errorField([] { parseSweepSpec(spec({{"stages.9.pressure", {1}}})); }), "vary.stages.9.pressure");
  EXPECT_EQ(errorField([] {
              parseSweepSpec(ojson{{"base", {{"preset", "circular-quick"}}}, {"vary", {{"seed", {1}}}}, {"jobs", 2}});
            }),
            "jobs");
  EXPECT_EQ(errorField([] { parseSweepSpec(ojson{{"base", {{"preset", "no-such"}}}, {"vary", {{"seed", {1}}}}}); }),
            "base.preset");
}

TEST(SweepSpec, AGridOfMoreRunsThanTheLimitIsRefusedBeforeItIsBuilt) {
  // 40^6 = 4.1e9 runs: expandSweep would allocate them all (tests/server/fuzz/fuzz_sweep).
  ojson vary = ojson::object();
  ojson forty = ojson::array();
  for (int k = 1; k <= 40; ++k) forty.push_back(k);
  for (const char* path : {"seed", "material.friction", "material.density", "material.restitution",
                           "material.local_damping", "stages.0.strain_rate"})
    vary[path] = forty;
  EXPECT_EQ(errorField([&] { parseSweepSpec(spec(vary)); }), "vary");
  // 10 x 10^4 = the limit itself is a sweep; zip mode is never more than one list long.
  ojson atLimit = {{"seed", ojson::array()}, {"material.friction", ojson::array()}};
  for (int k = 0; k < 10; ++k) atLimit["seed"].push_back(k + 1);
  for (int k = 0; k < 10000; ++k) atLimit["material.friction"].push_back(0.1 + 1e-5 * k);
  EXPECT_EQ(parseSweepSpec(spec(atLimit)).axes.size(), 2u);
  EXPECT_EQ(errorField([&] { parseSweepSpec(spec(vary, "zip")); }), "");
}

TEST(SweepSpec, APathThatAnotherPathsValueBreaksIsASceneErrorNamingIt) {
  // Each path is tried alone when the spec is parsed; "seed" = 1 then leaves "seed.x" no
  // object to go into (fuzz_sweep: it escaped as std::invalid_argument).
  const ojson tiny = {{"name", "t"},
                      {"particles", {{{"shape", "disc"}, {"radius", 0.002}, {"position", {0, 0}}}}},
                      {"stages", {{{"type", "free"}, {"duration", 0.001}}}}};
  const SweepSpec s = parseSweepSpec(ojson{{"base", tiny}, {"vary", {{"seed", {1}}, {"seed.x", {1}}}}});
  EXPECT_EQ(errorField([&] { expandSweep(s); }), "vary.seed.x");
}

TEST(SweepSpec, ACombinationTheSceneRefusesIsNamedBeforeAnythingRuns) {
  // An unknown field and a value out of range are both the scene parser's word, relayed with
  // the varied path.
  EXPECT_EQ(errorField([] { expandSweep(parseSweepSpec(spec({{"material.frction", {0.3}}}))); }),
            "vary.material.frction");
  EXPECT_EQ(errorField([] { expandSweep(parseSweepSpec(spec({{"material.friction", {0.3, -1.0}}}))); }),
            "vary.material.friction");
  EXPECT_EQ(errorField([] { expandSweep(parseSweepSpec(spec({{"stages.2.strain_rate", {1.0, 0.0}}}))); }),
            "vary.stages.2.strain_rate");
  // A base whose fault is not varied is the base's.
  ojson bad = spec({{"seed", {1}}});
  bad["base"] = {{"particles", ojson::array()}, {"stages", ojson::array()}};
  EXPECT_EQ(errorField([&] { expandSweep(parseSweepSpec(bad)); }), "base.particles");
}

}  // namespace
}  // namespace grainlab::studies

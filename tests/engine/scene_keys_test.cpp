// The scene-key catalogue describes the parser: every key a preset uses is in it, a key it
// does not list is refused as unknown, and each numeric bound it states is the parser's own
// (a value just past it is refused naming the key, a value at a closed bound is accepted).
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/scene_keys.hpp"

namespace grainlab {
namespace {

using nlohmann::json;

// Every key path of a JSON scene, indices generalised ("stages[].strain_rate").
void collectPaths(const json& j, const std::string& path, std::set<std::string>& out) {
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      const std::string p = path.empty() ? key : path + "." + key;
      out.insert(p);
      collectPaths(value, p, out);
    }
  } else if (j.is_array()) {
    for (const json& item : j)
      if (item.is_object()) collectPaths(item, path + "[]", out);
  }
}

std::set<std::string> cataloguePaths() {
  std::set<std::string> paths;
  for (const SceneKey& k : sceneKeyCatalogue()) paths.insert(k.path);
  return paths;
}

TEST(SceneKeys, EveryPresetKeyIsCatalogued) {
  const std::set<std::string> catalogued = cataloguePaths();
  for (const std::string& name : presetNames()) {
    std::set<std::string> used;
    collectPaths(presetScene(name), "", used);
    for (const std::string& path : used) EXPECT_TRUE(catalogued.count(path)) << name << ": " << path;
  }
}

TEST(SceneKeys, EveryStageTypeAndBothEnginesAreReached) {
  std::set<std::string> stageTypes;
  std::set<std::string> engines;
  for (const SceneKey& k : sceneKeyCatalogue()) {
    for (const std::string& t : k.stageTypes) stageTypes.insert(t);
    if (k.path == "solver.engine") engines.insert(k.choices.begin(), k.choices.end());
  }
  for (StageSpec::Type t : grainlab::stageTypes()) EXPECT_TRUE(stageTypes.count(std::string(toString(t)))) << toString(t);
  EXPECT_EQ(engines, (std::set<std::string>{"box2d", "dem"}));
}

// The exemplar (by the catalogue's own list) that uses a key, and where to put a value in it.
json* slotFor(json& scene, const std::string& path) {
  json* at = &scene;
  std::string rest = path;
  while (!rest.empty()) {
    const size_t dot = rest.find('.');
    std::string part = rest.substr(0, dot);
    rest = dot == std::string::npos ? "" : rest.substr(dot + 1);
    const bool array = part.size() > 2 && part.substr(part.size() - 2) == "[]";
    if (array) part = part.substr(0, part.size() - 2);
    if (!at->is_object() || !at->contains(part)) return nullptr;
    at = &(*at)[part];
    if (array) {
      if (!at->is_array() || at->empty()) return nullptr;
      at = &(*at)[0];
    }
  }
  return at;
}

// The parse of `scene` with `value` at `path`: "" if accepted, else the field refused.
std::string refusedField(json scene, const std::string& path, const json& value) {
  *slotFor(scene, path) = value;
  try {
    parseScene(scene);
    return "";
  } catch (const SceneError& e) {
    return e.field();
  }
}

// The path with the first stage/particle index filled in, as the parser names it.
std::string concrete(const std::string& path) {
  std::string out = path;
  for (size_t at = out.find("[]"); at != std::string::npos; at = out.find("[]")) out.replace(at, 2, "[0]");
  return out;
}

TEST(SceneKeys, StatedBoundsAreTheParsers) {
  int checked = 0;
  for (const SceneKey& k : sceneKeyCatalogue()) {
    if (k.kind != "number" && k.kind != "integer") continue;
    // An exemplar where this key is read (by the stage type the entry is for).
    for (const auto& [name, exemplar] : sceneKeyExemplars()) {
      json scene = exemplar;
      json* slot = slotFor(scene, k.path);
      if (!slot || slot->is_null()) continue;
      if (k.path.rfind("stages[].", 0) == 0 && !k.stageTypes.empty() &&
          scene["stages"][0].value("type", "free") != k.stageTypes.front())
        continue;
      if (k.min) {
        const double below = k.kind == "integer" ? *k.min - 1 : *k.min - std::max(1e-9, std::abs(*k.min) * 1e-9);
        const json value = k.kind == "integer" ? json(static_cast<long long>(below)) : json(below);
        EXPECT_EQ(refusedField(scene, k.path, value), concrete(k.path)) << name << ": " << k.path << " = " << below;
        if (!k.minOpen && k.kind == "number") {
          const std::string at = refusedField(scene, k.path, *k.min);
          EXPECT_NE(at, concrete(k.path)) << name << ": " << k.path << " = " << *k.min << " (closed bound)";
        }
      }
      if (k.max && *k.max < 1e15) {
        const double above = k.kind == "integer" ? *k.max + 1 : *k.max * (1 + 1e-9) + 1e-12;
        const json value = k.kind == "integer" ? json(static_cast<long long>(above)) : json(above);
        EXPECT_EQ(refusedField(scene, k.path, value), concrete(k.path)) << name << ": " << k.path << " = " << above;
      }
      ++checked;
      break;
    }
  }
  EXPECT_GT(checked, 30);
}

TEST(SceneKeys, AKeyTheCatalogueDoesNotListIsRefused) {
  // Beside every catalogued key, in the object that holds it, a key the parser never reads.
  const std::set<std::string> catalogued = cataloguePaths();
  int checked = 0;
  for (const auto& [name, exemplar] : sceneKeyExemplars()) {
    std::set<std::string> used;
    collectPaths(exemplar, "", used);
    for (const std::string& path : used) {
      json scene = exemplar;
      json* holder = slotFor(scene, path);
      if (!holder || !holder->is_object()) continue;
      const std::string unknown = path + ".not_a_key";
      ASSERT_FALSE(catalogued.count(unknown));
      (*holder)["not_a_key"] = 1;
      try {
        parseScene(scene);
        ADD_FAILURE() << name << ": " << unknown << " was accepted";
      } catch (const SceneError& e) {
        EXPECT_EQ(e.reason(), "unknown key") << name << ": " << unknown;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

}  // namespace
}  // namespace grainlab

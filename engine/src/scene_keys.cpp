#include "grainlab/scene_keys.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <set>

#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"
#include "json_reader.hpp"

namespace grainlab {
namespace {

using nlohmann::json;

// A scene with a generated specimen in a membrane and the given stages, nothing else: the
// keys it leaves out are read at their defaults.
json membraneScene(const json& stages) {
  return {{"assembly", json::object()}, {"boundary", {{"type", "membrane"}}}, {"stages", stages}};
}

// A stage with only the keys its type requires.
json minimalStage(const std::string& type) {
  if (type == "free") return {{"type", "free"}, {"duration", 0.01}};
  if (type == "rotation")
    return {{"type", "rotation"}, {"deviatoric_strain_rate", 1.0}, {"rotation_rate_deg_per_s", 100.0},
            {"total_rotation_deg", 30.0}};
  if (type == "cyclic") return {{"type", "cyclic"}, {"strain_amplitude", 0.01}, {"cycles", 1}};
  if (type == "simple_shear") return {{"type", "simple_shear"}, {"shear_rate", 1.0}};
  return {{"type", type}};
}

std::string generalise(const std::string& path) {
  static const std::regex index(R"(\[[0-9]+\])");
  return std::regex_replace(path, index, "[]");
}

// The reads of one key path by one stage type, merged over the exemplars.
struct Observed {
  KeyRead read;                  // the first typed read (bounds, choices, kind)
  std::set<std::string> fallbacks;  // dumps of the fallbacks used when the key was absent
  json example;
};

int rank(const std::string& kind) { return kind == "raw" ? 0 : kind == "string" ? 1 : 2; }

class CatalogueSink : public KeyReadSink {
 public:
  void keyRead(const KeyRead& read) override {
    const std::string path = generalise(read.path);
    if (path == "stages[].type") stageType_ = read.value.is_string() ? read.value.get<std::string>() : "free";
    const std::string stage = path.rfind("stages[].", 0) == 0 ? stageType_ : "";
    Observed& o = observed_[{path, stage}];
    // A choice is read through a string, a typed key may be looked at raw first: the most
    // specific read says what the key is.
    if (o.read.kind.empty() || rank(read.kind) > rank(o.read.kind)) {
      o.read = read;
      o.fallbacks.clear();
    }
    if (rank(read.kind) == rank(o.read.kind)) {
      // An infinite fallback (no time limit) is "infinity": JSON has no number for it.
      const bool infinite = read.fallback.is_number() && !std::isfinite(read.fallback.get<double>());
      if (read.value.is_null() && read.kind != "raw") o.fallbacks.insert(infinite ? "\"infinity\"" : read.fallback.dump());
      if (o.example.is_null() && !read.value.is_null()) o.example = read.value;
    }
  }
  const std::map<std::pair<std::string, std::string>, Observed>& observed() const { return observed_; }

 private:
  std::string stageType_ = "free";
  std::map<std::pair<std::string, std::string>, Observed> observed_;
};

SceneKey describe(const std::string& path, const Observed& o) {
  SceneKey k;
  k.path = path;
  k.kind = o.read.kind;
  if (k.kind == "raw") k.kind = o.example.is_object() ? "object" : "array";
  if (o.fallbacks.size() == 1) k.defaultValue = json::parse(*o.fallbacks.begin());
  k.defaultDerived = o.fallbacks.size() > 1;
  if (o.read.bounded) {
    if (std::isfinite(o.read.min)) k.min = o.read.min;
    if (std::isfinite(o.read.max)) k.max = o.read.max;
    k.minOpen = o.read.openMin;
    k.maxOpen = o.read.openMax;
  }
  k.choices.assign(o.read.choices.begin(), o.read.choices.end());
  k.example = o.example;
  return k;
}

bool sameDescription(const SceneKey& a, const SceneKey& b) {
  return a.path == b.path && a.kind == b.kind && a.defaultValue == b.defaultValue &&
         a.defaultDerived == b.defaultDerived && a.min == b.min && a.max == b.max && a.minOpen == b.minOpen &&
         a.maxOpen == b.maxOpen && a.choices == b.choices;
}

}  // namespace

std::vector<std::pair<std::string, json>> sceneKeyExemplars() {
  std::vector<std::pair<std::string, json>> scenes;
  for (const std::string& name : presetNames()) scenes.emplace_back("preset " + name, presetScene(name));
  scenes.emplace_back("explicit disc, no other keys", json{{"particles", json::array({{{"radius", 0.001}}})}});
  scenes.emplace_back("empty material, solver, output and boundary objects",
                      json{{"particles", json::array({{{"radius", 0.001}}})},
                           {"material", json::object()},
                           {"solver", json::object()},
                           {"output", json::object()},
                           {"boundary", json::object()}});
  for (StageSpec::Type t : stageTypes()) {
    const std::string type(toString(t));
    scenes.emplace_back("minimal " + type + " stage", membraneScene(json::array({minimalStage(type)})));
  }
  scenes.emplace_back("rotation from total and duration",
                      membraneScene(json::array({{{"type", "rotation"}, {"deviatoric_strain_rate", 1.0},
                                                  {"total_rotation_deg", 90.0}, {"duration", 0.1}}})));
  scenes.emplace_back("rotation from rate and duration",
                      membraneScene(json::array({{{"type", "rotation"}, {"deviatoric_strain_rate", 1.0},
                                                  {"rotation_rate_deg_per_s", 900.0}, {"duration", 0.1}}})));
  json ownFriction = json::array();
  for (const char* type : {"isotropic", "biaxial", "rotation", "simple_shear"}) {
    json stage = minimalStage(type);
    stage["friction"] = 0.3;
    ownFriction.push_back(stage);
  }
  scenes.emplace_back("loading stages with their own friction", membraneScene(ownFriction));
  scenes.emplace_back("cyclic between stress ratios, own friction and time limit",
                      membraneScene(json::array({{{"type", "cyclic"}, {"q_over_p_limits", {-0.2, 0.3}},
                                                  {"cycles", 2}, {"lateral", "constant_volume"},
                                                  {"friction", 0.3}, {"max_time", 1.0}}})));
  scenes.emplace_back(
      "polygons and discs between walls, box2d",
      json{{"name", "exemplar"},
           {"seed", 7},
           {"particles",
            json::array({{{"shape", "polygon"},
                          {"vertices", {{-0.001, -0.001}, {0.001, -0.001}, {0.001, 0.001}, {-0.001, 0.001}}},
                          {"position", {0, 0.002}},
                          {"angle", 0.1},
                          {"velocity", {0, 0}},
                          {"spin", 0},
                          {"motion", "dynamic"},
                          {"boundary", false}},
                         {{"shape", "disc"}, {"radius", 0.001}, {"position", {0.004, 0.002}}, {"motion", "fixed"}}})},
           {"walls", json::array({{{"point", {0, 0}}, {"normal", {0, 1}}}})},
           {"gravity", {0, -9.81}},
           {"stages", json::array({{{"type", "free"}, {"name", "settle"}, {"duration", 0.01}}})},
           {"solver",
            {{"engine", "box2d"}, {"velocity_iterations", 8}, {"position_iterations", 3}, {"timestep", 1e-5},
             {"timestep_safety", 0.2}, {"threads", 1}}},
           {"output",
            {{"sample_interval", 0.001}, {"sample_strain", 0.002}, {"fabric", true}, {"histograms", true},
             {"histogram_bins", 36}, {"vtk", false}, {"vtk_every", 1}, {"checkpoint_every_s", 60}}}});
  // start_from names files that are read when the run starts, not when the scene is parsed.
  json fromRun = membraneScene(json::array({{{"type", "isotropic"}, {"name", "consolidation"}}, {{"type", "biaxial"}}}));
  fromRun["start_from"] = {{"run", "prepared-run"}, {"stage", "consolidation"}};
  fromRun["output"] = {{"stage_checkpoints", false}};
  scenes.emplace_back("started from a run's stage, no stage checkpoints", fromRun);
  json fromFile = membraneScene(json::array({{{"type", "isotropic"}}, {{"type", "biaxial"}}}));
  fromFile["start_from"] = {{"checkpoint", "prepared-run/stages/consolidation.checkpoint"}};
  scenes.emplace_back("started from a checkpoint file", fromFile);
  json fromStored = membraneScene(json::array({{{"type", "isotropic"}, {"name", "consolidation"}}, {{"type", "biaxial"}}}));
  fromStored["start_from"] = {{"run_id", 7}, {"stage", "consolidation"}};
  scenes.emplace_back("started from a run stored by grainlab serve", fromStored);
  scenes.emplace_back("elongated assembly, every recipe key",
                      json{{"assembly",
                            {{"shape", "elongated"}, {"disc_radius", 0.002}, {"long_axes", {0.0045, 0.005, 0.007}},
                             {"count_fractions", {0.3, 0.4, 0.3}}, {"aspect_ratio", 1.5}, {"vertices", 6},
                             {"orientation", "bedding"}, {"bedding_angle_deg", 30}, {"specimen_diameter", 0.06},
                             {"target_void_ratio", 0.27}, {"particle_count", 200}, {"boundary_radius", 0.0}}},
                           {"boundary", {{"type", "membrane"}}}});
  scenes.emplace_back("clumps: a clump particle, and a clump assembly",
                      json{{"particles", json::array({{{"shape", "clump"},
                                                       {"members", json::array({{{"position", {-0.0008, 0}}, {"radius", 0.001}},
                                                                                {{"position", {0.0008, 0}}, {"radius", 0.001}}})},
                                                       {"position", {0, 0.002}}}})}});
  scenes.emplace_back("explicit discs in a periodic cell of a given size",
                      json{{"particles", json::array({{{"radius", 0.001}, {"position", {0.002, 0.002}}}})},
                           {"boundary", {{"type", "periodic"}, {"size", {0.01, 0.01}}, {"rate_cap", 1.0}}}});
  scenes.emplace_back("clump assembly",
                      json{{"assembly", {{"shape", "clump"}, {"clump_discs", 3}, {"aspect_ratio", 1.732}}},
                           {"boundary", {{"type", "membrane"}}}});
  return scenes;
}

std::vector<SceneKey> sceneKeyCatalogue() {
  CatalogueSink sink;
  {
    KeyReadScope scope(sink);
    for (const auto& [name, scene] : sceneKeyExemplars()) parseScene(scene);
  }
  // One entry per key and description; the stage types that read a key alike share it.
  std::vector<SceneKey> keys;
  for (const auto& [where, o] : sink.observed()) {
    SceneKey k = describe(where.first, o);
    auto same = std::find_if(keys.begin(), keys.end(), [&](const SceneKey& e) { return sameDescription(e, k); });
    if (same == keys.end()) {
      if (!where.second.empty()) k.stageTypes.push_back(where.second);
      keys.push_back(k);
    } else {
      if (!where.second.empty()) same->stageTypes.push_back(where.second);
      if (same->example.is_null()) same->example = k.example;
    }
  }
  for (SceneKey& k : keys) {
    // Stage types in the order of the enum, the order the docs use.
    std::vector<std::string> ordered;
    for (StageSpec::Type t : stageTypes()) {
      const std::string name(toString(t));
      if (std::count(k.stageTypes.begin(), k.stageTypes.end(), name)) ordered.push_back(name);
    }
    k.stageTypes = ordered;
  }
  std::stable_sort(keys.begin(), keys.end(), [](const SceneKey& a, const SceneKey& b) { return a.path < b.path; });
  return keys;
}

json sceneKeyCatalogueJson() {
  json keys = json::array();
  for (const SceneKey& k : sceneKeyCatalogue()) {
    json j = {{"path", k.path}, {"kind", k.kind}};
    if (k.defaultValue) j["default"] = *k.defaultValue;
    if (k.defaultDerived) j["default"] = "derived";
    if (k.kind == "number" || k.kind == "integer") {
      j["min"] = k.min ? json(*k.min) : json(nullptr);
      j["max"] = k.max ? json(*k.max) : json(nullptr);
      j["min_open"] = k.minOpen;
      j["max_open"] = k.maxOpen;
    }
    if (!k.choices.empty()) j["choices"] = k.choices;
    if (!k.stageTypes.empty()) j["stage_types"] = k.stageTypes;
    j["example"] = k.example;
    keys.push_back(j);
  }
  json exemplars = json::array();
  for (const auto& [name, scene] : sceneKeyExemplars()) exemplars.push_back(name);
  return {{"keys", keys}, {"exemplars", exemplars}};
}

}  // namespace grainlab

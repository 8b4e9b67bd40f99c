#include "grainlab/studies/sweep_preparation.hpp"

#include <cstdint>
#include <map>

#include "grainlab/errors.hpp"
#include "grainlab/scene.hpp"

namespace grainlab::studies {
namespace {

namespace fs = std::filesystem;

// A varied path's pieces: "stages.2.strain_rate" (or "stages[2].strain_rate") -> stages, 2, ...
std::vector<std::string> pieces(const std::string& path) {
  std::vector<std::string> out{""};
  for (char c : path) {
    if (c == '.' || c == '[' || c == ']') {
      if (!out.back().empty()) out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  if (out.back().empty()) out.pop_back();
  return out;
}

// Why a varied path changes the specimen ("" if it only changes what is run on it).
std::string changesSpecimen(const std::string& path, size_t preparedIndex, const std::string& stage) {
  const std::vector<std::string> p = pieces(path);
  const std::string head = p.empty() ? "" : p.front();
  if (head == "seed" || head == "name" || head == "output") return {};
  if (head == "solver") {
    if (p.size() >= 2 && p[1] != "engine") return {};
    return "the specimen's contacts belong to its solver.engine";
  }
  if (head == "stages" && p.size() >= 3) {
    size_t index = 0;
    try {
      index = std::stoul(p[1]);
    } catch (const std::exception&) {
      return "it is not a stage's index";
    }
    if (index > preparedIndex) return {};
    return "stage " + std::to_string(index) + " is prepared once, as the specimen ('" + stage + "' is stage " +
           std::to_string(preparedIndex) + ")";
  }
  return "the specimen is prepared once per seed with the base's " + (head.empty() ? path : head) +
         " (a sweep with \"prepare\" varies only seed and what runs after the prepared stage: "
         "the later stages, solver settings and output)";
}

}  // namespace

SweepPreparation prepareSweep(const SweepSpec& spec, std::vector<SweepRun>& runs, const fs::path& outDir) {
  SweepPreparation out;
  if (runs.empty()) return out;
  const Scene first = parseScene(runs.front().scene);
  size_t index = first.stages.size();
  if (spec.prepareStage.empty()) {
    for (size_t k = 1; k < first.stages.size() && index == first.stages.size(); ++k)
      if (isShearing(first.stages[k].type)) index = k - 1;
    if (index == first.stages.size())
      throw SceneError("prepare.stage", "the base has no shearing stage to prepare before: name the stage");
  } else {
    std::string names;
    for (size_t k = 0; k < first.stages.size(); ++k) {
      if (first.stages[k].name == spec.prepareStage) index = k;
      names += (names.empty() ? "" : ", ") + first.stages[k].name;
    }
    if (index == first.stages.size())
      throw SceneError("prepare.stage", "the base has no stage '" + spec.prepareStage + "' (its stages: " + names + ")");
  }
  out.stage = first.stages[index].name;
  if (index + 1 >= first.stages.size())
    throw SceneError("prepare.stage", "'" + out.stage + "' is the base's last stage: nothing would run on the specimen");
  for (const SweepAxis& axis : spec.axes) {
    const std::string why = changesSpecimen(axis.path, index, out.stage);
    if (!why.empty())
      throw SceneError("vary." + axis.path, "changes the specimen \"prepare\" makes once per seed: " + why);
  }

  std::map<std::uint64_t, std::string> specimenOf;  // seed -> folder under outDir
  for (SweepRun& run : runs) {
    const std::uint64_t seed = parseScene(run.scene).seed;
    auto [it, isNew] = specimenOf.emplace(seed, "specimens/seed-" + std::to_string(seed));
    if (isNew) {
      // The base's own preparation with this seed, stopped after the prepared stage; it keeps
      // that stage's end whatever the engine (box2d keeps none unless asked).
      nlohmann::json scene = spec.base;
      scene["seed"] = seed;
      nlohmann::json stages = nlohmann::json::array();
      for (size_t k = 0; k <= index; ++k) stages.push_back(runs.front().scene["stages"][k]);  // alike in every run
      scene["stages"] = stages;
      scene["output"]["stage_checkpoints"] = true;
      out.specimens.push_back({it->second, outDir / it->second, scene});
    }
    run.scene["start_from"] = {{"run", (outDir / it->second).string()}, {"stage", out.stage}};
    run.parameters.emplace_back("specimen", it->second);
  }
  return out;
}

}  // namespace grainlab::studies

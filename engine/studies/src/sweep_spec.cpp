#include "grainlab/studies/sweep_spec.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/studies/scene_path.hpp"

namespace grainlab::studies {
namespace {

// An ordered_json value as a plain json value (numbers keep every bit through dump/parse).
nlohmann::json plain(const nlohmann::ordered_json& value) { return nlohmann::json::parse(value.dump()); }

nlohmann::json resolveBase(const nlohmann::ordered_json& base) {
  if (!base.is_object()) throw SceneError("base", "must be a scene object or {\"preset\": NAME}");
  if (!base.contains("preset")) return plain(base);
  if (base.size() != 1)
    throw SceneError("base", "give either {\"preset\": NAME} alone or a whole scene (grainlab preset NAME prints one to edit)");
  if (!base["preset"].is_string()) throw SceneError("base.preset", "must be a preset's name");
  try {
    return presetScene(base["preset"].get<std::string>());
  } catch (const SceneError& e) {
    throw SceneError("base.preset", e.reason());
  }
}

// A value as it reads in a directory name: letters, digits, '.', '-' and '_' only.
std::string nameSafe(const nlohmann::json& value) {
  const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
  std::string out;
  for (char c : text) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                      c == '-' || c == '_';
    out += keep ? c : '_';
  }
  return out;
}

std::string runId(size_t index, size_t total, const std::vector<std::pair<std::string, nlohmann::json>>& parameters) {
  const size_t width = std::max<size_t>(3, std::to_string(total).size());
  std::string number = std::to_string(index + 1);
  std::string id = std::string(width - number.size(), '0') + number;
  for (const auto& [path, value] : parameters) {
    const size_t dot = path.rfind('.');
    id += '-';  // (appended piece by piece: gcc 12 warns falsely on a chain of operator+)
    id += path.substr(dot == std::string::npos ? 0 : dot + 1);
    id += '=';
    id += nameSafe(value);
  }
  constexpr size_t kMaxIdLength = 96;  // the number alone keeps ids unique; the rest is for reading
  if (id.size() > kMaxIdLength) id.resize(kMaxIdLength);
  return id;
}

// Which varied path the scene parser's field belongs to ("" if none).
std::string variedPathOf(const std::string& field, const std::vector<SweepAxis>& axes) {
  for (const SweepAxis& axis : axes) {
    const std::string name = sceneFieldName(axis.path);
    if (field == name || field.starts_with(name + ".") || field.starts_with(name + "[")) return axis.path;
  }
  return {};
}

std::string describe(const std::vector<std::pair<std::string, nlohmann::json>>& parameters) {
  std::string text;
  for (const auto& [path, value] : parameters) text += (text.empty() ? "" : ", ") + path + " = " + value.dump();
  return text;
}

}  // namespace

SweepSpec parseSweepSpec(const nlohmann::ordered_json& spec) {
  if (!spec.is_object()) throw SceneError("(spec)", "a sweep spec is a JSON object with base, vary and mode");
  for (const auto& [key, value] : spec.items()) {
    if (key != "base" && key != "vary" && key != "mode" && key != "name" && key != "prepare")
      throw SceneError(key, "unknown key (a sweep spec has base, vary, mode, name and prepare)");
  }
  SweepSpec out;
  out.source = spec;
  if (!spec.contains("base")) throw SceneError("base", "missing: give {\"preset\": NAME} or a scene");
  out.base = resolveBase(spec["base"]);
  if (spec.contains("prepare")) {  // checked against the runs by prepareSweep
    const auto& prepare = spec["prepare"];
    const bool form = prepare.is_object() && prepare.size() <= 1 && (prepare.empty() || prepare.contains("stage"));
    if (!form) throw SceneError("prepare", "give {\"stage\": NAME}, or {} for the stage before the first shearing stage");
    if (prepare.contains("stage") && (!prepare["stage"].is_string() || prepare["stage"].get<std::string>().empty()))
      throw SceneError("prepare.stage", "must be a stage's name");
    out.prepare = true;
    out.prepareStage = prepare.value("stage", std::string());
  }

  const std::string mode = spec.contains("mode") && spec["mode"].is_string() ? spec["mode"].get<std::string>() : "";
  if (!spec.contains("mode") || mode == "grid") out.mode = SweepMode::Grid;
  else if (mode == "zip") out.mode = SweepMode::Zip;
  else throw SceneError("mode", "must be \"grid\" (every combination) or \"zip\" (the lists in lockstep)");

  if (!spec.contains("vary") || !spec["vary"].is_object() || spec["vary"].empty())
    throw SceneError("vary", "give at least one scene path with a list of values, e.g. {\"seed\": [1, 2, 3]}");
  for (const auto& [path, values] : spec["vary"].items()) {
    const std::string field = "vary." + path;
    if (!values.is_array()) throw SceneError(field, "must be a list of values");
    if (values.empty()) throw SceneError(field, "empty list: give at least one value");
    SweepAxis axis{path, {}};
    for (const auto& v : values) axis.values.push_back(plain(v));
    try {
      nlohmann::json probe = out.base;
      setAtPath(probe, path, axis.values.front());
    } catch (const std::invalid_argument& e) {
      throw SceneError(field, e.what());
    }
    out.axes.push_back(std::move(axis));
  }
  if (out.mode == SweepMode::Grid) {
    // Counted before anything is built: six lists of 40 values make 4.1e9 runs, which
    // expandSweep would try to allocate at once (found by tests/server/fuzz/fuzz_sweep).
    double runs = 1;  // (a double: the product of the lists' lengths cannot overflow it)
    std::string product;
    for (const SweepAxis& axis : out.axes) {
      runs *= static_cast<double>(axis.values.size());
      product += (product.empty() ? "" : " x ") + std::to_string(axis.values.size());
    }
    if (runs > static_cast<double>(kMaxSweepRuns)) {
      char count[32];
      std::snprintf(count, sizeof count, "%.3g", runs);
      throw SceneError("vary", "the grid has " + std::string(count) + " runs (" + product + "), more than the " +
                                   std::to_string(kMaxSweepRuns) +
                                   " a sweep may have: give fewer values, or vary them together with \"mode\": \"zip\"");
    }
  }
  if (out.mode == SweepMode::Zip) {
    for (const SweepAxis& axis : out.axes) {
      if (axis.values.size() != out.axes.front().values.size())
        throw SceneError("vary." + axis.path, "has " + std::to_string(axis.values.size()) + " values but vary." +
                                                  out.axes.front().path + " has " +
                                                  std::to_string(out.axes.front().values.size()) +
                                                  ": zip mode takes lists of one length");
    }
  }
  return out;
}

SweepSpec loadSweepSpec(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SceneError("(file)", "cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::ordered_json spec;
  try {
    spec = nlohmann::ordered_json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw SceneError("(json)", std::string("not valid JSON: ") + e.what());
  }
  return parseSweepSpec(spec);
}

std::vector<SweepRun> expandSweep(const SweepSpec& spec) {
  try {
    parseScene(spec.base);
  } catch (const SceneError& e) {
    // The varied values may repair what the base lacks; only a base error on a path that is
    // not varied is the base's fault.
    if (variedPathOf(e.field(), spec.axes).empty()) throw SceneError("base." + e.field(), e.reason());
  }
  size_t count = spec.mode == SweepMode::Zip ? spec.axes.front().values.size() : 1;
  if (spec.mode == SweepMode::Grid) {
    for (const SweepAxis& axis : spec.axes) count *= axis.values.size();
  }
  std::vector<SweepRun> runs;
  runs.reserve(count);
  for (size_t k = 0; k < count; ++k) {
    SweepRun run;
    run.scene = spec.base;
    size_t rest = k;  // grid: k in mixed radix, the last axis least significant
    std::vector<size_t> pick(spec.axes.size());
    for (size_t a = spec.axes.size(); a-- > 0;) {
      if (spec.mode == SweepMode::Zip) {
        pick[a] = k;
      } else {
        pick[a] = rest % spec.axes[a].values.size();
        rest /= spec.axes[a].values.size();
      }
    }
    for (size_t a = 0; a < spec.axes.size(); ++a) {
      const nlohmann::json& value = spec.axes[a].values[pick[a]];
      run.parameters.emplace_back(spec.axes[a].path, value);
      try {
        setAtPath(run.scene, spec.axes[a].path, value);
      } catch (const std::invalid_argument& e) {
        // parseSweepSpec tried each path alone with its first value; here another path's
        // value may have changed what this one goes through ("seed" = 2, then "seed.x").
        throw SceneError("vary." + spec.axes[a].path,
                         "run " + std::to_string(k + 1) + " (" + describe(run.parameters) + "): " + e.what());
      }
    }
    try {
      parseScene(run.scene);
    } catch (const SceneError& e) {
      const std::string varied = variedPathOf(e.field(), spec.axes);
      throw SceneError(varied.empty() ? "vary" : "vary." + varied,
                       "run " + std::to_string(k + 1) + " (" + describe(run.parameters) + "): " + e.field() + ": " +
                           e.reason());
    }
    run.id = runId(k, count, run.parameters);
    runs.push_back(std::move(run));
  }
  return runs;
}

}  // namespace grainlab::studies

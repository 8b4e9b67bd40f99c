#include "grainlab/studies/shape_fidelity/representation.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"

namespace grainlab::shapes {
namespace {

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

[[noreturn]] void refuse(const std::string& name, const std::string& why) {
  throw SceneError("--representations", "\"" + name + "\": " + why +
                                            " (expected hexagons, clumps-N with N in 2..8, rolling-MU with MU > 0, or discs)");
}

}  // namespace

std::string Representation::name() const {
  switch (shape) {
    case Shape::Hexagons: return "hexagons";
    case Shape::Clumps: return "clumps-" + std::to_string(clumpDiscs);
    case Shape::RollingDiscs: return "rolling-" + number(rollingFriction);
    case Shape::Discs: return "discs";
  }
  return {};
}

Representation parseRepresentation(const std::string& name) {
  Representation r;
  if (name == "hexagons") return r;
  if (name == "discs") {
    r.shape = Shape::Discs;
    return r;
  }
  auto tail = [&](const std::string& prefix) { return name.substr(prefix.size()); };
  if (name.starts_with("clumps-")) {
    r.shape = Shape::Clumps;
    size_t used = 0;
    try {
      r.clumpDiscs = std::stoi(tail("clumps-"), &used);
    } catch (const std::exception&) {
      refuse(name, "the discs per clump are not a whole number");
    }
    if (used != tail("clumps-").size()) refuse(name, "the discs per clump are not a whole number");
    if (r.clumpDiscs < 2 || r.clumpDiscs > 8) refuse(name, "a clump here has 2 to 8 discs");
    return r;
  }
  if (name.starts_with("rolling-")) {
    r.shape = Shape::RollingDiscs;
    size_t used = 0;
    try {
      r.rollingFriction = std::stod(tail("rolling-"), &used);
    } catch (const std::exception&) {
      refuse(name, "the rolling friction is not a number");
    }
    if (used != tail("rolling-").size()) refuse(name, "the rolling friction is not a number");
    if (!(r.rollingFriction > 0) || !std::isfinite(r.rollingFriction)) refuse(name, "the rolling friction must be > 0");
    return r;
  }
  refuse(name, "unknown representation");
}

const std::vector<std::string>& shapeAssemblies() {
  static const std::vector<std::string> a{"random", "bedding-30"};
  return a;
}

std::string representationPreset(const Representation& r, const std::string& assembly, bool quick) {
  std::string preset;
  switch (r.shape) {
    case Shape::Hexagons: preset = "elongated-" + assembly; break;
    case Shape::Clumps: preset = "clump-" + assembly; break;
    case Shape::RollingDiscs: preset = "circular-rolling"; break;
    case Shape::Discs: preset = "circular"; break;
  }
  return quick ? preset + "-quick" : preset;
}

nlohmann::json representationScene(const Representation& r, const std::string& assembly, bool quick, int seed) {
  nlohmann::json scene = presetScene(representationPreset(r, assembly, quick));
  if (r.shape == Shape::Clumps) scene["assembly"]["clump_discs"] = r.clumpDiscs;
  if (r.shape == Shape::RollingDiscs) scene["material"]["rolling_friction"] = r.rollingFriction;
  scene["seed"] = seed;
  scene["name"] = scene["name"].get<std::string>() + " as " + r.name() + ", seed " + std::to_string(seed);
  return scene;
}

}  // namespace grainlab::shapes

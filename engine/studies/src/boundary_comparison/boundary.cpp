#include "grainlab/studies/boundary_comparison/boundary.hpp"

#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"

namespace grainlab::boundaries {

std::string boundaryName(Boundary b) {
  switch (b) {
    case Boundary::Ring: return "ring";
    case Boundary::Cell: return "cell";
    case Boundary::CellMatched: return "cell-matched";
  }
  return {};
}

Boundary parseBoundary(const std::string& name) {
  for (Boundary b : {Boundary::Ring, Boundary::Cell, Boundary::CellMatched})
    if (boundaryName(b) == name) return b;
  throw SceneError("--boundaries", "\"" + name + "\" is not one of ring, cell, cell-matched");
}

const std::vector<std::string>& boundaryAssemblies() {
  static const std::vector<std::string> a{"circular", "bedding-30"};
  return a;
}

std::string boundaryPreset(Boundary b, const std::string& assembly, bool quick) {
  const std::string specimen = assembly == "circular" ? "circular" : "elongated-" + assembly;
  const std::string preset = b == Boundary::Ring ? specimen : "periodic-biaxial-" + specimen;
  return quick ? preset + "-quick" : preset;
}

nlohmann::json boundaryScene(Boundary b, const std::string& assembly, bool quick, int seed, double axialStrain) {
  nlohmann::json scene = presetScene(boundaryPreset(b, assembly, quick));
  for (nlohmann::json& stage : scene["stages"]) {
    // In the cell, frictionless compaction jams the grains at their densest (no ring's void
    // ratio ends it); compacted with friction they lock at the ring's looser packing.
    if (b == Boundary::CellMatched && stage.value("name", "") == "compaction")
      stage["friction"] = scene["material"]["friction"];
    if (axialStrain > 0 && stage.value("type", "") == "biaxial") stage["target_axial_strain"] = axialStrain;
  }
  scene["seed"] = seed;
  scene["name"] = scene["name"].get<std::string>() + " (" + boundaryName(b) + "), seed " + std::to_string(seed);
  return scene;
}

}  // namespace grainlab::boundaries

#pragma once
// The particle representations `grainlab shapes` compares, and the scene each one runs: the
// paper's hexagon presets (the reference), clumps of N discs in a line, discs with rolling
// resistance, and plain discs, on the paper's random and bedding-30 assemblies.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace grainlab::shapes {

enum class Shape { Hexagons, Clumps, RollingDiscs, Discs };

struct Representation {
  Shape shape = Shape::Hexagons;
  int clumpDiscs = 0;          ///< Clumps: discs per clump (2..8)
  double rollingFriction = 0;  ///< RollingDiscs: μ_r
  /// "hexagons", "clumps-3", "rolling-0.1", "discs": the CSV's `representation` and the run
  /// files' names.
  std::string name() const;
  /// Discs, rolling or not, have no orientation to lay out: one ensemble serves both assemblies.
  bool carriesFabric() const { return shape == Shape::Hexagons || shape == Shape::Clumps; }
};

/// "hexagons", "clumps-N", "rolling-X" or "discs" back to a representation; throws
/// SceneError("--representations", ...) saying what it expected.
Representation parseRepresentation(const std::string& name);

/// The assemblies compared: "random" and "bedding-30".
const std::vector<std::string>& shapeAssemblies();

/// The preset the representation runs for `assembly` (quick or full size): elongated-<assembly>,
/// clump-<assembly>, circular-rolling or circular, with "-quick" for the quick size.
std::string representationPreset(const Representation& r, const std::string& assembly, bool quick);

/// That preset's scene with the representation applied (assembly.clump_discs, or
/// material.rolling_friction) and `seed`. The clumps keep the preset's length over width, the
/// hexagons' √3, which every clump of 2 discs or more can take.
nlohmann::json representationScene(const Representation& r, const std::string& assembly, bool quick, int seed);

}  // namespace grainlab::shapes

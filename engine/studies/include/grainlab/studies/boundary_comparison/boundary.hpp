#pragma once
// The boundaries `grainlab boundaries` sets side by side: the paper's membrane ring, the
// periodic cell, and the cell prepared to the ring's density. Each is a preset's scene with a
// seed, so every run prepares its own specimen.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace grainlab::boundaries {

enum class Boundary {
  Ring,         ///< the membrane ring: circular-quick, elongated-bedding-30-quick
  Cell,         ///< the periodic cell: periodic-biaxial-*-quick, compacted without friction
  CellMatched,  ///< the cell compacted with the material's friction: the ring's void ratio
};

/// "ring", "cell", "cell-matched".
std::string boundaryName(Boundary b);
/// Throws SceneError at "--boundaries" for any other name.
Boundary parseBoundary(const std::string& name);

/// The assemblies compared: "circular" and "bedding-30".
const std::vector<std::string>& boundaryAssemblies();

/// The preset a boundary runs for an assembly, e.g. "periodic-biaxial-elongated-bedding-30-quick".
std::string boundaryPreset(Boundary b, const std::string& assembly, bool quick);

/// The preset's scene with `seed`; CellMatched sets the compaction stage's friction to the
/// material's. `axialStrain` > 0 ends the shearing there instead (shortened runs for tests).
nlohmann::json boundaryScene(Boundary b, const std::string& assembly, bool quick, int seed, double axialStrain = 0);

}  // namespace grainlab::boundaries

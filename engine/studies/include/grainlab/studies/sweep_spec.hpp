#pragma once
// A sweep: a base scene, the scene paths to vary with their values, and how to combine
// them. `grainlab sweep` reads one from a spec file (docs/sweeps.md):
//   { "base": { "preset": "circular-quick" } | SCENE,
//     "vary": { "material.friction": [0.3, 0.5], "seed": [1, 2, 3] },
//     "mode": "grid" | "zip",
//     "prepare": { "stage": "consolidation" } }      (optional: one specimen per seed)
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace grainlab::studies {

/// One varied scene path and its values, in the order given.
struct SweepAxis {
  std::string path;                      ///< dotted, e.g. "stages.2.strain_rate"
  std::vector<nlohmann::json> values;
};

enum class SweepMode {
  Grid,  ///< every combination; the last axis varies fastest
  Zip,   ///< the lists in lockstep (all of one length)
};

struct SweepSpec {
  nlohmann::ordered_json source;  ///< the spec as given: sweep.json keeps it, a resume compares it
  nlohmann::json base;            ///< the base scene (a preset already resolved)
  std::vector<SweepAxis> axes;    ///< in the order of "vary"
  SweepMode mode = SweepMode::Grid;
  bool prepare = false;           ///< "prepare": each seed's specimen made once (sweep_preparation.hpp)
  std::string prepareStage;       ///< its stage; empty = the stage before the first shearing stage
};

/// One run of a sweep: its scene and the values it was given.
struct SweepRun {
  std::string id;  ///< its directory's name: "003-friction=0.5-seed=2"
  std::vector<std::pair<std::string, nlohmann::json>> parameters;  ///< (path, value), in axis order
  nlohmann::json scene;
};

/// The most runs a sweep may have: more is a mistake in the spec (every run takes seconds at
/// least), and its runs would not fit in memory.
inline constexpr std::size_t kMaxSweepRuns = 100000;

/// Checks the spec's form (not yet the scenes it makes). Throws SceneError naming the spec's
/// field ("base", "vary.material.friction", "mode") and the reason; a grid of more than
/// kMaxSweepRuns runs is refused on "vary".
SweepSpec parseSweepSpec(const nlohmann::ordered_json& spec);
/// Reads a spec file; a file that cannot be read or is not JSON is a SceneError on "(file)"/"(json)".
SweepSpec loadSweepSpec(const std::string& path);

/// Every run of the sweep, each scene validated as `grainlab run` would. Throws SceneError
/// for the first run whose scene is refused, naming the varied path (or "base.<field>" when
/// the base scene itself is bad) and the scene parser's reason.
std::vector<SweepRun> expandSweep(const SweepSpec& spec);

}  // namespace grainlab::studies

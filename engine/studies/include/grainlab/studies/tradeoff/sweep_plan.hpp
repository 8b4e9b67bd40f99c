#pragma once
// The settings `grainlab tradeoff` sweeps, and the scene each one runs: a preset's scene
// JSON (presetScene) with one knob turned.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace grainlab::tradeoff {

/// One point of the sweep.
struct Setting {
  std::string preset;
  /// Which knob this point turns: "reference", "noise" (the baseline with a 1% longer
  /// timestep: how far chaos alone moves the measures), "timestep_safety",
  /// "inertial_number", "vertices", "sample_strain", "engine" or "box2d" (the box2d engine's
  /// own knobs: its velocity iterations and its timestep).
  std::string axis;
  std::string value;              ///< the knob's value as shown in the CSV and the plot
  double timestepSafety = 0.2;    ///< fraction of the critical timestep
  double inertialNumber = 1e-3;   ///< target I = ε̇ d √(ρ/p) of the shearing stage
  double sampleStrain = 0.005;    ///< axial strain between shearing samples
  int vertices = 0;               ///< polygon vertex count; 0 = the preset's (and for discs)
  std::string engine = "dem";
  int velocityIterations = 0;     ///< box2d's velocity iterations; 0 = the engine's default
  /// Same scene, so the same run: the baseline appears on every axis but runs once.
  bool sameRun(const Setting& other) const;
};

/// What to sweep, around which baseline, against which reference.
struct SweepPlan {
  std::vector<std::string> presets;
  std::vector<double> timestepSafeties, inertialNumbers, sampleStrains;
  std::vector<int> vertexCounts;            ///< for presets with polygons only
  Setting baseline, reference;              ///< preset and axis are filled per point
  bool noiseProbe = true;
  bool engineAxis = true;                   ///< try solver.engine "box2d"
  /// box2d's own knobs, around the baseline run through box2d (only with the engine axis).
  std::vector<int> box2dVelocityIterations;
  std::vector<double> box2dTimestepSafeties;
};

/// Timestep safety 0.05..0.4, I 1e-2..1e-4, vertices 4/6/8, sample strain 0.001..0.01, the
/// box2d engine with 4 and 20 velocity iterations and at safety 0.06 and 0.6, on
/// circular-quick and elongated-bedding-30-quick; reference: safety 0.05, I = 1e-4,
/// sample strain 0.001.
SweepPlan fullPlan();
/// A few seconds' worth on circular-quick, for the test: two values per axis.
SweepPlan quickPlan();

/// Keeps only the named axes of the plan (timestep_safety, inertial_number, vertices,
/// sample_strain, engine — which includes box2d's own knobs — and noise); the reference always
/// runs. Throws SceneError("--axes", ...) naming an axis it does not know.
void keepAxes(SweepPlan& plan, const std::vector<std::string>& axes);

/// Every point of the plan, the reference of each preset first. `box2dRefusal`, if set, is
/// why the parser refused the box2d engine: the engine axis is then left out.
std::vector<Setting> expandPlan(const SweepPlan& plan, const std::optional<std::string>& box2dRefusal);

/// The preset's scene with the setting applied; the shearing strain rate is the one that
/// gives the setting's inertial number (strainRateFor).
nlohmann::json settingScene(const Setting& setting);

/// ε̇ = I / (d √(ρ/p)) for the scene's first biaxial stage: d is the mean equal-area diameter
/// of its generated specimen, ρ its density and p the stage's confining pressure. 1/s.
double strainRateFor(const nlohmann::json& scene, double inertialNumber);

/// The preset's polygon vertex count; 0 for discs.
int presetVertices(const std::string& preset);

/// Why the scene parser refuses solver.engine "box2d" for `preset`; nullopt if it accepts it.
std::optional<std::string> box2dRefusal(const std::string& preset);

}  // namespace grainlab::tradeoff

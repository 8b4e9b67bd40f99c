#include "grainlab/studies/tradeoff/sweep_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/shape.hpp"
#include "grainlab/specimen.hpp"

namespace grainlab::tradeoff {
namespace {

using nlohmann::json;

std::string text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

json& biaxialStage(json& scene) {
  for (json& stage : scene["stages"]) {
    if (stage.value("type", "") == toString(StageSpec::Type::Biaxial)) return stage;
  }
  throw SceneError("stages", "the scene has no biaxial stage to shear");
}

}  // namespace

int presetVertices(const std::string& preset) {
  const json scene = presetScene(preset);
  if (!scene.contains("assembly") || scene["assembly"].value("shape", "disc") == "disc") return 0;
  return scene["assembly"].value("vertices", 6);
}

bool Setting::sameRun(const Setting& o) const {
  return preset == o.preset && timestepSafety == o.timestepSafety && inertialNumber == o.inertialNumber &&
         sampleStrain == o.sampleStrain && vertices == o.vertices && engine == o.engine &&
         velocityIterations == o.velocityIterations;
}

SweepPlan fullPlan() {
  SweepPlan p;
  p.presets = {"circular-quick", "elongated-bedding-30-quick"};
  p.timestepSafeties = {0.05, 0.1, 0.2, 0.4};
  p.inertialNumbers = {1e-2, 3e-3, 1e-3, 3e-4, 1e-4};
  p.sampleStrains = {0.001, 0.002, 0.005, 0.01};
  p.vertexCounts = {4, 6, 8};
  // box2d's default is 8 iterations at safety 0.2 (its step 10x the DEM's): the engine axis.
  p.box2dVelocityIterations = {4, 20};
  p.box2dTimestepSafeties = {0.06, 0.6};
  p.baseline.timestepSafety = 0.2;
  p.baseline.inertialNumber = 1e-3;
  p.baseline.sampleStrain = 0.005;
  p.reference.timestepSafety = 0.05;
  p.reference.inertialNumber = 1e-4;
  p.reference.sampleStrain = 0.001;
  return p;
}

SweepPlan quickPlan() {
  SweepPlan p;
  p.presets = {"circular-quick"};
  p.timestepSafeties = {0.2, 0.4};
  p.inertialNumbers = {1e-2, 3e-3};
  p.sampleStrains = {0.005, 0.01};
  p.box2dVelocityIterations = {20};
  p.baseline.timestepSafety = 0.2;
  p.baseline.inertialNumber = 1e-2;
  p.baseline.sampleStrain = 0.01;
  p.reference.timestepSafety = 0.1;
  p.reference.inertialNumber = 3e-3;
  p.reference.sampleStrain = 0.005;
  p.noiseProbe = false;
  return p;
}

void keepAxes(SweepPlan& plan, const std::vector<std::string>& axes) {
  static const std::vector<std::string> known{"timestep_safety", "inertial_number", "vertices", "sample_strain",
                                              "engine", "noise"};
  for (const std::string& a : axes) {
    if (std::find(known.begin(), known.end(), a) == known.end()) {
      throw SceneError("--axes", "unknown axis \"" + a +
                                     "\" (timestep_safety, inertial_number, vertices, sample_strain, engine, noise)");
    }
  }
  const auto kept = [&](const char* axis) { return std::find(axes.begin(), axes.end(), axis) != axes.end(); };
  if (!kept("timestep_safety")) plan.timestepSafeties.clear();
  if (!kept("inertial_number")) plan.inertialNumbers.clear();
  if (!kept("vertices")) plan.vertexCounts.clear();
  if (!kept("sample_strain")) plan.sampleStrains.clear();
  if (!kept("engine")) plan.engineAxis = false;
  if (!kept("noise")) plan.noiseProbe = false;
}

std::vector<Setting> expandPlan(const SweepPlan& plan, const std::optional<std::string>& box2dRefusal) {
  std::vector<Setting> out;
  for (const std::string& preset : plan.presets) {
    Setting ref = plan.reference;
    ref.preset = preset;
    ref.axis = "reference";
    ref.value = "safety " + text(ref.timestepSafety) + ", I " + text(ref.inertialNumber) + ", sample " +
                text(ref.sampleStrain);
    out.push_back(ref);
    Setting base = plan.baseline;
    base.preset = preset;
    if (plan.noiseProbe) {
      Setting noise = base;
      noise.axis = "noise";
      noise.timestepSafety = 1.01 * base.timestepSafety;
      noise.value = "baseline at safety " + text(noise.timestepSafety);
      out.push_back(noise);
    }
    auto add = [&](const std::string& axis, const std::string& value, auto&& turn) {
      Setting s = base;
      s.axis = axis;
      s.value = value;
      turn(s);
      out.push_back(s);
    };
    for (double v : plan.timestepSafeties) add("timestep_safety", text(v), [&](Setting& s) { s.timestepSafety = v; });
    for (double v : plan.inertialNumbers) add("inertial_number", text(v), [&](Setting& s) { s.inertialNumber = v; });
    if (const int own = presetVertices(preset); own > 0) {
      // The preset's own count is the baseline's run, not another one.
      for (int v : plan.vertexCounts) {
        add("vertices", std::to_string(v), [&](Setting& s) { s.vertices = v == own ? 0 : v; });
      }
    }
    for (double v : plan.sampleStrains) add("sample_strain", text(v), [&](Setting& s) { s.sampleStrain = v; });
    if (plan.engineAxis && !box2dRefusal) {
      add("engine", "dem", [](Setting&) {});
      add("engine", "box2d", [](Setting& s) { s.engine = "box2d"; });
      for (int v : plan.box2dVelocityIterations) {
        add("box2d", "velocity_iterations " + std::to_string(v), [&](Setting& s) {
          s.engine = "box2d";
          s.velocityIterations = v;
        });
      }
      for (double v : plan.box2dTimestepSafeties) {
        add("box2d", "timestep_safety " + text(v), [&](Setting& s) {
          s.engine = "box2d";
          s.timestepSafety = v;
        });
      }
    }
  }
  return out;
}

double strainRateFor(const json& sceneJson, double inertialNumber) {
  const Scene scene = parseScene(sceneJson);
  if (!scene.assembly) throw SceneError("assembly", "the inertial number needs a generated specimen");
  const Specimen specimen = generateSpecimen(*scene.assembly, scene.seed);
  double diameters = 0;
  for (int k = 0; k < specimen.specimenCount; ++k) {
    const ParticleSpec& p = specimen.particles[static_cast<size_t>(k)];
    const double area = p.shape == ShapeKind::Disc ? discArea(p.radius) : makePolygon(p.vertices).area;
    diameters += 2 * std::sqrt(area / kPi);
  }
  const double d = diameters / specimen.specimenCount;
  for (const StageSpec& stage : scene.stages) {
    if (stage.type == StageSpec::Type::Biaxial) {
      return inertialNumber / (d * std::sqrt(scene.material.density / stage.pressure));
    }
  }
  throw SceneError("stages", "the scene has no biaxial stage to shear");
}

json settingScene(const Setting& s) {
  json scene = presetScene(s.preset);
  scene["name"] = s.preset + " " + s.axis + " " + s.value;
  scene["solver"]["timestep_safety"] = s.timestepSafety;
  scene["solver"]["engine"] = s.engine;
  if (s.velocityIterations > 0) scene["solver"]["velocity_iterations"] = s.velocityIterations;
  scene["output"]["sample_strain"] = s.sampleStrain;
  if (s.vertices > 0) scene["assembly"]["vertices"] = s.vertices;
  biaxialStage(scene)["strain_rate"] = strainRateFor(scene, s.inertialNumber);
  return scene;
}

std::optional<std::string> box2dRefusal(const std::string& preset) {
  json scene = presetScene(preset);
  scene["solver"]["engine"] = "box2d";
  try {
    parseScene(scene);
  } catch (const SceneError& e) {
    return e.field() + ": " + e.reason();
  }
  return std::nullopt;
}

}  // namespace grainlab::tradeoff

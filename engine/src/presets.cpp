#include "grainlab/presets.hpp"

#include "grainlab/errors.hpp"
#include "specimen_shapes.hpp"

namespace grainlab {
namespace {

using nlohmann::json;

// The paper's material: quartz-like density; k_n chosen so that the mean contact overlap at
// p = 300 kPa is about 1e-3 of the particle size. For discs the mean normal force is
// f ≈ 2π r p / (Z φ) ≈ 1.2 kN/m (r = 2 mm, Z ≈ 4, φ ≈ 0.8), so δ = 4 µm needs k_n ≈ 3e8 N/m;
// k_t = k_n/2. Restitution 0.5 and a light local damping make consolidation settle without
// affecting the quasi-static shearing, where the inertial number stays ~2e-4.
json paperMaterial() {
  return {{"density", 2650.0}, {"normal_stiffness", 3e8}, {"tangential_stiffness", 1.5e8},
          {"friction", 0.5}, {"restitution", 0.5}, {"local_damping", 0.1}};
}

// The paper's stages. Compaction, frictionless, stops when "the particles get close to each
// other as much as possible and no inter-force exists": at a void ratio of 0.40 inside the
// ring, one rule for every assembly, where p is still 0.002-0.3% of the confining stress.
// Compacting further (to 3 kPa, the earlier end) jams the frictionless packing at its densest
// and left e = 0.19-0.21 after consolidation against the paper's 0.26-0.28; from 0.40 the
// frictional consolidation builds the packing (docs/biaxial-test.md, "Preparation"). The
// 3 kPa end stays as a backstop for a specimen that jams looser than 0.40.
json paperStages(double shearRate) {
  return json::array({
      {{"type", "compaction"}, {"name", "compaction"}, {"void_ratio", 0.40}, {"pressure", 3e3},
       {"strain_rate", 2.0}, {"friction", 0.0}},
      {{"type", "isotropic"}, {"name", "consolidation"}, {"pressure", 300e3}, {"strain_rate", 0.5}},
      {{"type", "biaxial"}, {"name", "shearing"}, {"pressure", 300e3}, {"strain_rate", shearRate},
       {"target_axial_strain", 0.2}},
  });
}

// The paper's elongated hexagons (aspect ratio 1.5 of their ellipse, 6 vertices): their long
// axis over their smallest width, √3 (1.732). A clump of discs in a line is given the same.
double hexagonLengthOverWidth() {
  return 1.0 / specimen::polygonMinWidth(specimen::ellipsePolygon(1.0, 1.5, 6));
}

json paperAssembly(const std::string& kind, bool quick) {
  json a;
  if (kind.starts_with("clump:")) {
    // Three discs in a line with the hexagons' sizes (long axes), grading and length over width.
    a = {{"shape", "clump"}, {"clump_discs", 3}, {"aspect_ratio", hexagonLengthOverWidth()}};
    const std::string orientation = kind.substr(6);
    if (orientation == "random") {
      a["orientation"] = "random";
    } else {
      a["orientation"] = "bedding";
      a["bedding_angle_deg"] = std::stod(orientation);
    }
  } else if (kind == "circular") {
    a = {{"shape", "disc"}, {"disc_radius", 0.002}};
  } else {
    a = {{"shape", "elongated"}, {"aspect_ratio", 1.5}, {"vertices", 6}};
    if (kind == "random") {
      a["orientation"] = "random";
    } else {
      a["orientation"] = "bedding";
      a["bedding_angle_deg"] = std::stod(kind);
    }
  }
  a["specimen_diameter"] = quick ? 0.06 : 0.160;
  return a;
}

json paperScene(const std::string& name, const std::string& kind, bool quick) {
  return {{"name", name},
          {"seed", 1},
          {"material", paperMaterial()},
          {"assembly", paperAssembly(kind, quick)},
          {"boundary", {{"type", "membrane"}}},
          {"stages", paperStages(quick ? 1.0 : 0.5)},
          {"solver", {{"engine", "dem"}, {"timestep_safety", 0.2}}},
          {"output", {{"sample_strain", quick ? 0.005 : 0.002}, {"fabric", true}, {"histograms", true}}}};
}

// The loading paths of docs/loading-paths.md: the paper's preparation (compaction,
// consolidation to 300 kPa), then one path in place of the biaxial shearing. The quick ones
// shear at the quick biaxial preset's rate, so each costs about what it does.
json pathStage(const std::string& path, bool quick) {
  const double rate = quick ? 1.0 : 0.5;
  if (path == "rotation") {
    // One full turn of the strain-rate axes over a deviatoric strain of 0.3 (ε̇1 − ε̇3 × t):
    // the first 30-60° build the stress up from isotropic, the rest is the turning itself
    // (docs/loading-paths.md).
    return {{"type", "rotation"}, {"name", "rotation"}, {"deviatoric_strain_rate", rate},
            {"total_rotation_deg", 360.0}, {"duration", 0.3 / rate}, {"mean_stress", 300e3},
            {"initial_direction_deg", 90.0}};
  }
  if (path == "cyclic") {
    return {{"type", "cyclic"}, {"name", "cyclic"}, {"pressure", 300e3}, {"strain_rate", rate},
            {"strain_amplitude", 0.01}, {"cycles", 3}};
  }
  if (path == "simple-shear") {
    return {{"type", "simple_shear"}, {"name", "simple shear"}, {"shear_rate", rate}, {"normal_stress", 300e3},
            {"target_shear_strain", 0.3}};
  }
  return {{"type", "biaxial"}, {"name", "constant volume"}, {"lateral", "constant_volume"}, {"strain_rate", rate},
          {"target_axial_strain", 0.2}};
}

json pathScene(const std::string& name, const std::string& path, const std::string& kind, bool quick) {
  json scene = paperScene(name, kind, quick);
  scene["stages"][2] = pathStage(path, quick);
  return scene;
}

// Each path on the circular specimen, and the rotation also on the elongated random one
// (the non-coaxiality the paper finds there is the question a rotation asks further).
const std::vector<std::pair<std::string, std::pair<std::string, std::string>>>& pathPresets() {
  static const std::vector<std::pair<std::string, std::pair<std::string, std::string>>> presets{
      {"rotation-circular", {"rotation", "circular"}},
      {"rotation-elongated-random", {"rotation", "random"}},
      {"cyclic-circular", {"cyclic", "circular"}},
      {"simple-shear-circular", {"simple-shear", "circular"}},
      {"constant-volume-circular", {"constant-volume", "circular"}}};
  return presets;
}

// The circular assembly whose discs resist rolling (docs/shape-fidelity.md): the paper's
// material with μ_r = 0.1, a common starting value for discs standing in for angular grains
// (not calibrated here to the hexagons' strength), and the rolling damper at η_r = 0.3, the
// ratio Ai et al. (2011) use.
json rollingScene(const std::string& name, bool quick) {
  json scene = paperScene(name, "circular", quick);
  scene["material"]["rolling_friction"] = 0.1;
  scene["material"]["rolling_damping"] = 0.3;
  return scene;
}

// A pile of discs settling under gravity in a box: the demo, and the speed benchmark's scene.
json demoPile() {
  json particles = json::array();
  const double r = 0.002;
  for (int row = 0; row < 20; ++row) {
    for (int col = 0; col < 20; ++col) {
      const double x = -0.042 + col * 2.2 * r + (row % 2) * 1.1 * r;
      const double y = r * 1.2 + row * 2.2 * r;
      particles.push_back({{"shape", "disc"}, {"radius", r * (0.9 + 0.1 * ((row * 7 + col * 3) % 5) / 4.0)},
                           {"position", {x, y}}});
    }
  }
  return {{"name", "demo-pile"},
          {"seed", 1},
          {"material", paperMaterial()},
          {"particles", particles},
          {"walls", json::array({{{"point", {0, 0}}, {"normal", {0, 1}}},
                                 {{"point", {-0.045, 0}}, {"normal", {1, 0}}},
                                 {{"point", {0.045, 0}}, {"normal", {-1, 0}}}})},
          {"gravity", {0, -9.81}},
          {"stages", json::array({{{"type", "free"}, {"name", "settling"}, {"duration", 0.3}}})},
          {"output", {{"sample_interval", 0.01}}}};
}

// The paper's assembly and stages in a periodic cell (docs/periodic-cell.md): the same recipe
// placed in a square cell, compacted without friction by the isotropic servos to 3 kPa (the
// ring's compaction backstop; the cell has no ring to stop at a void ratio) at a cap of
// 0.25 /s, where the inertial number at 3 kPa stays below 1e-3, consolidated to 300 kPa with
// friction, then sheared at constant σ11 as in the ring.
// A path other than "biaxial" replaces the shearing as the ring's path presets do.
// The cell's rotation is stress-controlled (the ring's turns the strain rate): the stress is
// brought to q = 0.3 p at θ0 = 90° (vertical major stress; φ_mob = 17.5°, about half the
// circular specimen's peak, docs/biaxial-test.md), then its axes make half a turn, which brings
// the stress tensor back to where it started.
json cellRotationStage(bool quick) {
  return {{"type", "rotation"}, {"name", "rotation"}, {"mean_stress", 300e3}, {"deviatoric_stress", 90e3},
          {"initial_direction_deg", 90.0}, {"total_rotation_deg", 180.0}, {"duration", quick ? 0.3 : 0.6}};
}

json periodicScene(const std::string& name, const std::string& path, const std::string& kind, bool quick) {
  json scene = path == "biaxial" ? paperScene(name, kind, quick) : pathScene(name, path, kind, quick);
  if (path == "rotation") scene["stages"][2] = cellRotationStage(quick);
  // A quick cell is wider than the quick ring's 0.06 m specimen: in a cell of 177 discs, about
  // 13 diameters across, chains spanning the cell along the compression lock and collapse
  // (docs/periodic-cell.md, "Presets", measured).
  if (quick) scene["assembly"]["specimen_diameter"] = 0.11;
  scene["boundary"] = {{"type", "periodic"}};
  // The dense cell dilates at its peak faster than 3 /s when sheared at the quick 1 /s: under
  // that cap σ11 strayed by up to 75 % (seeds 1-4); at 10 /s by at most 1.6 %, with an inertial
  // number of at most 2e-3 (docs/periodic-cell.md, "Presets").
  if (quick) scene["boundary"]["rate_cap"] = 10.0;
  scene["stages"][0] = {{"type", "isotropic"}, {"name", "compaction"}, {"pressure", 3e3}, {"strain_rate", 0.25},
                        {"friction", 0.0}, {"max_time", 4.0}};
  return scene;
}

const std::vector<std::pair<std::string, std::pair<std::string, std::string>>>& periodicPresets() {
  static const std::vector<std::pair<std::string, std::pair<std::string, std::string>>> presets{
      {"periodic-biaxial-circular", {"biaxial", "circular"}},
      {"periodic-biaxial-elongated-bedding-30", {"biaxial", "30"}},
      {"periodic-rotation-circular", {"rotation", "circular"}},
      {"periodic-simple-shear-circular", {"simple-shear", "circular"}}};
  return presets;
}

const std::vector<std::pair<std::string, std::string>>& paperPresets() {
  static const std::vector<std::pair<std::string, std::string>> presets{
      {"circular", "circular"},           {"elongated-random", "random"},
      {"elongated-bedding-0", "0"},       {"elongated-bedding-30", "30"},
      {"elongated-bedding-60", "60"},     {"elongated-bedding-90", "90"},
      {"clump-random", "clump:random"},   {"clump-bedding-30", "clump:30"}};
  return presets;
}

}  // namespace

std::vector<std::string> presetNames() {
  std::vector<std::string> names;
  for (const auto& p : paperPresets()) names.push_back(p.first);
  for (const auto& p : paperPresets()) names.push_back(p.first + "-quick");
  for (const auto& p : pathPresets()) names.push_back(p.first);
  for (const auto& p : pathPresets()) names.push_back(p.first + "-quick");
  for (const auto& p : periodicPresets()) names.push_back(p.first);
  for (const auto& p : periodicPresets()) names.push_back(p.first + "-quick");
  names.push_back("circular-rolling");
  names.push_back("circular-rolling-quick");
  names.push_back("demo-pile");
  return names;
}

json presetScene(const std::string& name) {
  for (const auto& [preset, kind] : paperPresets()) {
    if (name == preset) return paperScene(name, kind, false);
    if (name == preset + "-quick") return paperScene(name, kind, true);
  }
  for (const auto& [preset, what] : pathPresets()) {
    if (name == preset) return pathScene(name, what.first, what.second, false);
    if (name == preset + "-quick") return pathScene(name, what.first, what.second, true);
  }
  for (const auto& [preset, what] : periodicPresets()) {
    if (name == preset) return periodicScene(name, what.first, what.second, false);
    if (name == preset + "-quick") return periodicScene(name, what.first, what.second, true);
  }
  if (name == "circular-rolling" || name == "circular-rolling-quick") return rollingScene(name, name.ends_with("-quick"));
  if (name == "demo-pile") return demoPile();
  throw SceneError("preset", "unknown preset \"" + name + "\" (grainlab presets lists them)");
}

}  // namespace grainlab

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "grainlab/errors.hpp"
#include "grainlab/scene.hpp"
#include "json_reader.hpp"
#include "start_from_json.hpp"

namespace grainlab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Material parseMaterial(const nlohmann::json& j) {
  Material m;
  if (j.is_null()) return m;
  JsonReader r(j, "material");
  m.density = r.number("density", m.density, 0, kInf, true);
  m.normalStiffness = r.number("normal_stiffness", m.normalStiffness, 0, kInf, true);
  m.tangentialStiffness = r.number("tangential_stiffness", m.tangentialStiffness, 0, kInf, true);
  m.friction = r.number("friction", m.friction, 0, kInf);
  m.restitution = r.number("restitution", m.restitution, 0, 1, true);
  m.localDamping = r.number("local_damping", m.localDamping, 0, 1, false, true);
  m.rollingFriction = r.number("rolling_friction", m.rollingFriction, 0, kInf);
  m.rollingStiffnessRatio = r.number("rolling_stiffness_ratio", m.rollingStiffnessRatio, 0, kInf, true);
  m.rollingDamping = r.number("rolling_damping", m.rollingDamping, 0, 1);
  r.finish();
  return m;
}

// A clump's member discs: [{"position": [x, y], "radius": r}, ...], positions relative to the
// particle's position.
std::vector<ClumpMember> parseClumpMembers(const nlohmann::json& j, const std::string& path) {
  if (!j.is_array() || j.empty()) {
    throw SceneError(path, "a clump needs members [{\"position\": [x, y], \"radius\": r}, ...]");
  }
  std::vector<ClumpMember> members;
  for (size_t k = 0; k < j.size(); ++k) {
    JsonReader m(j[k], path + "[" + std::to_string(k) + "]");
    if (!m.has("radius")) throw SceneError(m.fieldPath("radius"), "a clump member needs a radius");
    ClumpMember member;
    member.radius = m.number("radius", 0, 0, kInf, true);
    member.centre = m.vec2("position", member.centre);
    m.finish();
    members.push_back(member);
  }
  try {
    makeClump(members);
  } catch (const std::invalid_argument& e) {
    throw SceneError(path, e.what());
  }
  return members;
}

ParticleSpec parseParticle(const nlohmann::json& j, const std::string& path) {
  JsonReader r(j, path);
  ParticleSpec p;
  const std::string shape = r.choice("shape", "disc", {"disc", "polygon", "clump"});
  if (shape == "clump") {
    p.shape = ShapeKind::Clump;
    p.members = parseClumpMembers(r.raw("members"), r.fieldPath("members"));
  } else if (shape == "disc") {
    p.shape = ShapeKind::Disc;
    if (!r.has("radius")) throw SceneError(r.fieldPath("radius"), "a disc needs a radius");
    p.radius = r.number("radius", 0, 0, kInf, true);
  } else {
    p.shape = ShapeKind::Polygon;
    const nlohmann::json& vs = r.raw("vertices");
    const std::string vpath = r.fieldPath("vertices");
    if (!vs.is_array()) throw SceneError(vpath, "a polygon needs vertices [[x, y], ...]");
    for (size_t k = 0; k < vs.size(); ++k) p.vertices.push_back(parseVec2(vs[k], vpath + "[" + std::to_string(k) + "]"));
    try {
      makePolygon(p.vertices);
    } catch (const std::invalid_argument& e) {
      throw SceneError(vpath, e.what());
    }
  }
  p.position = r.vec2("position", p.position);
  p.angle = r.number("angle", 0, -kInf, kInf);
  p.velocity = r.vec2("velocity", p.velocity);
  p.spin = r.number("spin", 0, -kInf, kInf);
  const std::string motion = r.choice("motion", "dynamic", {"dynamic", "fixed", "kinematic"});
  p.motion = motion == "dynamic" ? Motion::Dynamic : motion == "fixed" ? Motion::Fixed : Motion::Kinematic;
  p.boundary = r.boolean("boundary", false);
  r.finish();
  return p;
}

Wall parseWall(const nlohmann::json& j, const std::string& path) {
  JsonReader r(j, path);
  Wall w;
  w.point = r.vec2("point", w.point);
  w.normal = r.vec2("normal", w.normal);
  if (w.normal.norm() == 0) throw SceneError(r.fieldPath("normal"), "must not be zero");
  w.normal.normalize();
  r.finish();
  return w;
}

StageSpec::Lateral parseLateral(JsonReader& r) {
  const std::string lateral = r.choice("lateral", "constant_stress", {"constant_stress", "constant_volume"});
  return lateral == "constant_volume" ? StageSpec::Lateral::ConstantVolume : StageSpec::Lateral::ConstantStress;
}

// How the ring's rotation is driven: the strain-rate axes turn at a deviatoric strain rate.
void parseRingRotationDrive(JsonReader& r, StageSpec& s) {
  if (!r.has("deviatoric_strain_rate")) {
    throw SceneError(r.fieldPath("deviatoric_strain_rate"), "a rotation stage needs a deviatoric_strain_rate (ε̇1 − ε̇3, 1/s)");
  }
  s.deviatoricStrainRate = r.number("deviatoric_strain_rate", 0, 0, kInf, true);
  s.pressure = r.number("mean_stress", 300e3, 0, kInf, true);
}

// How the cell's rotation is driven: the stress turns at constant p and q, and the strain rate
// that follows is measured, so it takes a deviatoric stress instead of a strain rate.
void parseCellRotationDrive(JsonReader& r, StageSpec& s) {
  if (r.has("deviatoric_strain_rate")) {
    throw SceneError(r.fieldPath("deviatoric_strain_rate"),
                     "a rotation in a periodic cell is stress-controlled: give deviatoric_stress (q, Pa); the strain "
                     "rate is measured");
  }
  if (!r.has("deviatoric_stress")) {
    throw SceneError(r.fieldPath("deviatoric_stress"),
                     "a rotation in a periodic cell needs the deviatoric stress q = (σ1 − σ2)/2 it holds, in Pa");
  }
  s.pressure = r.number("mean_stress", 300e3, 0, kInf, true);
  s.deviatoricStress = r.number("deviatoric_stress", 0, 0, kInf, true);
  if (s.deviatoricStress >= s.pressure) {
    throw SceneError(r.fieldPath("deviatoric_stress"),
                     "must be below mean_stress (" + std::to_string(s.pressure) +
                         " Pa): a granular packing carries no tension, σ2 = p − q must stay positive");
  }
}

// The rotation's drive (the ring's or the cell's), start and speed. Speed and length: two of
// rotation_rate_deg_per_s, total_rotation_deg and duration; the third follows.
void parseRotation(JsonReader& r, StageSpec& s, bool inCell) {
  if (inCell) parseCellRotationDrive(r, s);
  else parseRingRotationDrive(r, s);
  s.initialDirectionDeg = r.number("initial_direction_deg", 90, -kInf, kInf);
  const bool rate = r.has("rotation_rate_deg_per_s"), total = r.has("total_rotation_deg"), duration = r.has("duration");
  if (rate + total + duration < 2) {
    const std::string missing = rate ? "duration" : total ? "duration" : "rotation_rate_deg_per_s";
    throw SceneError(r.fieldPath(missing),
                     "a rotation stage needs rotation_rate_deg_per_s with total_rotation_deg or a duration, or "
                     "total_rotation_deg with a duration");
  }
  if (rate && total && duration) {
    throw SceneError(r.fieldPath("duration"),
                     "give two of rotation_rate_deg_per_s, total_rotation_deg and duration, not all three");
  }
  s.rotationDerivedField = !duration ? "duration" : !total ? "total_rotation_deg" : "rotation_rate_deg_per_s";
  if (rate) {
    s.rotationRateDeg = r.number("rotation_rate_deg_per_s", 0, -kInf, kInf);
    if (s.rotationRateDeg == 0) throw SceneError(r.fieldPath("rotation_rate_deg_per_s"), "must not be zero");
  }
  if (total) {
    const double degrees = r.number("total_rotation_deg", 0, -kInf, kInf);
    if (degrees == 0) throw SceneError(r.fieldPath("total_rotation_deg"), "must not be zero");
    if (rate && (degrees > 0) != (s.rotationRateDeg > 0)) {
      throw SceneError(r.fieldPath("total_rotation_deg"), "has the opposite sign of rotation_rate_deg_per_s");
    }
    if (rate) s.duration = degrees / s.rotationRateDeg;
    else {
      s.duration = r.number("duration", 0, 0, kInf, true);
      s.rotationRateDeg = degrees / s.duration;
    }
  } else {
    s.duration = r.number("duration", 0, 0, kInf, true);
  }
}

// The cyclic stage: the biaxial stage's fields, and one kind of limit.
void parseCyclic(JsonReader& r, StageSpec& s) {
  s.pressure = r.number("pressure", 300e3, 0, kInf, true);
  s.strainRate = r.number("strain_rate", 0.5, 0, kInf, true);
  s.lateral = parseLateral(r);
  const bool amplitude = r.has("strain_amplitude"), limits = r.has("q_over_p_limits");
  if (amplitude == limits) {
    throw SceneError(r.fieldPath("strain_amplitude"),
                     amplitude ? "give strain_amplitude or q_over_p_limits, not both"
                               : "a cyclic stage needs strain_amplitude or q_over_p_limits");
  }
  if (amplitude) s.strainAmplitude = r.number("strain_amplitude", 0, 0, 0.5, true);
  if (limits) {
    const std::string field = r.fieldPath("q_over_p_limits");
    const Vec2 l = parseVec2(r.raw("q_over_p_limits"), field);
    // (σ22 − σ11)/(σ22 + σ11) lies in (−1, 1) for a specimen in compression, and loading
    // starts by compressing axis 2 from about 0.
    if (!(l.x() < l.y())) throw SceneError(field, "must be [lower, upper] with lower < upper");
    if (!(l.x() > -1) || !(l.y() < 1)) throw SceneError(field, "both limits must lie strictly between -1 and 1");
    if (!(l.y() > 0)) throw SceneError(field, "the upper limit must be above 0: the first half cycle compresses axis 2");
    s.qOverPLimits = std::make_pair(l.x(), l.y());
  }
  if (!r.has("cycles")) throw SceneError(r.fieldPath("cycles"), "a cyclic stage needs a number of cycles");
  s.cycles = static_cast<int>(r.integer("cycles", 1, 1, 10000));
}

// The axial strain path a cyclic stage travels, for its default time limit: 4·amplitude per
// cycle, or with stress-ratio limits (no strain known beforehand) 0.2 per cycle: three times
// the 0.065 per cycle cyclic-circular-quick travelled between ratios −0.2 and 0.3.
double cyclicPathEstimate(const StageSpec& s) {
  return s.cycles * (s.strainAmplitude ? 4 * *s.strainAmplitude : 0.2);
}

StageSpec parseStage(const nlohmann::json& j, const std::string& path, bool inCell) {
  JsonReader r(j, path);
  StageSpec s;
  std::set<std::string> typeNames;
  for (StageSpec::Type t : stageTypes()) typeNames.emplace(toString(t));
  const std::string type = r.choice("type", "free", typeNames);
  s.type = *parseStageType(type);
  s.name = r.string("name", type);
  switch (s.type) {
    case StageSpec::Type::Free:
      if (!r.has("duration")) throw SceneError(r.fieldPath("duration"), "a free stage needs a duration in s");
      s.duration = r.number("duration", 0, 0, kInf, true);
      break;
    case StageSpec::Type::Compaction:
      // The paper's stage 0: frictionless, until the particles are close (void_ratio) with
      // almost no force (pressure, the backstop).
      s.pressure = r.number("pressure", 5e3, 0, kInf, true);
      s.strainRate = r.number("strain_rate", 2.0, 0, kInf, true);
      s.friction = r.number("friction", 0.0, 0, kInf);
      if (r.has("void_ratio")) s.voidRatio = r.number("void_ratio", 0, 0, 10, true);
      break;
    case StageSpec::Type::Isotropic:
      s.pressure = r.number("pressure", 300e3, 0, kInf, true);
      s.strainRate = r.number("strain_rate", 0.5, 0, kInf, true);
      break;
    case StageSpec::Type::Biaxial:
      s.pressure = r.number("pressure", 300e3, 0, kInf, true);
      s.strainRate = r.number("strain_rate", 0.5, 0, kInf, true);
      s.targetAxialStrain = r.number("target_axial_strain", 0.2, 0, 0.5, true);
      s.lateral = parseLateral(r);
      break;
    case StageSpec::Type::Rotation: parseRotation(r, s, inCell); break;
    case StageSpec::Type::Cyclic: parseCyclic(r, s); break;
    case StageSpec::Type::SimpleShear:
      if (!r.has("shear_rate")) throw SceneError(r.fieldPath("shear_rate"), "a simple_shear stage needs a shear_rate γ̇ in 1/s");
      s.shearRate = r.number("shear_rate", 0, 0, kInf, true);
      s.pressure = r.number("normal_stress", 300e3, 0, kInf, true);
      s.targetShearStrain = r.number("target_shear_strain", 0.2, 0, 2, true);
      break;
  }
  // A stage's own friction (compaction has its default of 0 above).
  if (s.type != StageSpec::Type::Free && s.type != StageSpec::Type::Compaction && r.has("friction")) {
    s.friction = r.number("friction", 0, 0, kInf);
  }
  // Every loading stage has a time limit, so a criterion that is never met cannot run forever:
  // compaction and consolidation 1 s of simulated time (about ten times what the presets
  // need), shearing twice the time its target strain (or rotation) takes.
  const double defaultMaxTime = s.type == StageSpec::Type::Biaxial      ? 2 * s.targetAxialStrain / s.strainRate
                                : s.type == StageSpec::Type::Rotation    ? 2 * s.duration
                                : s.type == StageSpec::Type::SimpleShear ? 2 * s.targetShearStrain / s.shearRate
                                : s.type == StageSpec::Type::Cyclic      ? 2 * cyclicPathEstimate(s) / s.strainRate
                                : s.type == StageSpec::Type::Free        ? kInf
                                                                         : 1.0;
  s.maxTime = r.number("max_time", defaultMaxTime, 0, kInf, true);
  r.finish();
  return s;
}

SolverSpec parseSolver(const nlohmann::json& j) {
  SolverSpec s;
  if (j.is_null()) return s;
  JsonReader r(j, "solver");
  const std::string engine = r.choice("engine", "dem", {"dem", "box2d"});
  s.engine = engine == "box2d" ? SolverSpec::Engine::Box2d : SolverSpec::Engine::Dem;
  for (const char* key : {"velocity_iterations", "position_iterations"}) {
    if (!r.has(key)) continue;
    if (s.engine != SolverSpec::Engine::Box2d) {
      throw SceneError(r.fieldPath(key), "only the box2d engine has solver iterations (set solver.engine to \"box2d\")");
    }
    const nlohmann::json& v = j[key];
    if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 100) {
      throw SceneError(r.fieldPath(key), "must be an integer in 1..100, got " + v.dump());
    }
  }
  s.velocityIterations = static_cast<int>(r.integer("velocity_iterations", s.velocityIterations, 1, 100));
  s.positionIterations = static_cast<int>(r.integer("position_iterations", s.positionIterations, 1, 100));
  s.timestep = r.number("timestep", 0, 0, kInf);
  s.timestepSafety = r.number("timestep_safety", s.timestepSafety, 0, 10, true);
  s.threads = static_cast<int>(r.integer("threads", s.threads, 1, 64));
  r.finish();
  return s;
}

OutputSpec parseOutput(const nlohmann::json& j) {
  OutputSpec o;
  if (j.is_null()) return o;
  JsonReader r(j, "output");
  o.sampleInterval = r.number("sample_interval", 0, 0, kInf);
  o.sampleStrain = r.number("sample_strain", o.sampleStrain, 0, 0.5, true);
  o.fabric = r.boolean("fabric", o.fabric);
  o.histograms = r.boolean("histograms", o.histograms);
  o.histogramBins = static_cast<int>(r.integer("histogram_bins", o.histogramBins, 18, 360));
  o.vtk = r.boolean("vtk", o.vtk);
  o.vtkEvery = static_cast<int>(r.integer("vtk_every", o.vtkEvery, 1, 1000000));
  o.checkpointEverySeconds = r.number("checkpoint_every_s", o.checkpointEverySeconds, 0, kInf, true);
  if (r.has("stage_checkpoints")) o.stageCheckpoints = r.boolean("stage_checkpoints", true);
  r.finish();
  return o;
}

// Rolling resistance is a disc model in the DEM engine (rolling_resistance.hpp): a polygon
// resists rolling by its shape already, and Box2D has no such couple here.
void refuseRollingWhereNotModelled(const Scene& scene) {
  if (scene.material.rollingFriction == 0) return;
  bool shaped = scene.assembly && scene.assembly->shape != SpecimenRecipe::Shape::Disc;
  for (const ParticleSpec& p : scene.particles) shaped = shaped || p.shape != ShapeKind::Disc;
  if (shaped) {
    throw SceneError("material.rolling_friction", "rolling resistance is for discs; this scene has polygons or clumps, "
                                                  "which resist rolling by their shape (set it to 0)");
  }
  if (scene.solver.engine == SolverSpec::Engine::Box2d) {
    throw SceneError("material.rolling_friction", "the box2d engine has no rolling resistance (use the dem engine, or "
                                                  "set it to 0)");
  }
}

// Box2D's solver here builds one fixture per body: clumps are grainlab's DEM only. And clump
// contacts are disc contacts: a scene with clumps has no polygons.
void refuseClumpsWhereTheyCannotRun(const Scene& scene) {
  const bool clumpAssembly = scene.assembly && scene.assembly->shape == SpecimenRecipe::Shape::Clump;
  int firstClump = -1, firstPolygon = -1;
  for (size_t k = 0; k < scene.particles.size(); ++k) {
    if (scene.particles[k].shape == ShapeKind::Clump && firstClump < 0) firstClump = static_cast<int>(k);
    if (scene.particles[k].shape == ShapeKind::Polygon && firstPolygon < 0) firstPolygon = static_cast<int>(k);
  }
  const bool polygonAssembly = scene.assembly && scene.assembly->shape == SpecimenRecipe::Shape::Elongated;
  if ((firstClump >= 0 || clumpAssembly) && (firstPolygon >= 0 || polygonAssembly)) {
    const std::string field = firstClump >= 0 ? "particles[" + std::to_string(firstClump) + "].shape" : "assembly.shape";
    throw SceneError(field, "a scene with clumps cannot also have polygons (clump contacts are between discs)");
  }
  if (scene.solver.engine != SolverSpec::Engine::Box2d) return;
  for (size_t k = 0; k < scene.particles.size(); ++k) {
    if (scene.particles[k].shape == ShapeKind::Clump) {
      throw SceneError("particles[" + std::to_string(k) + "].shape",
                       "clumps run in the dem engine only (solver.engine \"box2d\" builds one shape per body)");
    }
  }
  if (scene.assembly && scene.assembly->shape == SpecimenRecipe::Shape::Clump) {
    throw SceneError("assembly.shape",
                     "clumps run in the dem engine only (solver.engine \"box2d\" builds one shape per body)");
  }
}

// A periodic cell (docs/periodic-cell.md) holds discs and polygons that all meet each other
// through its images: the contact loop across its edges has no walls or clumps yet, and its
// size comes either from the assembly or from boundary.size, not both.
void refuseWhatACellCannotHold(const Scene& scene) {
  if (!scene.walls.empty()) throw SceneError("walls", "a periodic cell has no walls (remove them or use another boundary)");
  for (size_t k = 0; k < scene.particles.size(); ++k) {
    if (scene.particles[k].shape == ShapeKind::Clump) {
      throw SceneError("particles[" + std::to_string(k) + "].shape", "a periodic cell holds discs and polygons, not clumps");
    }
  }
  if (scene.assembly && scene.assembly->shape == SpecimenRecipe::Shape::Clump) {
    throw SceneError("assembly.shape", "a periodic cell holds discs and polygons, not clumps");
  }
  if (scene.assembly && scene.boundary.cellSize) {
    throw SceneError("boundary.size", "the assembly sizes the cell: give boundary.size only for explicit particles");
  }
  if (!scene.assembly && !scene.boundary.cellSize) {
    throw SceneError("boundary.size", "a periodic cell of explicit particles needs its size [width, height] in m");
  }
  if (scene.gravity != Vec2::Zero()) throw SceneError("gravity", "a periodic cell has no gravity (it tiles the plane)");
}

// The cell's loading paths (periodic_stages.hpp): the membrane's isotropic, biaxial and
// simple_shear in the cell, and the stress-controlled rotation; compaction and cyclic are the
// ring's only.
void refuseStageACellCannotRun(const StageSpec& s, const std::string& path) {
  using T = StageSpec::Type;
  if (s.type == T::Free || s.type == T::Isotropic || s.type == T::Biaxial || s.type == T::SimpleShear ||
      s.type == T::Rotation)
    return;
  throw SceneError(path + ".type", "a periodic cell runs free, isotropic, biaxial, simple_shear and rotation stages, not " +
                                       std::string(toString(s.type)));
}

}  // namespace

Scene parseScene(const nlohmann::json& json) {
  JsonReader r(json, "");
  Scene scene;
  scene.name = r.string("name", scene.name);
  scene.seed = static_cast<std::uint64_t>(r.integer("seed", 1, 0, std::numeric_limits<long long>::max()));
  scene.material = parseMaterial(r.raw("material"));

  const nlohmann::json& particles = r.raw("particles");
  if (!particles.is_null()) {
    if (!particles.is_array()) throw SceneError("particles", "must be an array");
    for (size_t k = 0; k < particles.size(); ++k) {
      scene.particles.push_back(parseParticle(particles[k], "particles[" + std::to_string(k) + "]"));
    }
  }
  const nlohmann::json& assembly = r.raw("assembly");
  if (!assembly.is_null()) scene.assembly = parseSpecimenRecipe(assembly, "assembly");
  if (scene.particles.empty() && !scene.assembly) {
    throw SceneError("particles", "the scene has no particles (give particles or an assembly)");
  }

  const nlohmann::json& walls = r.raw("walls");
  if (!walls.is_null()) {
    if (!walls.is_array()) throw SceneError("walls", "must be an array");
    for (size_t k = 0; k < walls.size(); ++k) scene.walls.push_back(parseWall(walls[k], "walls[" + std::to_string(k) + "]"));
  }
  scene.gravity = r.vec2("gravity", scene.gravity);

  const nlohmann::json& boundary = r.raw("boundary");
  if (!boundary.is_null()) {
    JsonReader b(boundary, "boundary");
    const std::string type = b.choice("type", "none", {"none", "membrane", "periodic"});
    scene.boundary.type = type == "membrane"   ? BoundarySpec::Type::Membrane
                          : type == "periodic" ? BoundarySpec::Type::Periodic
                                               : BoundarySpec::Type::None;
    if (scene.boundary.type == BoundarySpec::Type::Periodic) {
      if (b.has("size")) {
        const Vec2 size = b.vec2("size", Vec2::Zero());
        if (!(size.x() > 0) || !(size.y() > 0) || !size.allFinite()) {
          throw SceneError(b.fieldPath("size"), "the cell's width and height must be positive and finite");
        }
        scene.boundary.cellSize = size;
      }
      scene.boundary.rateCap = b.number("rate_cap", scene.boundary.rateCap, 0, kInf, true);
    }
    b.finish();
  }
  if (scene.boundary.type == BoundarySpec::Type::Periodic) refuseWhatACellCannotHold(scene);
  if (scene.boundary.type == BoundarySpec::Type::Membrane && !scene.assembly) {
    throw SceneError("boundary.type", "a membrane boundary is generated with the assembly: give an assembly");
  }

  const nlohmann::json& stages = r.raw("stages");
  if (!stages.is_null()) {
    if (!stages.is_array()) throw SceneError("stages", "must be an array");
    for (size_t k = 0; k < stages.size(); ++k) {
      const std::string path = "stages[" + std::to_string(k) + "]";
      StageSpec s = parseStage(stages[k], path, scene.boundary.type == BoundarySpec::Type::Periodic);
      if (scene.boundary.type == BoundarySpec::Type::Periodic) refuseStageACellCannotRun(s, path);
      else if (s.type != StageSpec::Type::Free && scene.boundary.type != BoundarySpec::Type::Membrane) {
        throw SceneError(path + ".type", "a " + s.name + " stage loads through the boundary ring: set boundary.type to \"membrane\"");
      }
      scene.stages.push_back(s);
    }
  }
  if (scene.stages.empty()) {
    StageSpec free;
    free.name = "free";
    free.duration = 0.01;
    scene.stages.push_back(free);
  }
  scene.solver = parseSolver(r.raw("solver"));
  if (scene.boundary.type == BoundarySpec::Type::Periodic && scene.solver.engine == SolverSpec::Engine::Box2d) {
    throw SceneError("boundary.type", "the box2d engine has no periodic cell (use solver.engine \"dem\")");
  }
  refuseClumpsWhereTheyCannotRun(scene);
  scene.output = parseOutput(r.raw("output"));
  scene.startFrom = parseStartFrom(r.raw("start_from"));
  refuseRollingWhereNotModelled(scene);
  r.finish();
  return scene;
}

Scene loadSceneFile(const std::string& path) { return parseScene(loadSceneJson(path)); }

nlohmann::json loadSceneJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SceneError("(file)", "cannot read " + path);
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::parse_error& e) {
    throw SceneError("(json)", std::string("not valid JSON: ") + e.what());
  }
  return j;
}

}  // namespace grainlab

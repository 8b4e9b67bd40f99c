#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "grainlab/contact.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/math.hpp"
#include "grainlab/validity.hpp"
#include "validity_format.hpp"
#include "grainlab/world.hpp"
#include "prepared_specimen.hpp"
#include "run_context.hpp"
#include "validity_reference.hpp"

namespace grainlab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();


std::string runCostField(const std::string& costField) {
  // RunCost names stage fields "stages.2.strain_rate"; the parser's errors "stages[2].strain_rate".
  if (costField.rfind("stages.", 0) != 0) return costField;
  const size_t dot = costField.find('.', 7);
  if (dot == std::string::npos) return costField;
  return "stages[" + costField.substr(7, dot - 7) + "]" + costField.substr(dot);
}

std::string stageField(size_t k, const char* key) { return "stages[" + std::to_string(k) + "]." + key; }

// The field that drives a quantity: of the fields it depends on, the one furthest from its
// reference value (validity_reference.hpp) in the direction that makes the quantity worse.
// `power`: the quantity goes as field^power (for a lower-bounded quantity, pass the power
// with which it falls).
struct Driver {
  std::string field;
  double value;
  double reference;
  double power;
};

std::string drivingField(const std::vector<Driver>& drivers) {
  std::string best;
  double worst = -kInf;
  for (const Driver& d : drivers) {
    if (!(d.value > 0) || !(d.reference > 0)) continue;
    const double push = d.power * std::log(d.value / d.reference);
    if (push > worst) {
      worst = push;
      best = d.field;
    }
  }
  return best.empty() && !drivers.empty() ? drivers.front().field : best;
}

// The fields the timestep depends on: dt = safety · 2√(m/2k) ∝ safety √(ρ/k), or the given one.
std::vector<Driver> timestepDrivers(const Scene& scene, double power) {
  if (scene.solver.timestep > 0) return {{"solver.timestep", scene.solver.timestep, reference::kTimestep, power}};
  const double stiffest = std::max(scene.material.normalStiffness, 3 * scene.material.tangentialStiffness);
  return {{"solver.timestep_safety", scene.solver.timestepSafety, reference::kTimestepSafety, power},
          {"material.density", scene.material.density, reference::kDensity, power / 2},
          {stiffest == scene.material.normalStiffness ? "material.normal_stiffness" : "material.tangential_stiffness",
           stiffest, reference::kNormalStiffness, -power / 2}};
}

// The size fields of a generated specimen's particles (power: the quantity goes as d^power).
std::vector<Driver> particleSizeDrivers(const Scene& scene, double power) {
  if (!scene.assembly) return {};
  const SpecimenRecipe& a = *scene.assembly;
  if (a.shape == SpecimenRecipe::Shape::Disc) return {{"assembly.disc_radius", a.discRadius, reference::kDiscRadius, power}};
  double longest = 0;
  for (double l : a.longAxes) longest = std::max(longest, l);
  return {{"assembly.long_axes", longest, reference::kLongAxis, power}};
}

// Of a stage: the rate of its largest principal strain (1/s) and the field that sets it.
std::pair<double, std::string> principalRate(const StageSpec& s, size_t k) {
  switch (s.type) {
    case StageSpec::Type::Compaction:
    case StageSpec::Type::Isotropic:
    case StageSpec::Type::Biaxial:
    case StageSpec::Type::Cyclic: return {s.strainRate, stageField(k, "strain_rate")};
    case StageSpec::Type::Rotation: return {s.deviatoricStrainRate / 2, stageField(k, "deviatoric_strain_rate")};
    case StageSpec::Type::SimpleShear: return {s.shearRate / 2, stageField(k, "shear_rate")};
    case StageSpec::Type::Free: break;
  }
  return {0, ""};
}

// The stress a stage holds (Pa) and its field.
std::pair<double, std::string> targetStress(const StageSpec& s, size_t k) {
  switch (s.type) {
    case StageSpec::Type::Rotation: return {s.pressure, stageField(k, "mean_stress")};
    case StageSpec::Type::SimpleShear: return {s.pressure, stageField(k, "normal_stress")};
    case StageSpec::Type::Free: return {0, ""};
    default: return {s.pressure, stageField(k, "pressure")};
  }
}

// A measure of each specimen particle (not the ring, not a wall's): the mean equal-area
// diameter, m; 0 for a world without particles.
double meanDiameter(const World& world) {
  double sum = 0;
  int n = 0;
  for (int k = 0; k < world.size(); ++k) {
    if (world.boundaryFlags()[k] || world.motions()[k] != Motion::Dynamic) continue;
    sum += 2 * std::sqrt(world.area(k) / kPi);
    ++n;
  }
  return n ? sum / n : 0;
}

// Collects the quantities against their limits.
class Envelope {
 public:
  explicit Envelope(ValidityAssessment& out) : out_(out) {}

  /// `hard`: the hard limit when the caller sets it (the cost's), else the table's.
  void check(const std::string& quantity, double value, const std::string& field, const std::string& meaning,
             double hard = std::nan("")) {
    const ValidityQuantity& q = validityQuantity(quantity);
    if (std::isnan(hard)) hard = q.hard;
    auto past = [&](double limit) { return q.upper ? value > limit : value < limit; };
    if (std::isnan(value)) return;
    if (past(hard)) out_.refusals.push_back({field, quantity, value, hard, meaning + " (" + q.hardReason + ")"});
    else if (past(q.soft)) out_.warnings.push_back({field, quantity, value, q.soft, meaning + " (" + q.softReason + ")"});
    // How far towards its soft limit: for likelyCause.
    const double ratio = q.upper ? value / q.soft : q.soft / value;
    if (ratio > worstRatio_) {
      worstRatio_ = ratio;
      worst_ = {field, quantity, value, q.soft, meaning};
    }
  }
  double worstRatio() const { return worstRatio_; }
  const ValidityWarning& worst() const { return worst_; }

 private:
  ValidityAssessment& out_;
  double worstRatio_ = -kInf;
  ValidityWarning worst_;
};

// The scene key that sets a particle's size.
const char* shapeKey(const ParticleSpec& p) {
  return p.shape == ShapeKind::Disc ? "radius" : p.shape == ShapeKind::Clump ? "members" : "vertices";
}

// The key that sets a particle's size (givenSize): a disc's radius, a polygon's vertices, a
// clump's member reaching furthest from its reference point.
std::string sizeKey(const ParticleSpec& p) {
  if (p.shape != ShapeKind::Clump || p.members.empty()) return shapeKey(p);
  size_t far = 0;
  for (size_t m = 0; m < p.members.size(); ++m) {
    const ClumpMember& a = p.members[m];
    const ClumpMember& b = p.members[far];
    if (a.centre.norm() + a.radius > b.centre.norm() + b.radius) far = m;
  }
  return "members[" + std::to_string(far) + "].radius";
}

// A particle's size as the scene gives it: a disc's radius, a polygon's or a clump's bounding
// radius (about the reference point it is given from).
double givenSize(const ParticleSpec& p) {
  if (p.shape == ShapeKind::Disc) return p.radius;
  double r = 0;
  for (const ClumpMember& m : p.members) r = std::max(r, m.centre.norm() + m.radius);
  for (const Vec2& v : p.vertices) r = std::max(r, v.norm());
  return r;
}

// The quantities the scene alone decides, checked before the world is built (a specimen of
// 1e300 m grains, or a ring of 1e-300 m discs, cannot be built to be measured).
void assessAlone(const Scene& scene, Envelope& envelope) {
  if (scene.assembly) {
    const SpecimenRecipe& a = *scene.assembly;
    // The grains' equal-area diameter: a disc's, or for the elongated polygons L/√aspect
    // (an ellipse of axes L and L/aspect), averaged over the size classes.
    double d = 2 * a.discRadius, smallestWidth = 2 * a.discRadius;
    if (a.shape != SpecimenRecipe::Shape::Disc && !a.longAxes.empty()) {  // polygons and clumps alike
      d = 0;
      smallestWidth = kInf;
      for (double l : a.longAxes) {
        d += l / std::sqrt(a.aspectRatio) / static_cast<double>(a.longAxes.size());
        smallestWidth = std::min(smallestWidth, l / a.aspectRatio);
      }
    }
    const double across = a.specimenDiameter / d;
    std::vector<Driver> drivers{{"assembly.specimen_diameter", a.specimenDiameter, reference::kSpecimenDiameter, -1}};
    for (const Driver& p : particleSizeDrivers(scene, 1)) drivers.push_back(p);
    envelope.check("particles_across", across, drivingField(drivers),
                   threeSignificant(across) + " particles of " + threeSignificant(1e3 * d) + " mm across a " + threeSignificant(1e3 * a.specimenDiameter) +
                       " mm specimen");
    if (a.boundaryRadius > 0) {
      const double automatic = 0.5 * smallestWidth;
      const double ratio = std::max(a.boundaryRadius / automatic, automatic / a.boundaryRadius);
      envelope.check("boundary_particle_ratio", ratio, "assembly.boundary_radius",
                     "ring discs of " + threeSignificant(1e3 * a.boundaryRadius) + " mm beside the automatic " +
                         threeSignificant(1e3 * automatic) + " mm (half the narrowest grain)");
    }
  }
  // Explicit particles: the spread of their sizes, blamed on the one furthest (in log) from
  // the median size.
  if (scene.particles.size() > 1) {
    std::vector<double> sizes;
    for (const ParticleSpec& p : scene.particles) sizes.push_back(givenSize(p));
    std::vector<double> sorted = sizes;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double median = sorted[sorted.size() / 2];
    size_t odd = 0;
    for (size_t k = 0; k < sizes.size(); ++k)
      if (std::abs(std::log(sizes[k] / median)) > std::abs(std::log(sizes[odd] / median))) odd = k;
    const auto [smallest, largest] = std::minmax_element(sizes.begin(), sizes.end());
    const double spread = *largest / *smallest;
    envelope.check("size_ratio", spread,
                   "particles[" + std::to_string(odd) + "]." + sizeKey(scene.particles[odd]),
                   "the largest particle is " + threeSignificant(spread) + " times the smallest");
  }
}

void assess(const Scene& scene, const World& world, const RunCost* cost, double maxSeconds, Envelope& envelope) {
  const double d = meanDiameter(world);
  const double dt = world.timestep();
  const bool dem = world.engine() == WorldSettings::Engine::Dem;
  const double rho = scene.material.density;
  const double specimenRadius = scene.assembly ? scene.assembly->specimenDiameter / 2 : 0;

  assessAlone(scene, envelope);

  // Explicit particles as given: how deep they start in each other, how fast they start.
  const int explicitCount = static_cast<int>(scene.particles.size());
  if (dem && explicitCount > 0) {
    std::vector<ContactRecord> contacts;
    world.contacts(contacts);
    double deepest = 0;
    int deepestParticle = -1;
    for (const ContactRecord& c : contacts) {
      for (int k : {c.i, c.j}) {
        if (k < 0 || k >= explicitCount) continue;
        const double relative = c.overlap / world.boundingRadii()[k];
        if (relative > deepest) {
          deepest = relative;
          deepestParticle = k;
        }
      }
    }
    if (deepestParticle >= 0) {
      const char* key = shapeKey(scene.particles[deepestParticle]);
      envelope.check("initial_overlap", deepest, "particles[" + std::to_string(deepestParticle) + "]." + key,
                     "particle " + std::to_string(deepestParticle) + " starts " + threeSignificant(deepest) +
                         " of its radius inside a neighbour or wall");
    }
    for (int k = 0; k < explicitCount; ++k) {
      const double r = world.boundingRadii()[k];
      const double moved = scene.particles[k].velocity.norm() * dt / r, turned = std::abs(scene.particles[k].spin) * dt;
      if (moved >= turned && moved > 0)
        envelope.check("initial_motion_per_step", moved, "particles[" + std::to_string(k) + "].velocity",
                       "particle " + std::to_string(k) + " moves " + threeSignificant(moved) + " of its radius per step");
      else if (turned > 0)
        envelope.check("initial_motion_per_step", turned, "particles[" + std::to_string(k) + "].spin",
                       "particle " + std::to_string(k) + "'s surface moves " + threeSignificant(turned) + " of its radius per step");
    }
  }

  if (dem && world.criticalTimestep() > 0) {
    const double ratio = dt / world.criticalTimestep();
    const std::string field = scene.solver.timestep > 0 ? "solver.timestep" : "solver.timestep_safety";
    envelope.check("timestep_ratio", ratio, field,
                   "timestep " + threeSignificant(dt) + " s is " + threeSignificant(ratio) + " of the critical " + threeSignificant(world.criticalTimestep()) + " s");
  }

  for (size_t k = 0; k < scene.stages.size(); ++k) {
    const StageSpec& s = scene.stages[k];
    const auto [rate, rateField] = principalRate(s, k);
    const auto [stress, stressField] = targetStress(s, k);
    if (s.type == StageSpec::Type::Free) continue;

    // The mean overlap at the stage's target stress: δ/r = p d / (k_n r) = 2 p / k_n.
    if (dem && stress > 0) {
      const double overlap = 2 * stress / scene.material.normalStiffness;
      const std::string field = drivingField({{stressField, stress, reference::kStress, 1},
                                              {"material.normal_stiffness", scene.material.normalStiffness,
                                               reference::kNormalStiffness, -1}});
      envelope.check("overlap", overlap, field,
                     "the mean contact overlap at " + threeSignificant(stress) + " Pa is " + threeSignificant(overlap) + " of the radius");
    }

    // The inertial number at the requested rate: I = ε̇ d √(ρ/p). Compaction is not meant to
    // be quasi-static (it only brings the particles together).
    if (s.type != StageSpec::Type::Compaction && rate > 0 && stress > 0 && d > 0) {
      const double inertial = rate * d * std::sqrt(rho / stress);
      std::vector<Driver> drivers{{rateField, rate, reference::kRate, 1},
                                  {stressField, stress, reference::kStress, -0.5},
                                  {"material.density", rho, reference::kDensity, 0.5}};
      for (const Driver& p : particleSizeDrivers(scene, 1)) drivers.push_back(p);
      const std::string field = drivingField(drivers);
      envelope.check("inertial_number", inertial, field,
                     "the inertial number at " + threeSignificant(rate) + " /s and " + threeSignificant(stress) + " Pa is " + threeSignificant(inertial) +
                         ": the " + std::string(toString(s.type)) + " stage is no longer quasi-static");
      // The lateral servo moves the ring no faster than the quasi-static bound allows, so a
      // stage sheared faster cannot hold σ11 at its target.
      const bool heldLaterally = (s.type == StageSpec::Type::Biaxial || s.type == StageSpec::Type::Cyclic) &&
                                 s.lateral == StageSpec::Lateral::ConstantStress;
      if (heldLaterally) {
        envelope.check("lateral_servo_inertial_number", inertial, field,
                       "the axial rate asks for an inertial number of " + threeSignificant(inertial) +
                           ", above the lateral servo's cap: σ11 will not be held at " + threeSignificant(stress) + " Pa");
      }
    }

    // The boundary's displacement per step against the particle radius: ε̇ dt R / r.
    if (rate > 0 && d > 0 && specimenRadius > 0) {
      const double perStep = rate * dt * specimenRadius / (d / 2);
      std::vector<Driver> drivers{{rateField, rate, reference::kRate, 1}};
      for (const Driver& t : timestepDrivers(scene, 1)) drivers.push_back(t);
      envelope.check("strain_per_step", perStep, drivingField(drivers),
                     "the boundary moves " + threeSignificant(perStep) + " of a particle radius per step");
    }

    // The strain between samples (strain-sampled stages).
    if (s.type == StageSpec::Type::Biaxial || s.type == StageSpec::Type::Cyclic ||
        s.type == StageSpec::Type::SimpleShear) {
      envelope.check("strain_per_sample", scene.output.sampleStrain, "output.sample_strain",
                     "a sample every " + threeSignificant(scene.output.sampleStrain) + " of strain");
    }

    if (s.type == StageSpec::Type::Rotation) {
      const double degPerSecond = std::abs(s.rotationRateDeg);
      // Whichever two of rate, total and duration the scene gave: the one furthest from its
      // reference is the likelier slip.
      std::vector<Driver> rotation;
      for (const Driver& d : std::initializer_list<Driver>{
               {"total_rotation_deg", std::abs(s.rotationRateDeg * s.duration), reference::kTotalRotationDeg, 1},
               {"rotation_rate_deg_per_s", degPerSecond, reference::kRotationRateDeg, 1},
               {"duration", s.duration, reference::kRotationDuration, -1}}) {
        // Only the two fields the scene gave can be to blame.
        if (d.field != s.rotationDerivedField) rotation.push_back({stageField(k, d.field.c_str()), d.value, d.reference, d.power});
      }
      std::vector<Driver> perStepDrivers = rotation;
      for (const Driver& t : timestepDrivers(scene, 1)) perStepDrivers.push_back(t);
      const double perStep = degPerSecond * dt;
      envelope.check("rotation_per_step", perStep, drivingField(perStepDrivers),
                     "the strain-rate direction turns " + threeSignificant(perStep) + "° per step");
      const double spacing = scene.output.sampleInterval > 0 ? scene.output.sampleInterval : s.duration / 180;
      const double perSample = degPerSecond * spacing;
      std::vector<Driver> perSampleDrivers = rotation;
      if (scene.output.sampleInterval > 0)
        perSampleDrivers.push_back({"output.sample_interval", scene.output.sampleInterval,
                                    reference::kRotationDuration / 180, 1});
      envelope.check("rotation_per_sample", perSample, drivingField(perSampleDrivers),
                     "the strain-rate direction turns " + threeSignificant(perSample) + "° between samples");
    }
  }

  if (cost) {
    const double seconds = cost->certainSeconds();
    std::vector<Driver> drivers = timestepDrivers(scene, -1);
    if (scene.assembly)
      drivers.push_back({"assembly.specimen_diameter", scene.assembly->specimenDiameter, reference::kSpecimenDiameter, 2});
    // The run's length: the stage asking for the most simulated time (RunCost's field), by
    // its rate (slower is longer) and the path it travels.
    const std::string lengthField = runCostField(cost->field);
    const size_t open = lengthField.find('['), close = lengthField.find(']');
    if (open != std::string::npos && close != std::string::npos) {
      const size_t k = std::stoul(lengthField.substr(open + 1, close - open - 1));
      const StageSpec& s = scene.stages.at(k);
      const auto [rate, rateField] = principalRate(s, k);
      if (rate > 0) drivers.push_back({rateField, rate, reference::kRate, -1});
      if (s.type == StageSpec::Type::Cyclic) drivers.push_back({stageField(k, "cycles"), double(s.cycles), 3, 1});
      if (s.type == StageSpec::Type::Biaxial)
        drivers.push_back({stageField(k, "target_axial_strain"), s.targetAxialStrain, 0.2, 1});
      if (s.type == StageSpec::Type::SimpleShear)
        drivers.push_back({stageField(k, "target_shear_strain"), s.targetShearStrain, 0.3, 1});
      if (s.type == StageSpec::Type::Free || s.type == StageSpec::Type::Rotation)
        drivers.push_back({stageField(k, "duration"), s.duration, reference::kRotationDuration, 1});
      if (lengthField.find("max_time") != std::string::npos)
        drivers.push_back({lengthField, s.maxTime, reference::kSimulatedTime, 1});
    }
    std::string field = drivingField(drivers);
    if (field.empty()) field = lengthField;
    // The soft limit on what it may take (criterion stages to their time limits), the hard
    // one (the caller's) on what it takes at least.
    const double most = cost->mostSeconds();
    if (seconds > maxSeconds)
      envelope.check("estimated_seconds", seconds, field,
                     "the run is estimated to take " + humanDuration(seconds) + " (" + cost->describe() + ")",
                     maxSeconds);
    else
      envelope.check("estimated_seconds", most, field,
                     "the run may take up to " + humanDuration(most) + " (" + cost->describe() + ")");
  }
}

}  // namespace

ValidityAssessment assessSceneAlone(const Scene& scene) {
  ValidityAssessment out;
  Envelope envelope(out);
  assessAlone(scene, envelope);
  return out;
}

ValidityAssessment assessValidity(const Scene& scene, const World& world, const RunCost& cost, double maxSeconds) {
  ValidityAssessment out;
  out.cost = cost;
  Envelope envelope(out);
  assess(scene, world, &cost, maxSeconds, envelope);
  return out;
}

ValidityAssessment assessSceneValidity(const Scene& scene, double maxSeconds) {
  // What the scene alone decides first: such a scene may not even build.
  if (ValidityAssessment alone = assessSceneAlone(scene); !alone.refusals.empty()) return alone;
  RunContext context(scene);
  // As runScene: a prepared specimen is loaded (one that is missing or does not fit is a
  // SceneError naming start_from's field) and only the stages after it are counted.
  std::size_t firstStage = 0;
  if (scene.startFrom) {
    PreparedHistory history;
    firstStage = loadPreparedSpecimen(scene, context, history);
  }
  return assessValidity(scene, context.world(), estimateRunCost(scene, context.world(), firstStage), maxSeconds);
}

std::string likelyCause(const Scene& scene, const World& world) {
  ValidityAssessment ignored;
  Envelope envelope(ignored);
  assess(scene, world, nullptr, std::numeric_limits<double>::infinity(), envelope);
  // Less than halfway to every soft limit: nothing in the scene stands out.
  if (!(envelope.worstRatio() > 0.5)) return {};
  const ValidityWarning& w = envelope.worst();
  return w.field + " (" + w.quantity + " " + threeSignificant(w.value) + " against its limit " + threeSignificant(w.limit) + ": " + w.meaning + ")";
}

}  // namespace grainlab

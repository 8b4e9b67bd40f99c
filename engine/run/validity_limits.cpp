// The validity envelope's table: each quantity, its two limits and why (docs/validity.md
// gives the measurements behind them).
#include <limits>
#include <stdexcept>

#include "grainlab/validity.hpp"
#include "validity_format.hpp"

namespace grainlab {
namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

}  // namespace

const std::vector<ValidityQuantity>& validityQuantities() {
  static const std::vector<ValidityQuantity> table{
      {"inertial_number", "", true, 1e-3, 0.1, "I = ε̇ d √(ρ/p) at the stage's requested rate and target stress",
       "quasi-static shearing needs I below about 1e-3: above it the stress depends on the rate",
       "above 0.1 the packing flows as a dense fluid, not a solid under test: a peak strength means nothing"},
      {"lateral_servo_inertial_number", "", true, 0.8e-3, kNone,
       "the inertial number a biaxial or cyclic stage with lateral constant_stress asks for",
       "the lateral servo moves the ring no faster than I = 0.8e-3 allows, so σ11 is not held at its target",
       "none: the run still shears, at a lateral stress the run-time check measures"},
      {"lateral_stress_error", "", true, 0.1, 1.0, "|σ11 − target| / target, measured during a constant-stress shearing",
       "σ11 is more than 10% off the stress the stage holds: the test is no longer at its confining stress",
       "σ11 is off by more than its target: the test is another boundary condition"},
      {"overlap", "", true, 0.01, 0.1,
       "mean contact overlap over the particle radius: δ/r = p d / (k_n r) = 2p/k_n at a target stress; "
       "measured from the contacts at the start and during the run",
       "above 1% the linear contact stands for a deformation, not a touch: results depend on the stiffness",
       "above 10% particles pass into each other: the packing is not a granular packing"},
      {"initial_overlap", "", true, 0.1, 1.0,
       "the deepest overlap of an explicit particle with a neighbour or wall as given, over its radius",
       "above 10% of the radius the first steps push the particle out with a burst of elastic energy",
       "above a whole radius the particle starts with its centre inside another body: the contact has no meaning"},
      {"particles_across", "", false, 10, 5, "specimen diameter over the mean particle diameter",
       "under 10 across, the one-particle boundary layer at each side is over a fifth of the specimen",
       "under 5 across there is no interior: the specimen is its boundary"},
      {"boundary_particle_ratio", "", true, 3, 10,
       "assembly.boundary_radius against the automatic one (half the narrowest grain), whichever is larger "
       "over the other",
       "3 times off, the ring touches the specimen at another scale than the grains': the membrane is no longer "
       "grain-scale",
       "10 times off, grains pass between the ring's discs (larger) or the ring outnumbers its specimen (smaller)"},
      {"size_ratio", "", true, 10, 1000, "the largest explicit particle's size over the smallest's",
       "over 10 the smallest particles set a timestep 10 times shorter than the others need",
       "over 1000 the smallest particles are not resolved by the contacts of the others (and cost 1000 times "
       "more steps)"},
      {"timestep_ratio", "", true, 0.3, 0.45, "timestep over the single-contact critical timestep 2√(m/2k)",
       "above 0.3 a particle with 6 or more contacts is past its own stability bound and can gain energy",
       "above 0.45 a dense packing heats until its strength means nothing (0.5) or diverges (0.6 and up)"},
      {"strain_per_step", "radius", true, 0.01, 0.1,
       "how far the boundary moves in one step, over the particle radius: ε̇ dt R / r",
       "above 1% of a radius per step a contact's overlap builds within a few steps",
       "above 10% of a radius per step the boundary drives overlaps past the overlap limit in a step"},
      {"strain_per_sample", "", true, 0.01, 0.05, "axial (or shear) strain between two samples: output.sample_strain",
       "above 0.01 the peak of φ_mob (at 2-5% axial strain) is sampled by a few points only",
       "above 0.05 the peak falls between two samples"},
      {"rotation_per_step", "°", true, 0.1, 1.0, "how far the strain-rate direction turns in one step",
       "above 0.1° per step the stress cannot follow the turning within the servo's response time",
       "above 1° per step the boundary's direction jumps: the path is not a rotation"},
      {"rotation_per_sample", "°", true, 10, 90, "how far the strain-rate direction turns between samples",
       "above 10° the series resolves the turning by fewer than 18 samples per half turn",
       "above 90° the sampled direction (periodic in 180°) is aliased: the series cannot follow the rotation"},
      {"initial_motion_per_step", "radius", true, 0.01, 0.1,
       "a particle's given velocity (or spin times radius) times the timestep, over its radius",
       "above 1% of a radius per step the first contacts are struck, not touched",
       "above 10% of a radius per step the particle jumps through its neighbours"},
      {"estimated_seconds", "s", true, 3600, kNone, "the run's estimated wall time (RunCost, one thread): at most (soft), at least (hard)",
       "a run over an hour is worth checking the fields that drive its cost before waiting",
       "the caller's limit: grainlab run refuses over 30 days (unless --force), the server its --max-run-seconds"},
  };
  return table;
}

const ValidityQuantity& validityQuantity(const std::string& name) {
  for (const ValidityQuantity& q : validityQuantities())
    if (q.name == name) return q;
  throw std::logic_error("no validity quantity " + name);
}

std::string ValidityAssessment::refusalMessage() const {
  std::string out;
  for (const ValidityWarning& r : refusals) {
    const ValidityQuantity& q = validityQuantity(r.quantity);
    out += (out.empty() ? "" : "; ") + r.field + ": " + r.quantity + " " + threeSignificant(r.value) + (q.upper ? " > " : " < ") +
           threeSignificant(r.limit) + ": " + r.meaning;
  }
  return out;
}

nlohmann::json warningsJson(const std::vector<ValidityWarning>& warnings) {
  nlohmann::json out = nlohmann::json::array();
  for (const ValidityWarning& w : warnings) {
    nlohmann::json j = {{"field", w.field}, {"quantity", w.quantity}, {"value", w.value}, {"limit", w.limit},
                        {"meaning", w.meaning}};
    if (w.step >= 0) j["step"] = w.step;
    out.push_back(j);
  }
  return out;
}

std::vector<ValidityWarning> warningsFromJson(const nlohmann::json& warnings) {
  std::vector<ValidityWarning> out;
  if (!warnings.is_array()) return out;
  for (const nlohmann::json& j : warnings) {
    ValidityWarning w;
    w.field = j.value("field", "");
    w.quantity = j.value("quantity", "");
    w.value = j.value("value", 0.0);
    w.limit = j.value("limit", 0.0);
    w.meaning = j.value("meaning", "");
    w.step = j.value("step", std::int64_t{-1});
    out.push_back(w);
  }
  return out;
}

std::string describe(const ValidityWarning& w) {
  bool upper = true;
  for (const ValidityQuantity& q : validityQuantities())
    if (q.name == w.quantity) upper = q.upper;
  std::string line = "warning: " + w.field + ": " + w.quantity + " " + threeSignificant(w.value) + (upper ? " > " : " < ") +
                     threeSignificant(w.limit);
  if (w.step >= 0) line += " at step " + std::to_string(w.step);
  return line + ": " + w.meaning;
}

}  // namespace grainlab

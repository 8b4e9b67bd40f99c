#include "timestep_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact_law.hpp"

namespace grainlab {

double stiffestSpring(const ParticleStore& particles, const Material& material, int k, bool tangential) {
  const double r = particles.boundingRadius[k];
  const double g = particles.mass[k] * r * r / particles.inertia[k];
  const double rotational = 1.0 + g;
  // A disc's normal force passes through its centre (so does a one-disc clump's); a polygon's
  // or a clump member's need not.
  const bool central = particles.shape[k] == ShapeKind::Disc ||
                       (particles.shape[k] == ShapeKind::Clump && particles.clumpOf(k).members.size() == 1);
  const double normal = material.normalStiffness * (central ? 1.0 : rotational);
  if (!tangential) return normal;
  if (material.rollingFriction > 0 && particles.shape[k] == ShapeKind::Disc) {
    // The rolling spring k_r = β k_t R*² (R* <= R) acts on the rotation the tangential spring
    // already couples to the translation. With u = Rφ, the pair of springs is the stiffness
    // k_t [[1, 1], [1, 1 + β]] on (x, u) with masses (m, m/g): the highest eigenvalue of
    // M⁻¹K is k_t/m · (T + √(T² − 4D))/2, T = 1 + g(1 + β), D = gβ, which is k_t (1 + g)/m
    // when β = 0 (rolling_resistance.hpp).
    const double b = material.rollingStiffnessRatio;
    const double t = 1 + g * (1 + b), d = g * b;
    return std::max(normal, material.tangentialStiffness * 0.5 * (t + std::sqrt(t * t - 4 * d)));
  }
  return std::max(normal, material.tangentialStiffness * rotational);
}

double criticalTimestep(const ParticleStore& particles, const Material& material) {
  double dt = std::numeric_limits<double>::infinity();
  // The tangential spring counts whatever the friction now: the World caches this once for
  // the run, and friction may change between stages.
  for (int k = 0; k < particles.size(); ++k) {
    dt = std::min(dt, 2.0 * std::sqrt(0.5 * particles.mass[k] / stiffestSpring(particles, material, k, true)));
  }
  return dt;
}

double packingTimestep(const ParticleStore& particles, const Material& material, std::span<const int> contactCount,
                       int* particle, int* contacts) {
  const double zeta = dampingRatio(material.restitution);
  const double dampingFactor = std::sqrt(1 + zeta * zeta) - zeta;
  double dt = std::numeric_limits<double>::infinity();
  for (int k = 0; k < particles.size(); ++k) {
    const int count = contactCount[static_cast<size_t>(k)];
    if (particles.motion[k] != Motion::Dynamic || count == 0) continue;
    // The same spring as criticalTimestep(), once per contact; frictionless contacts (the
    // friction as it is now) have no tangential spring.
    const double stiffest = stiffestSpring(particles, material, k, material.friction > 0);
    const double bound = dampingFactor * 2.0 * std::sqrt(0.5 * particles.mass[k] / (stiffest * count));
    if (bound < dt) {
      dt = bound;
      if (particle) *particle = k;
      if (contacts) *contacts = count;
    }
  }
  return dt;
}

}  // namespace grainlab

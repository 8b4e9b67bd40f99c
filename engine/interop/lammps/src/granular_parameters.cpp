#include "grainlab/lammps/granular_parameters.hpp"

#include <cmath>

#include "grainlab/math.hpp"

namespace grainlab::lammps {
namespace {

// The engine's ζ(e) (engine/src/contact_law.hpp): ζ = −ln e / √(π² + ln² e), 0 for e = 1.
double dampingRatio(double e) {
  if (e >= 1) return 0;
  const double l = std::log(e);
  return -l / std::sqrt(kPi * kPi + l * l);
}

}  // namespace

GranularParameters granularParameters(const Material& material, double pairMass, double wallMass) {
  const double zeta = dampingRatio(material.restitution);
  GranularParameters p;
  p.kn = material.normalStiffness;
  p.kt = material.tangentialStiffness;
  p.gammaN = 2 * zeta * std::sqrt(p.kn / pairMass);
  p.gammaT = 2 * zeta * std::sqrt(p.kt / pairMass);
  p.gammaNWall = 2 * zeta * std::sqrt(p.kn / wallMass);
  p.gammaTWall = 2 * zeta * std::sqrt(p.kt / wallMass);
  p.friction = material.friction;
  return p;
}

}  // namespace grainlab::lammps

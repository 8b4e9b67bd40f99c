#pragma once
// Axial (direction, not vector) angles: θ and θ + 180° are the same direction. Directions are
// averaged only through e^{2iθ} (docs/micromechanics.md, Conventions).
#include <cmath>
#include <complex>

#include "grainlab/math.hpp"

namespace grainlab::analysis {

/// An axial direction in degrees wrapped into [0, 180).
inline double axialDeg(double deg) {
  double r = std::fmod(deg, 180.0);
  if (r < 0) r += 180.0;
  // fmod of a tiny negative number plus 180 can round up to 180 itself.
  if (r >= 180.0) r = 0.0;
  return r;
}

/// A difference of axial directions in degrees wrapped into [−90, 90).
inline double wrapAxialDeg(double deg) { return axialDeg(deg + 90.0) - 90.0; }

/// A second-order Fourier term a·cos 2(θ − θ_k) as the complex number A = a e^{2iθ_k}.
/// thetaDeg in degrees.
inline std::complex<double> axialComplex(double a, double thetaDeg) {
  return std::polar(a, 2.0 * radians(thetaDeg));
}

/// The direction of a complex term A: ½ arg A in degrees, in [0, 180). Zero when A = 0,
/// where the direction means nothing.
inline double axialDirectionDeg(std::complex<double> A) {
  return axialDeg(0.5 * degrees(std::atan2(A.imag(), A.real())));
}

}  // namespace grainlab::analysis

#include "grainlab/analysis/stress_direction.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>

#include "grainlab/analysis/angles.hpp"
#include "grainlab/analysis/sff.hpp"

namespace grainlab::analysis {

namespace {

// Σ a_k e^{2iθ_k} over the given terms; its half-argument is the weighted axial mean.
template <std::size_t N>
std::complex<double> sumTerms(const FabricState& f, const Term (&terms)[N]) {
  std::complex<double> z{};
  for (Term k : terms) z += f.A(k);
  return z;
}

}  // namespace

double thetaSigmaMacroDeg(const StressTensor& s) {
  // atan2 keeps the quadrant of 2θσ, so the major (not the minor) direction comes out.
  return axialDirectionDeg({s.s11 - s.s22, s.s12 + s.s21});
}

double thetaSigmaEq7Deg(const FabricState& f) {
  static constexpr Term all[] = {Term::c, Term::n, Term::t, Term::ln, Term::lt};
  return axialDirectionDeg(sumTerms(f, all));
}

double thetaSigmaEq10Deg(const FabricState& f) {
  std::complex<double> z{};
  for (Term k : {Term::c, Term::n, Term::t}) z += axialComplex(1.0, f.thetaDeg(k));
  return axialDirectionDeg(z);
}

double thetaSigmaEq11Deg(const FabricState& f) {
  static constexpr Term three[] = {Term::c, Term::n, Term::t};
  return axialDirectionDeg(sumTerms(f, three));
}

double thetaSigmaSffDeg(const FabricState& f) { return axialDirectionDeg(sffClosedForm(f).Z); }

double omegaDeg(double thetaSigmaDeg, double thetaStrainRateDeg) {
  return wrapAxialDeg(thetaSigmaDeg - thetaStrainRateDeg);
}

double phiMobDeg(const StressTensor& s) {
  const double trace = s.s11 + s.s22;
  if (!(trace > 0)) return 0.0;
  const double ratio = std::hypot(s.s11 - s.s22, s.s12 + s.s21) / trace;
  return degrees(std::asin(std::min(1.0, ratio)));
}

StressDirections stressDirections(const StressTensor& s, const FabricState& f,
                                  double thetaStrainRateDeg) {
  StressDirections d;
  d.theta_sigma_macro_deg = thetaSigmaMacroDeg(s);
  d.theta_sigma_micro_deg = thetaSigmaEq7Deg(f);
  d.theta_sigma_eq10_deg = thetaSigmaEq10Deg(f);
  d.theta_sigma_eq11_deg = thetaSigmaEq11Deg(f);
  d.theta_sigma_sff_deg = thetaSigmaSffDeg(f);
  d.omega_macro_deg = omegaDeg(d.theta_sigma_macro_deg, thetaStrainRateDeg);
  d.omega_micro_deg = omegaDeg(d.theta_sigma_micro_deg, thetaStrainRateDeg);
  d.omega_eq10_deg = omegaDeg(d.theta_sigma_eq10_deg, thetaStrainRateDeg);
  d.omega_eq11_deg = omegaDeg(d.theta_sigma_eq11_deg, thetaStrainRateDeg);
  d.omega_sff_deg = omegaDeg(d.theta_sigma_sff_deg, thetaStrainRateDeg);
  d.phi_mob_deg = phiMobDeg(s);
  return d;
}

}  // namespace grainlab::analysis

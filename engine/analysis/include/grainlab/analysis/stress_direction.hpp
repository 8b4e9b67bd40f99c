#pragma once
// The major principal stress direction θσ from the stress tensor (macro) and from the fabric
// (paper Eqs. 7, 10, 11), the non-coaxiality ω = θσ − θ_ε̇ and the mobilised friction angle.
// All angles in degrees; directions in [0, 180), ω in [−90, 90). Compression positive, so the
// major principal stress is the larger one.
#include "grainlab/analysis/fabric.hpp"
#include "grainlab/stress.hpp"

namespace grainlab::analysis {

/// θσ = ½ atan2(σ12 + σ21, σ11 − σ22) in [0, 180): the major principal direction of the
/// symmetric part. (Paper Eq. 6 as printed, ½ atan(2σ12/(σ22 − σ11)), returns 90° − θσ or
/// −θσ mod 90°; it is deliberately not offered.) 0 for an isotropic stress.
double thetaSigmaMacroDeg(const StressTensor& s);

/// Paper Eq. (7): ½ atan2(Σ a_k sin 2θ_k, Σ a_k cos 2θ_k) over k ∈ {c, n, t, ln, lt}, in
/// [0, 180). Second-order accurate in the coefficients.
double thetaSigmaEq7Deg(const FabricState& f);

/// Paper Eq. (10): the unweighted circular mean (on 2θ) of θ_c, θ_n, θ_t, in [0, 180). Valid
/// only when a_c, a_n, a_t are nearly equal. The a-weighted circular mean of the same three
/// directions is exactly Eq. (11): use thetaSigmaEq11Deg for it.
double thetaSigmaEq10Deg(const FabricState& f);

/// Paper Eq. (11): Eq. (7) without the ln and lt terms, i.e. the a-weighted circular mean of
/// θ_c, θ_n, θ_t, in [0, 180). Error first order in a_ln, a_lt.
double thetaSigmaEq11Deg(const FabricState& f);

/// ½ arg Z of the stress-force-fabric closed form (sff.hpp), in [0, 180): the principal
/// direction the fabric's Fourier forms imply exactly, with no truncation.
double thetaSigmaSffDeg(const FabricState& f);

/// ω = θσ − θ_ε̇ wrapped into [−90, 90). The biaxial test has θ_ε̇ = 90°.
double omegaDeg(double thetaSigmaDeg, double thetaStrainRateDeg = 90.0);

/// sin φ_mob = √((σ11 − σ22)² + (σ12 + σ21)²) / (σ11 + σ22), from the symmetric part; degrees in
/// [0, 90]. 0 when σ11 + σ22 ≤ 0 (no compressive mean stress); 90 if the ratio exceeds 1.
double phiMobDeg(const StressTensor& s);

/// Everything above for one sample, degrees.
struct StressDirections {
  double theta_sigma_macro_deg = 0;  ///< from the stress tensor
  double theta_sigma_micro_deg = 0;  ///< Eq. (7)
  double theta_sigma_eq10_deg = 0;   ///< Eq. (10), unweighted mean of θ_c, θ_n, θ_t
  double theta_sigma_eq11_deg = 0;   ///< Eq. (11) = a-weighted mean of θ_c, θ_n, θ_t
  double theta_sigma_sff_deg = 0;    ///< exact closed form
  double omega_macro_deg = 0;        ///< each θσ minus θ_ε̇, in [−90, 90)
  double omega_micro_deg = 0;
  double omega_eq10_deg = 0;
  double omega_eq11_deg = 0;
  double omega_sff_deg = 0;
  double phi_mob_deg = 0;            ///< from the stress tensor
};

StressDirections stressDirections(const StressTensor& s, const FabricState& f,
                                  double thetaStrainRateDeg = 90.0);

}  // namespace grainlab::analysis

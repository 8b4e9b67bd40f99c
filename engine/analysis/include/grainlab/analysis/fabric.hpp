#pragma once
// Anisotropy of contact normals, contact forces and branch vectors, measured from discrete
// contacts with the second-order G0/G2 estimators of docs/micromechanics.md (paper Eqs. 2-4):
//   E(θ)   = (1/2π)[1 + a_c cos 2(θ − θ_c)]
//   f_n(θ) = f0 [1 + a_n cos 2(θ − θ_n)],     f_t(θ) = f0 [a_w − a_t sin 2(θ − θ_t)]
//   l_n(θ) = l0 [1 + a_ln cos 2(θ − θ_ln)],   l_t(θ) = −l0 a_lt sin 2(θ − θ_lt)
// θ is the direction of a contact end's outward normal, counter-clockwise from the 1-axis.
#include <complex>
#include <cstdint>
#include <span>

#include "grainlab/contact.hpp"
#include "grainlab/math.hpp"
#include "grainlab/periodic_cell.hpp"

namespace grainlab::analysis {

/// The five anisotropy terms; A_k = a_k e^{2iθ_k}.
enum class Term { c, n, t, ln, lt };

/// Angles are stored in degrees (as series.csv reports them), directions wrapped to [0, 180).
/// Coefficients a_k are dimensionless and ≥ 0. A direction means nothing when its a_k is
/// below about twice the noise floor 1.25·√(2/contacts).
struct FabricState {
  double a_c = 0, theta_c_deg = 0;    ///< contact normals
  double a_n = 0, theta_n_deg = 0;    ///< mean normal force
  double a_t = 0, theta_t_deg = 0;    ///< mean tangential force
  double a_w = 0;                     ///< f_t offset from moment equilibrium (momentEquilibriumAw)
  double a_ln = 0, theta_ln_deg = 0;  ///< normal component of branch vectors
  double a_lt = 0, theta_lt_deg = 0;  ///< tangential component of branch vectors
  double f0 = 0;                      ///< N/m: mean normal force, G0[f_n]
  double l0 = 0;                      ///< m: mean normal branch length, G0[l_n]
  /// Dimensionless G0[f_t]/f0: the direct, noisier measure of a_w. A check on equilibrium.
  double a_w_direct = 0;
  /// Dimensionless G0[l_t]/l0: ≈ 0 for the paper's l_t form; a self-check of the data.
  double lt0_ratio = 0;
  std::int64_t ends = 0;      ///< contact ends that entered the averages
  std::int64_t contacts = 0;  ///< contacts with at least one such end (the sample size)

  /// A_k = a_k e^{2iθ_k} (dimensionless).
  std::complex<double> A(Term k) const;
  double a(Term k) const;        ///< a_k, dimensionless
  double thetaDeg(Term k) const; ///< θ_k, degrees in [0, 180)
};

/// a_w from moment equilibrium (σ12 = σ21), using the other coefficients of `s`:
/// a_w = [a_c a_t S_ct + a_t a_ln S_ln,t − a_lt (a_n S_n,lt + a_c S_c,lt)] / (2 + a_c a_ln C_c,ln)
/// with C_kj = cos 2(θ_k − θ_j), S_kj = sin 2(θ_k − θ_j). Dimensionless. If the denominator is
/// not positive (possible only for a few contacts, far outside the Fourier forms' range of
/// a ≤ 1) it returns s.a_w_direct.
double momentEquilibriumAw(const FabricState& s);

/// Measures the anisotropy over the contact ends of particles with inside != 0 (see
/// contact_ends.hpp): A_c = 2⟨e⟩, then f0, A_n, A_t, l0, A_ln, A_lt from G0/G2 of f_n, f_t,
/// l_n, l_t, and a_w from moment equilibrium. One pass, no allocation. With no ends the
/// state is all zero; with zero f0 (or l0) the force (or branch) terms are zero.
/// Throws std::invalid_argument if inside and centroids differ in size and std::out_of_range
/// for a contact naming a particle that does not exist. In a periodic `cell`, branch vectors
/// run to the image (forEachInsideEnd).
FabricState measureFabric(std::span<const ContactRecord> contacts, std::span<const Vec2> centroids,
                          std::span<const unsigned char> inside, const PeriodicCell* cell = nullptr);

}  // namespace grainlab::analysis

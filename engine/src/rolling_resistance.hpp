#pragma once
// Rolling resistance for discs: the elastic-plastic spring-dashpot model ("type C") of Ai,
// Chen, Rotter and Ooi (2011, Powder Technology 206, 269-282), as LAMMPS's `rolling sds` and
// PFC's rrlinear. A couple resists the relative rotation of two touching discs (or of a disc
// and a wall): in 2D the relative rotation is one angle θ_r, accumulated while the contact
// lasts, and
//   M_r = −k_r θ_r − c_r ω_r,   |k_r θ_r| ≤ μ_r R* f_n   (the spring stops at the cap),
// with ω_r = ω_j − ω_i, R* = R_i R_j / (R_i + R_j) (R_i against a wall), the rolling stiffness
// k_r = β k_t R*² (β: material.rolling_stiffness_ratio, 1 as PFC's rrlinear) and the damper
// c_r = 2 η_r √(I_r k_r) (η_r: material.rolling_damping), where
// I_r = 1 / (1/(I_i + m_i R_i²) + 1/(I_j + m_j R_j²)) is the pair's inertia for relative rolling
// about the contact (a wall's or a fixed particle's term drops out). While the spring sits at
// the cap (full mobilisation) the damper is off, as in Ai's model with f = 0: the couple is then
// exactly ±μ_r R* f_n, the plastic rolling couple.
#include <algorithm>
#include <cmath>

#include "contact_law.hpp"

namespace grainlab {

struct RollingResistance {
  double stiffnessRatio;       ///< β: k_r = β k_t R*²
  double tangentialStiffness;  ///< k_t, N/m
  double friction;             ///< μ_r (dimensionless: the cap is μ_r R* f_n)
  double damping;              ///< η_r, a ratio of the critical damping 2√(I_r k_r)
  static constexpr bool kKeepsHistory = true;

  /// What a pair's couple needs of its particles, fixed while the pair lasts: the solver keeps
  /// one per pair (the square root and divisions stay out of the force loop).
  struct Pair {
    double stiffness;       ///< k_r, N·m/rad
    double compliance;      ///< 1/k_r
    double capPerForce;     ///< μ_r R*, m
    double damping;         ///< c_r, N·m·s/rad
  };
  /// The constants of a pair with effective radius R* (m) and rolling inertia I_r (kg·m²).
  Pair pair(double radius, double inertia) const {
    const double kr = stiffnessRatio * tangentialStiffness * radius * radius;
    return {kr, 1 / kr, friction * radius, 2 * damping * std::sqrt(inertia * kr)};
  }

  /// Returns the couple on j (on i it is the opposite) for the relative spin c.spin, and
  /// updates the relative rotation `history` (θ_r, rad).
  /// Written without branches: whether a contact rolls plastically changes from step to step
  /// in a packing, which a branch would mispredict.
  double couple(double fn, const ContactMotion& c, const Pair& pair, double dt, double& history) const {
    history += c.spin * dt;
    const double spring = -pair.stiffness * history;
    const double cap = std::max(pair.capPerForce * fn, 0.0);  // none while the dashpot pulls
    const double held = std::clamp(spring, -cap, cap);
    const bool plastic = std::abs(spring) >= cap;  // the spring sits at the cap: plastic rolling
    history = plastic ? -held * pair.compliance : history;
    return plastic ? held : spring - pair.damping * c.spin;
  }
  /// The rolling spring's elastic energy, J (per metre).
  static double energy(const Pair& pair, double history) { return 0.5 * pair.stiffness * history * history; }
};

}  // namespace grainlab

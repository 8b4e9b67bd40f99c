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
#include <cmath>

#include "contact_law.hpp"

namespace grainlab {

template <bool kDamped>
struct RollingResistance {
  double stiffnessRatio;       ///< β: k_r = β k_t R*²
  double tangentialStiffness;  ///< k_t, N/m
  double friction;             ///< μ_r (dimensionless: the cap is μ_r R* f_n)
  double damping;              ///< η_r, a ratio of the critical damping 2√(I_r k_r)
  static constexpr bool kKeepsHistory = true;
  static constexpr bool kNeedsInertia = kDamped;

  double stiffness(double radius) const { return stiffnessRatio * tangentialStiffness * radius * radius; }

  /// Returns the couple on j (on i it is the opposite) and updates the relative rotation
  /// `history` (θ_r, rad).
  double couple(double fn, const ContactMotion& c, double dt, double& history) const {
    const double kr = stiffness(c.radius);
    history += c.spin * dt;
    const double spring = -kr * history;
    const double cap = fn > 0 ? friction * c.radius * fn : 0.0;
    if (std::abs(spring) >= cap) {
      history = std::copysign(cap, history) / kr;  // the spring sits at the cap: plastic rolling
      return -kr * history;
    }
    if constexpr (kDamped) return spring - 2 * damping * std::sqrt(c.inertia * kr) * c.spin;
    return spring;
  }
  /// The rolling spring's elastic energy, J (per metre).
  double energy(double radius, double history) const { return 0.5 * stiffness(radius) * history * history; }
};

}  // namespace grainlab

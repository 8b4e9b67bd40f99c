#pragma once
// Contact laws, composed from a normal model and a tangential model (as LAMMPS GRANULAR
// composes its sub-models). Each model is a small value type with inline force functions;
// the ContactSolver instantiates its force loop once per combination, so a law costs no
// virtual call per contact. To add a law (Hertz-Mindlin, a twisting model): write its model
// in its own header with the same members (a slot in ContactHistory if it keeps history), and
// add one case to ContactSolver::computeForces' dispatch.
#include <cmath>

#include "grainlab/math.hpp"

namespace grainlab {

/// Relative motion at a contact point, seen from body i: vn = (v_j − v_i)·n (negative when
/// approaching), vt = (v_j − v_i)·t, spin = ω_j − ω_i (a wall's is 0).
struct ContactMotion {
  double overlap;           ///< m, > 0
  double vn;                ///< m/s
  double vt;                ///< m/s
  double spin = 0;          ///< rad/s (set where a law resists rolling)
};

/// Linear spring-dashpot: f_n = k_n δ − c_n v_n. As in LAMMPS's default, the dashpot may
/// pull slightly at the very end of a collision's unloading: that is what makes the
/// restitution of a binary collision exactly e (clamping at zero would release the pair
/// early and raise the rebound speed).
struct LinearSpringDashpot {
  double stiffness;  ///< k_n, N/m
  double force(const ContactMotion& c, double damping) const { return stiffness * c.overlap - damping * c.vn; }
  double energy(double overlap) const { return 0.5 * stiffness * overlap * overlap; }
};

/// Cundall-Strack: an incremental tangential spring kept while the contact persists,
/// capped by Coulomb friction; when it slides the spring is reset to the cap.
struct CundallStrack {
  double stiffness;  ///< k_t, N/m
  double friction;   ///< μ
  static constexpr bool kKeepsHistory = true;
  /// Returns f_t (the force on j along t) and updates the spring elongation `history`.
  double force(double fn, const ContactMotion& c, double damping, double dt, double& history) const {
    history += c.vt * dt;
    double ft = -stiffness * history - damping * c.vt;
    const double cap = fn > 0 ? friction * fn : 0.0;
    if (std::abs(ft) > cap) {
      ft = std::copysign(cap, ft);
      history = -(ft + damping * c.vt) / stiffness;  // spring + dashpot sit at the cap
    }
    return ft;
  }
  double energy(double history) const { return 0.5 * stiffness * history * history; }
};

/// No friction: no tangential force and no history to keep.
struct Frictionless {
  static constexpr bool kKeepsHistory = false;
  double force(double, const ContactMotion&, double, double, double&) const { return 0; }
};

/// No rolling resistance: no couple and no history to keep.
struct NoRolling {
  static constexpr bool kKeepsHistory = false;
};

/// A law's sub-models: normal force, tangential force, and the couple resisting relative
/// rotation (rolling_resistance.hpp). Each sub-model keeps its own slot of the pair's
/// ContactHistory.
template <class Normal, class Tangential, class Rolling = NoRolling>
struct ContactLaw {
  Normal normal;
  Tangential tangential;
  Rolling rolling{};
};

/// Damping ratio ζ of a linear spring-dashpot whose binary collision has restitution e:
/// ζ = −ln e / √(π² + ln² e); the coefficient for effective mass m* is 2ζ√(m* k).
inline double dampingRatio(double restitution) {
  if (restitution >= 1) return 0;
  const double l = std::log(restitution);
  return -l / std::sqrt(kPi * kPi + l * l);
}

}  // namespace grainlab

#pragma once

namespace grainlab {

/// The one contact material of a scene (SI units, 2D per metre of thickness).
struct Material {
  double density = 2650;              ///< kg/m³ (per metre of thickness: mass/area)
  double normalStiffness = 1e8;       ///< k_n, N/m per metre of thickness
  double tangentialStiffness = 5e7;   ///< k_t, N/m
  double friction = 0.5;              ///< Coulomb coefficient μ
  double restitution = 1.0;           ///< normal coefficient of restitution e in (0, 1]
  double localDamping = 0.0;          ///< Cundall's non-viscous damping α in [0, 1)
  // Rolling resistance for discs (engine/src/rolling_resistance.hpp); none when μ_r = 0.
  double rollingFriction = 0.0;       ///< μ_r: the plastic rolling couple is μ_r R* f_n
  double rollingStiffnessRatio = 1.0; ///< β: the rolling spring is k_r = β k_t R*² per radian
  double rollingDamping = 0.0;        ///< η_r: the rolling damper's ratio of its critical value
};

}  // namespace grainlab

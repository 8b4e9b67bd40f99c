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
};

}  // namespace grainlab

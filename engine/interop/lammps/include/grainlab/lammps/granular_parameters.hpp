#pragma once
// grainlab's contact material as the coefficients of LAMMPS's pair_style gran/hooke/history
// and fix wall/gran hooke/history (docs/lammps.md, "The material mapping"):
//   kn, kt   the same springs (N/m per metre of thickness, as the masses are per metre)
//   γn, γt   LAMMPS damps with m_eff·γ·v, grainlab with 2ζ√(m* k)·v, ζ from the restitution:
//            γ = 2ζ√(k/m*), exact for the effective mass m* it is computed for
//   xmu      the friction coefficient μ; dampflag 1 (the tangential dashpot is on, as in grainlab)
#include "grainlab/material.hpp"

namespace grainlab::lammps {

struct GranularParameters {
  double kn = 0;           ///< N/m
  double kt = 0;           ///< N/m
  double gammaN = 0;       ///< 1/s, particle-particle
  double gammaT = 0;       ///< 1/s
  double gammaNWall = 0;   ///< 1/s, particle-wall
  double gammaTWall = 0;   ///< 1/s
  double friction = 0;     ///< μ
};

/// The coefficients that reproduce grainlab's damping exactly for a pair of effective mass
/// `pairMass` (kg/m) and a particle of mass `wallMass` against a wall; other pairs are damped
/// by √(pairMass/m*) times grainlab's coefficient.
GranularParameters granularParameters(const Material& material, double pairMass, double wallMass);

}  // namespace grainlab::lammps

#pragma once
// How large a timestep explicit integration of the contact springs can take: for one contact
// (the critical timestep, fixed by the particles) and for the packing as it stands (which
// depends on how many contacts each particle carries).
#include <span>

#include "grainlab/material.hpp"
#include "grainlab/particle_store.hpp"

namespace grainlab {

/// Particle k's stiffest contact spring as seen through its rotational inertia, N/m: a force
/// at the bounding radius R, off the centre's line, moves the contact point as if the mass
/// were m / (1 + m R²/I). A disc's normal force passes through its centre; a polygon's need
/// not. `tangential`: whether the tangential spring counts (and with it a disc's rolling
/// spring, when the material has rolling resistance).
double stiffestSpring(const ParticleStore& particles, const Material& material, int k, bool tangential);

/// 2·√(m*/k) for the stiffest, lightest contact (World::criticalTimestep).
double criticalTimestep(const ParticleStore& particles, const Material& material);

/// The packing's bound (World::packingTimestep), given each particle's number of touching
/// contacts. `particle` and `contacts` (optional) receive the particle that sets it and its
/// contact count.
double packingTimestep(const ParticleStore& particles, const Material& material, std::span<const int> contactCount,
                       int* particle, int* contacts);

}  // namespace grainlab

#pragma once
// The DEM's time stepper: leapfrog (kick, drift) in double precision.
#include "grainlab/particle_store.hpp"

namespace grainlab {

/// Kick and drift particles [begin, end) by dt from the forces on them, then start their next
/// force from the body force: one pass, so each particle's data is loaded once (three loops
/// over the particles took a fifth of a disc pile's step). On the wide path (`widePath`) a
/// polygon's or a clump's cos and sin are advanced by its turn (incremental_rotation.hpp)
/// instead of taken from its angle by sincos, and particles are stepped several per
/// instruction (disc_leapfrog_kernel.hpp, polygon_leapfrog_kernel.hpp: the same bits as
/// leapfrogAdvanceScalar()).
void leapfrogAdvance(ParticleStore& particles, double dt, int begin, int end, bool widePath = false);

/// leapfrogAdvance() one particle at a time: the baseline path, and the reference the wide
/// path's kernels are tested against. `incrementalRotation` advances polygons' and clumps' cos
/// and sin as the wide path does.
void leapfrogAdvanceScalar(ParticleStore& particles, double dt, int begin, int end, bool incrementalRotation);

}  // namespace grainlab

#pragma once
// Leapfrog for a scene of discs with polygons or clumps, several particles per instruction: the
// wide path's scalar loop (leapfrogAdvanceScalar() with incremental rotation), operation for
// operation, so it gives that loop's bits. A spinning polygon's or clump's cos and sin are
// rotated by the series of incremental_rotation.hpp in every lane at once and kept where its
// turn is at most kMaxIncrementalTurn; the rare lane with a larger turn takes sincos of its new
// angle after.
#include "grainlab/particle_store.hpp"

namespace grainlab {

/// Kicks and drifts particles [begin, end) by dt, advances the polygons' and clumps' cos and sin
/// by their turn, and starts their next force from the body force.
void leapfrogPolygonsWide(ParticleStore& particles, double dt, int begin, int end);

}  // namespace grainlab

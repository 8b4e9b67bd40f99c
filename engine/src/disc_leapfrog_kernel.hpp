#pragma once
// Leapfrog's kick and drift for a discs-only scene, several particles per instruction: the
// arithmetic of leapfrogAdvance(), operation for operation (no fused products: the build
// contracts none), so it gives the scalar loop's bits. A disc's angle is advanced only where
// it spins, as the scalar loop does, by a select instead of a branch.
#include "grainlab/particle_store.hpp"

namespace grainlab {

/// Kicks and drifts discs [begin, end) by dt and starts their next force from the body force.
/// Every particle in the range must be a disc.
void leapfrogDiscsWide(ParticleStore& particles, double dt, int begin, int end);

}  // namespace grainlab

#pragma once
// Cundall's local damping (local_damping.hpp) several particles per instruction: each force
// component and torque takes f − (α|f|)·sign(v) in the scalar loop's operations (no fused
// products: the build contracts none), so the wide path's forces keep its bits. Vectors of
// x y pairs are damped as they lie: a component is damped by its own velocity's sign.
#include "grainlab/particle_store.hpp"

namespace grainlab {

/// applyLocalDampingScalar() over particles [begin, end), on the widest instruction set the
/// CPU has.
void applyLocalDampingWide(ParticleStore& particles, int begin, int end, double alpha);

}  // namespace grainlab

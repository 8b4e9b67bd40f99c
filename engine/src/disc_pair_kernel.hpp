#pragma once
// The disc-disc contact law evaluated several pairs per instruction: the geometry of
// touchDiscs(), the linear spring-dashpot and Cundall-Strack of contact_law.hpp, in the
// same operations in the same order, lane by lane. With no fused multiply-add (the build
// forbids contraction and the kernel calls none), every lane rounds as the scalar code does,
// so the wide path gives the baseline's bits on any instruction set.
#include <cstdint>
#include <string>

namespace grainlab {

/// Slots are processed in blocks of this many: a multiple of any target's lanes of double.
inline constexpr int kDiscPairBlock = 16;

/// One step's disc-disc pairs in structure-of-arrays form (arrays padded to whole blocks;
/// a padding slot has i = j = 0, which never touches), the particles they read, and where
/// the results go.
struct DiscPairKernelInput {
  // Particles: position and velocity as x0 y0 x1 y1 …; spin and radius per particle.
  const double* position;
  const double* velocity;
  const double* spin;
  const double* radius;
  // Slots.
  const std::int64_t* i;
  const std::int64_t* j;
  const std::int64_t* state;  // the pair's PairState, in doubles from pairState
  const double* dampN;
  const double* dampT;
  int slots;                  // real slots (the rest of the last block is padding)
  double* pairState;          // the neighbour list's pairs viewed as doubles
  // Law.
  double normalStiffness, tangentialStiffness, friction, dt;
  bool frictional;
  // Results, per pair end: the force and torque to add to i at [s], to j at [endStride + s];
  // −0 where the pair is apart (adding −0 changes nothing, not even a zero's sign).
  double* endFx;
  double* endFy;
  double* endTorque;
  int endStride;
};

/// Evaluates slots [begin, end) (block multiples): writes each pair's history, fn, ft and
/// overlap into its PairState as the scalar loop does, and its end forces.
void discPairForces(const DiscPairKernelInput& in, int begin, int end);
/// The instruction set discPairForces runs on this CPU (Highway's name, e.g. "AVX3").
std::string discPairKernelTarget();

}  // namespace grainlab

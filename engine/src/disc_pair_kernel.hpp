#pragma once
// The disc-disc contact law evaluated several pairs per instruction: the geometry of
// touchDiscs() and the linear spring-dashpot and Cundall-Strack of contact_law.hpp, lane by
// lane. It is not the scalar code's arithmetic: 1/|d| comes from a single-precision estimate
// refined by Newton's method (no divider: the scalar code's square root and two divisions
// bounded the kernel), the sliding reset multiplies by 1/k_t, and products are fused. Each
// differs from the baseline's by rounding only; lanes do not interact, so the result does not
// depend on how the slots are split between threads, and the same instruction set gives the
// same bits on every run.
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
  const double* dampN;
  const double* dampT;
  // The pairs' state per slot: the tangential spring (read and written), and the last
  // step's fn, ft and overlap (written; all zero where the pair is apart).
  double* history;
  double* fn;
  double* ft;
  double* overlap;
  // Law.
  double normalStiffness, tangentialStiffness, friction, dt;
  bool frictional;
  // The particles' force (x0 y0 x1 y1 …) and torque, to which each touching pair adds its
  // shares at once, in pair order, unless that end waits: where blockDefers[s / kDiscPairBlock]
  // is 1 (blockDefers null: nowhere), slot s's i end with iEnd[s] >= 0 writes its share as
  // fx fy torque at ends[4 iEnd[s]] instead, and so does its j end with jEnd[s] (−0 where the
  // pair is apart: adding −0 changes nothing, not even a zero's sign). Several threads each
  // add the ends of the particles they own and leave the others' waiting (disc_pair_batch.hpp).
  double* force;
  double* torque;
  double* ends;
  const std::int32_t* iEnd;
  const std::int32_t* jEnd;
  const std::uint8_t* blockDefers = nullptr;
  // Rolling resistance (rolling_resistance.hpp), where the scene has it; null otherwise. Per
  // slot: the relative rotation θ_r (read and written; zero where the pair is apart) and the
  // pair's constants k_r, 1/k_r, μ_r R*, c_r. A frictionless step keeps θ_r as it is (the
  // baseline's frictionless law has no couple) and clears it where the pair parts.
  double* rollingHistory = nullptr;
  const double* rollingStiffness = nullptr;
  const double* rollingCompliance = nullptr;
  const double* rollingCapPerForce = nullptr;
  const double* rollingDamping = nullptr;
  // Discs (required without bodyI): per slot, the radii of i and j (DiscPairBatch::layRadii),
  // loaded in order where the members' kernel gathers `radius`.
  const double* radiusI = nullptr;
  const double* radiusJ = nullptr;
  // Clumps' member discs (member_contacts.hpp), one thread only; null for a disc scene. Then
  // position and radius are the members', i and j name members, and the slots' bodies (whose
  // velocity and spin are read, and to which force and torque go) are bodyI and bodyJ; each
  // member sits at lever (x0 y0 x1 y1 …, world frame) from its body's centroid.
  const std::int64_t* bodyI = nullptr;
  const std::int64_t* bodyJ = nullptr;
  const double* lever = nullptr;
  // A periodic cell (docs/periodic-cell.md), null otherwise: per slot, j's image n (n1, n2 as
  // doubles), so that j is met at x_j + h n, and that image moves with the cell's affine
  // velocity, adding L (x_j + h n − x_i) to the relative velocity. The cell's edges h and its
  // velocity gradient L (row-major: h11 h12 h21 h22) change every step, the slots' n only at a
  // rebuild.
  const double* imageN1 = nullptr;
  const double* imageN2 = nullptr;
  double cellEdges[4] = {};
  double velocityGradient[4] = {};
};

/// Evaluates slots [begin, end) (block multiples): the pairs' state and their end forces.
void discPairForces(const DiscPairKernelInput& in, int begin, int end);
/// The instruction set discPairForces runs on this CPU (Highway's name, e.g. "AVX3").
std::string discPairKernelTarget();

}  // namespace grainlab

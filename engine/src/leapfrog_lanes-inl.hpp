// Leapfrog's kick and drift several particles per instruction, as leapfrogAdvance() steps a
// disc, operation for operation (no fused products: the build contracts none): the loop the wide
// path's leapfrog kernels share (disc_leapfrog_kernel.cpp, polygon_leapfrog_kernel.cpp). Those
// files include it once per Highway target after hwy/highway.h (foreach_target re-includes
// them), hence the toggle guard in place of #pragma once.
#if defined(GRAINLAB_LEAPFROG_LANES_INL_HPP) == defined(HWY_TARGET_TOGGLE)
#ifdef GRAINLAB_LEAPFROG_LANES_INL_HPP
#undef GRAINLAB_LEAPFROG_LANES_INL_HPP
#else
#define GRAINLAB_LEAPFROG_LANES_INL_HPP
#endif

#include <hwy/highway.h>

#include <cstdint>

#include "grainlab/particle_store.hpp"

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// One particle as leapfrogAdvance() kicks and drifts it (its angle; not its cos and sin): the
// ranges' ends that do not fill a vector.
HWY_INLINE void KickDriftOne(ParticleStore& p, double dt, int k) {
  p.velocity[k] += p.force[k] * (p.invMass[k] * dt);
  p.spin[k] += p.torque[k] * (p.invInertia[k] * dt);
  p.position[k] += p.velocity[k] * dt;
  if (p.spin[k] != 0) p.angle[k] += p.spin[k] * dt;
  p.force[k] = p.bodyForce(k);
  p.torque[k] = 0;
}

/// Kicks and drifts whole vectors of particles from `begin` on, as KickDriftOne() would, and
/// calls `stepped(k, spin)` once particles [k, k + lanes) are stepped, with their new spin.
/// Returns the first particle not stepped: the rest of [begin, end) fills no vector.
template <class Stepped>
HWY_INLINE int KickDriftLanes(ParticleStore& p, double dt, int begin, int end, const Stepped& stepped) {
  const hn::ScalableTag<double> d;
  const hn::RebindToUnsigned<decltype(d)> du;
  const hn::RebindToSigned<decltype(d)> di;
  const hn::Rebind<std::uint32_t, decltype(d)> d32;
  const hn::Rebind<std::uint8_t, decltype(d)> d8;
  const int lanes = static_cast<int>(hn::Lanes(d));
  double* const x = p.position.data()->data();
  double* const v = p.velocity.data()->data();
  double* const f = p.force.data()->data();
  double* const angle = p.angle.data();
  double* const w = p.spin.data();
  double* const tau = p.torque.data();
  const double* const invMass = p.invMass.data();
  const double* const invInertia = p.invInertia.data();
  const double* const mass = p.mass.data();
  const std::uint8_t* const motion = reinterpret_cast<const std::uint8_t*>(p.motion.data());
  const auto step = hn::Set(d, dt);
  const auto zero = hn::Zero(d);
  const auto dynamic = hn::Zero(du);  // Motion::Dynamic
  // Vectors of x y pairs (x0 y0 x1 y1 …) are read and written as they lie; a per-particle
  // value reaches both of its lanes by a table lookup (0 0 1 1 … for the first half of the
  // particles, then the second): two shuffles a vector where deinterleaving took four.
  // The weight's x y pairs likewise: the lower and upper vectors' differ where a vector holds
  // one double (HWY_SCALAR, the target of an x86-64 without SSSE3).
  HWY_ALIGN std::int64_t pairLanes[2 * hn::MaxLanes(d)];
  HWY_ALIGN double gravity[2 * hn::MaxLanes(d)];
  for (int l = 0; l < 2 * lanes; ++l) {
    pairLanes[l] = l / 2;
    gravity[l] = l % 2 ? p.gravity.y() : p.gravity.x();
  }
  const auto lower = hn::IndicesFromVec(d, hn::Load(di, pairLanes));
  const auto upper = hn::IndicesFromVec(d, hn::Load(di, pairLanes + lanes));
  const auto gLower = hn::Load(d, gravity);
  const auto gUpper = hn::LoadU(d, gravity + lanes);
  int k = begin;
  for (; k + lanes <= end; k += lanes) {
    double* const v0 = v + 2 * k;
    double* const v1 = v0 + lanes;
    double* const f0 = f + 2 * k;
    double* const f1 = f0 + lanes;
    double* const x0 = x + 2 * k;
    double* const x1 = x0 + lanes;
    // v += f (m⁻¹ dt); ω += τ (I⁻¹ dt); x += v dt
    const auto kick = hn::Mul(hn::LoadU(d, invMass + k), step);
    const auto vLower = hn::Add(hn::LoadU(d, v0), hn::Mul(hn::LoadU(d, f0), hn::TableLookupLanes(kick, lower)));
    const auto vUpper = hn::Add(hn::LoadU(d, v1), hn::Mul(hn::LoadU(d, f1), hn::TableLookupLanes(kick, upper)));
    hn::StoreU(vLower, d, v0);
    hn::StoreU(vUpper, d, v1);
    hn::StoreU(hn::Add(hn::LoadU(d, x0), hn::Mul(vLower, step)), d, x0);
    hn::StoreU(hn::Add(hn::LoadU(d, x1), hn::Mul(vUpper, step)), d, x1);
    const auto spin = hn::Add(hn::LoadU(d, w + k), hn::Mul(hn::LoadU(d, tau + k), hn::Mul(hn::LoadU(d, invInertia + k), step)));
    // The angle moves only where the particle spins (adding a zero turn could flip a −0).
    const auto a = hn::LoadU(d, angle + k);
    hn::StoreU(hn::IfThenElse(hn::Ne(spin, zero), hn::Add(a, hn::Mul(spin, step)), a), d, angle + k);
    hn::StoreU(spin, d, w + k);
    hn::StoreU(zero, d, tau + k);
    // The next force starts from the weight m g (dynamic particles) or +0.
    const auto isDynamic = hn::VecFromMask(
        d, hn::RebindMask(d, hn::Eq(hn::PromoteTo(du, hn::PromoteTo(d32, hn::LoadU(d8, motion + k))), dynamic)));
    const auto m = hn::LoadU(d, mass + k);
    hn::StoreU(hn::IfThenElseZero(hn::MaskFromVec(hn::TableLookupLanes(isDynamic, lower)),
                                  hn::Mul(hn::TableLookupLanes(m, lower), gLower)), d, f0);
    hn::StoreU(hn::IfThenElseZero(hn::MaskFromVec(hn::TableLookupLanes(isDynamic, upper)),
                                  hn::Mul(hn::TableLookupLanes(m, upper), gUpper)), d, f1);
    stepped(k, spin);
  }
  return k;
}

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#endif  // GRAINLAB_LEAPFROG_LANES_INL_HPP toggle

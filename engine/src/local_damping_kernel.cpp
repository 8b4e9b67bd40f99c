// Compiled once per instruction set Highway targets (foreach_target re-includes this file);
// applyLocalDampingWide() dispatches at run time to the widest the CPU has.
#include "local_damping_kernel.hpp"

#include "local_damping.hpp"

#ifdef GRAINLAB_HAS_WIDE_SIMD
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "local_damping_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void LocalDamping(ParticleStore& p, int begin, int end, double alpha) {
  const hn::ScalableTag<double> d;
  const hn::RebindToUnsigned<decltype(d)> du;
  const hn::RebindToSigned<decltype(d)> di;
  const hn::Rebind<std::uint32_t, decltype(d)> d32;
  const hn::Rebind<std::uint8_t, decltype(d)> d8;
  const int lanes = static_cast<int>(hn::Lanes(d));
  double* const f = p.force.data()->data();  // x y per particle
  const double* const v = p.velocity.data()->data();
  double* const tau = p.torque.data();
  const double* const w = p.spin.data();
  const std::uint8_t* const motion = reinterpret_cast<const std::uint8_t*>(p.motion.data());
  // A particle's motion reaches both lanes of its x y pair by a table lookup (0 0 1 1 … for
  // the first half of the particles, then the second), as in leapfrog_lanes-inl.hpp.
  HWY_ALIGN std::int64_t pairLanes[2 * hn::MaxLanes(d)];
  for (int l = 0; l < 2 * lanes; ++l) pairLanes[l] = l / 2;
  const auto lower = hn::IndicesFromVec(d, hn::Load(di, pairLanes));
  const auto upper = hn::IndicesFromVec(d, hn::Load(di, pairLanes + lanes));
  const auto a = hn::Set(d, alpha), zero = hn::Zero(d), plus = hn::Set(d, 1.0), minus = hn::Set(d, -1.0);
  // f − (α|f|)·sign(v), sign +1, −1 or +0 (also for a NaN velocity, as the scalar form).
  const auto damped = [&](auto force, auto velocity) HWY_ATTR {
    const auto sign = hn::IfThenElse(hn::Gt(velocity, zero), plus, hn::IfThenElseZero(hn::Lt(velocity, zero), minus));
    return hn::Sub(force, hn::Mul(hn::Mul(a, hn::Abs(force)), sign));
  };
  int k = begin;
  for (; k + lanes <= end; k += lanes) {
    const auto dynamic = hn::VecFromMask(
        d, hn::RebindMask(d, hn::Eq(hn::PromoteTo(du, hn::PromoteTo(d32, hn::LoadU(d8, motion + k))), hn::Zero(du))));
    double* const f0 = f + 2 * k;
    double* const f1 = f0 + lanes;
    const auto fl = hn::LoadU(d, f0), fu = hn::LoadU(d, f1);
    hn::StoreU(hn::IfThenElse(hn::MaskFromVec(hn::TableLookupLanes(dynamic, lower)), damped(fl, hn::LoadU(d, v + 2 * k)), fl),
               d, f0);
    hn::StoreU(hn::IfThenElse(hn::MaskFromVec(hn::TableLookupLanes(dynamic, upper)),
                              damped(fu, hn::LoadU(d, v + 2 * k + lanes)), fu),
               d, f1);
    const auto t = hn::LoadU(d, tau + k);
    hn::StoreU(hn::IfThenElse(hn::MaskFromVec(dynamic), damped(t, hn::LoadU(d, w + k)), t), d, tau + k);
  }
  applyLocalDampingScalar(p, k, end, alpha);  // the rest, which fills no vector
}

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grainlab {
HWY_EXPORT(LocalDamping);

void applyLocalDampingWide(ParticleStore& particles, int begin, int end, double alpha) {
  HWY_DYNAMIC_DISPATCH(LocalDamping)(particles, begin, end, alpha);
}

}  // namespace grainlab
#endif
#else  // a build without the wide path: simdPath() is always the baseline, which never calls this
#include <stdexcept>

namespace grainlab {
void applyLocalDampingWide(ParticleStore&, int, int, double) {
  throw std::logic_error("applyLocalDampingWide: this build has no wide path");
}
}  // namespace grainlab
#endif

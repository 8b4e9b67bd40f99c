// Compiled once per instruction set Highway targets (foreach_target re-includes this file);
// discPairForces() dispatches at run time to the widest the CPU has.
#include "disc_pair_kernel.hpp"

#include <algorithm>

#ifdef GRAINLAB_HAS_WIDE_SIMD
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "disc_pair_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// PairState's doubles, counted from the start of the struct (checked in disc_pair_batch.cpp).
constexpr int kHistory = 3, kFn = 4, kFt = 5, kOverlap = 6;

template <bool kFrictional>
void forces(const DiscPairKernelInput& in, int begin, int end) {
  const hn::ScalableTag<double> d;
  const hn::RebindToSigned<decltype(d)> di;
  const size_t lanes = hn::Lanes(d);
  const auto zero = hn::Zero(d);
  const auto negZero = hn::Set(d, -0.0);
  const auto half = hn::Set(d, 0.5);
  const auto kn = hn::Set(d, in.normalStiffness);
  const auto kt = hn::Set(d, in.tangentialStiffness);
  const auto negKt = hn::Set(d, -in.tangentialStiffness);
  const auto mu = hn::Set(d, in.friction);
  const auto dt = hn::Set(d, in.dt);
  HWY_ALIGN double history[hn::MaxLanes(d)], fnOut[hn::MaxLanes(d)], ftOut[hn::MaxLanes(d)],
      overlapOut[hn::MaxLanes(d)];
  for (int s = begin; s < end; s += static_cast<int>(lanes)) {
    const auto I = hn::LoadU(di, in.i + s), J = hn::LoadU(di, in.j + s);
    const auto I2 = hn::Add(I, I), J2 = hn::Add(J, J);
    const auto xi = hn::GatherIndex(d, in.position, I2), yi = hn::GatherIndex(d, in.position + 1, I2);
    const auto xj = hn::GatherIndex(d, in.position, J2), yj = hn::GatherIndex(d, in.position + 1, J2);
    const auto ri = hn::GatherIndex(d, in.radius, I), rj = hn::GatherIndex(d, in.radius, J);
    // touchDiscs()
    const auto dx = hn::Sub(xj, xi), dy = hn::Sub(yj, yi);
    const auto dist2 = hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy));
    const auto reach = hn::Add(ri, rj);
    const auto dist = hn::Sqrt(dist2);
    const auto nx = hn::Div(dx, dist), ny = hn::Div(dy, dist);
    const auto overlap = hn::Sub(reach, dist);
    const auto halfOverlap = hn::Mul(half, overlap);
    const auto armI = hn::Sub(ri, halfOverlap), armJ = hn::Sub(rj, halfOverlap);
    const auto touching = hn::AndNot(hn::Or(hn::Ge(dist2, hn::Mul(reach, reach)), hn::Eq(dist2, zero)),
                                     hn::Not(hn::Le(overlap, zero)));
    // contactForce(DiscContact): the relative motion at the contact.
    const auto vxi = hn::GatherIndex(d, in.velocity, I2), vyi = hn::GatherIndex(d, in.velocity + 1, I2);
    const auto vxj = hn::GatherIndex(d, in.velocity, J2), vyj = hn::GatherIndex(d, in.velocity + 1, J2);
    const auto wi = hn::GatherIndex(d, in.spin, I), wj = hn::GatherIndex(d, in.spin, J);
    const auto dvx = hn::Add(hn::Neg(vxi), vxj), dvy = hn::Add(hn::Neg(vyi), vyj);
    const auto spin = hn::Add(hn::Mul(wi, armI), hn::Mul(wj, armJ));
    const auto tx = hn::Neg(ny), ty = nx;
    const auto vn = hn::Add(hn::Mul(dvx, nx), hn::Mul(dvy, ny));
    const auto vt = hn::Sub(hn::Add(hn::Mul(dvx, tx), hn::Mul(dvy, ty)), spin);
    // The law (contact_law.hpp).
    const auto state = hn::LoadU(di, in.state + s);
    const auto dampN = hn::LoadU(d, in.dampN + s), dampT = hn::LoadU(d, in.dampT + s);
    const auto fn = hn::Sub(hn::Mul(kn, overlap), hn::Mul(dampN, vn));
    auto h = hn::GatherIndex(d, in.pairState + kHistory, state);
    auto ft = zero;
    if constexpr (kFrictional) {
      h = hn::Add(h, hn::Mul(vt, dt));
      ft = hn::Sub(hn::Mul(negKt, h), hn::Mul(dampT, vt));
      const auto cap = hn::IfThenElseZero(hn::Gt(fn, zero), hn::Mul(mu, fn));
      const auto slides = hn::Gt(hn::Abs(ft), cap);
      ft = hn::IfThenElse(slides, hn::CopySign(cap, ft), ft);
      // The divider bounds this kernel, and in a settled pile few contacts slide.
      if (!hn::AllFalse(d, slides)) h = hn::IfThenElse(slides, hn::Div(hn::Neg(hn::Add(ft, hn::Mul(dampT, vt))), kt), h);
    }
    const auto fx = hn::Add(hn::Mul(fn, nx), hn::Mul(ft, tx));
    const auto fy = hn::Add(hn::Mul(fn, ny), hn::Mul(ft, ty));
    const auto ti = hn::Mul(armI, ft), tj = hn::Mul(hn::Neg(armJ), ft);
    // Each end's share; x − F is x + (−F) in IEEE arithmetic.
    hn::StoreU(hn::IfThenElse(touching, hn::Neg(fx), negZero), d, in.endFx + s);
    hn::StoreU(hn::IfThenElse(touching, hn::Neg(fy), negZero), d, in.endFy + s);
    hn::StoreU(hn::IfThenElse(touching, hn::Neg(ti), negZero), d, in.endTorque + s);
    hn::StoreU(hn::IfThenElse(touching, fx, negZero), d, in.endFx + in.endStride + s);
    hn::StoreU(hn::IfThenElse(touching, fy, negZero), d, in.endFy + in.endStride + s);
    hn::StoreU(hn::IfThenElse(touching, tj, negZero), d, in.endTorque + in.endStride + s);
    // The pair's state, as the scalar loop leaves it (a pair apart keeps nothing).
    hn::Store(hn::IfThenElseZero(touching, h), d, history);
    hn::Store(hn::IfThenElseZero(touching, fn), d, fnOut);
    hn::Store(hn::IfThenElseZero(touching, ft), d, ftOut);
    hn::Store(hn::IfThenElseZero(touching, overlap), d, overlapOut);
    const int real = std::min(static_cast<int>(lanes), in.slots - s);
    for (int l = 0; l < real; ++l) {
      double* p = in.pairState + in.state[s + l];
      p[kHistory] = history[l];
      p[kFn] = fnOut[l];
      p[kFt] = ftOut[l];
      p[kOverlap] = overlapOut[l];
    }
  }
}

void DiscPairForces(const DiscPairKernelInput& in, int begin, int end) {
  if (in.frictional) forces<true>(in, begin, end);
  else forces<false>(in, begin, end);
}

const char* KernelTarget() { return hwy::TargetName(HWY_TARGET); }

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grainlab {
HWY_EXPORT(DiscPairForces);
HWY_EXPORT(KernelTarget);

void discPairForces(const DiscPairKernelInput& in, int begin, int end) {
  HWY_DYNAMIC_DISPATCH(DiscPairForces)(in, begin, end);
}

std::string discPairKernelTarget() { return HWY_DYNAMIC_DISPATCH(KernelTarget)(); }

}  // namespace grainlab
#endif
#else  // a build without the wide path: simdPath() is always the baseline, which never calls these
#include <stdexcept>

namespace grainlab {
void discPairForces(const DiscPairKernelInput&, int, int) {
  throw std::logic_error("discPairForces: this build has no wide path");
}
std::string discPairKernelTarget() { return "baseline"; }
}  // namespace grainlab
#endif

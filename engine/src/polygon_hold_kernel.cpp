// Compiled once per instruction set Highway targets (foreach_target re-includes this file);
// holdPolygonSlots() dispatches at run time to the widest the CPU has.
#include "polygon_hold_kernel.hpp"

#include <cmath>
#include <cstddef>

// foreach_target re-includes this file once per target: the scalar helpers are compiled once.
#ifndef GRAINLAB_POLYGON_HOLD_SCALAR
#define GRAINLAB_POLYGON_HOLD_SCALAR
namespace grainlab {
namespace {

// One slot in scalar code: the first pass's two tests of a polygon pair with kept features (decideWidePair's
// bounding circles, relativeMotion against the slack), in their operations and order.
inline bool holdsOne(const PolygonHoldInput& in, size_t s) {
  const double* x = in.particles.position;
  const double *cosAngle = in.particles.cosAngle, *sinAngle = in.particles.sinAngle;
  const auto i = static_cast<size_t>(in.i[s]), j = static_cast<size_t>(in.j[s]);
  const double dx = x[2 * j] - x[2 * i], dy = x[2 * j + 1] - x[2 * i + 1];
  const double reach = in.reach[s];
  if (dx * dx + dy * dy >= reach * reach) return false;
  const double mx = dx - in.offsetX[s], my = dy - in.offsetY[s];
  const double shift = std::abs(mx) + std::abs(my);
  const double turn = std::abs(cosAngle[i] - in.ca[s]) + std::abs(sinAngle[i] - in.sa[s]) +
                      std::abs(cosAngle[j] - in.cb[s]) + std::abs(sinAngle[j] - in.sb[s]);
  return shift + (in.lever[s] + shift) * turn < in.slack[s];
}

inline void posesOne(const PolygonHoldInput& in, size_t s) {
  const double* x = in.particles.position;
  const double *cosAngle = in.particles.cosAngle, *sinAngle = in.particles.sinAngle;
  const auto i = static_cast<size_t>(in.i[s]), j = static_cast<size_t>(in.j[s]);
  const bool iIsRef = in.normalSign[s] > 0;
  const size_t r = iIsRef ? i : j, e = iIsRef ? j : i;
  in.refX[s] = x[2 * r];
  in.refY[s] = x[2 * r + 1];
  in.refC[s] = cosAngle[r];
  in.refS[s] = sinAngle[r];
  in.incX[s] = x[2 * e];
  in.incY[s] = x[2 * e + 1];
  in.incC[s] = cosAngle[e];
  in.incS[s] = sinAngle[e];
}

// Slots [from, count) one by one.
inline int holdScalar(const PolygonHoldInput& in, size_t from, size_t count, std::int32_t* failed) {
  int n = 0;
  for (size_t s = from; s < count; ++s) {
    if (in.refX) posesOne(in, s);
    if (!holdsOne(in, s)) failed[n++] = static_cast<std::int32_t>(s);
  }
  return n;
}

}  // namespace
}  // namespace grainlab
#endif

#ifdef GRAINLAB_HAS_WIDE_SIMD
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "polygon_hold_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Whole vectors of slots; the last part-vector one by one (no lane reads past the range:
// another thread's slots follow it).
template <bool kPoses>
int HoldSlotsOf(const PolygonHoldInput& in, int count, std::int32_t* failed) {
  const hn::ScalableTag<double> d;
  const hn::RebindToSigned<decltype(d)> di;
  const size_t lanes = hn::Lanes(d), n = static_cast<size_t>(count);
  int nFailed = 0;
  size_t s = 0;
  for (; s + lanes <= n; s += lanes) {
    const auto I = hn::LoadU(di, in.i + s), J = hn::LoadU(di, in.j + s);
    const auto I2 = hn::Add(I, I), J2 = hn::Add(J, J);
    const PolygonHoldInput::Particles& p = in.particles;
    const auto xi = hn::GatherIndex(d, p.position, I2), yi = hn::GatherIndex(d, p.position + 1, I2);
    const auto xj = hn::GatherIndex(d, p.position, J2), yj = hn::GatherIndex(d, p.position + 1, J2);
    const auto ci = hn::GatherIndex(d, p.cosAngle, I), si = hn::GatherIndex(d, p.sinAngle, I);
    const auto cj = hn::GatherIndex(d, p.cosAngle, J), sj = hn::GatherIndex(d, p.sinAngle, J);
    // (x_j − x_i)·(x_j − x_i) >= reach²: the bounding circles apart
    const auto dx = hn::Sub(xj, xi), dy = hn::Sub(yj, yi);
    const auto reach = hn::LoadU(d, in.reach + s);
    const auto apart = hn::Ge(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy)), hn::Mul(reach, reach));
    // relativeMotion: shift = |d − offset|₁; turn = Σ|Δc| + |Δs|; shift + (lever + shift) turn
    const auto shift = hn::Add(hn::Abs(hn::Sub(dx, hn::LoadU(d, in.offsetX + s))),
                               hn::Abs(hn::Sub(dy, hn::LoadU(d, in.offsetY + s))));
    const auto turn = hn::Add(hn::Add(hn::Add(hn::Abs(hn::Sub(ci, hn::LoadU(d, in.ca + s))),
                                              hn::Abs(hn::Sub(si, hn::LoadU(d, in.sa + s)))),
                                      hn::Abs(hn::Sub(cj, hn::LoadU(d, in.cb + s)))),
                              hn::Abs(hn::Sub(sj, hn::LoadU(d, in.sb + s))));
    const auto motion = hn::Add(shift, hn::Mul(hn::Add(hn::LoadU(d, in.lever + s), shift), turn));
    // Fails unless motion < slack (a NaN fails, as the scalar test does) and the circles meet.
    const auto holds = hn::AndNot(apart, hn::Lt(motion, hn::LoadU(d, in.slack + s)));
    if constexpr (kPoses) {
      const auto iIsRef = hn::Gt(hn::LoadU(d, in.normalSign + s), hn::Zero(d));
      hn::StoreU(hn::IfThenElse(iIsRef, xi, xj), d, in.refX + s);
      hn::StoreU(hn::IfThenElse(iIsRef, yi, yj), d, in.refY + s);
      hn::StoreU(hn::IfThenElse(iIsRef, ci, cj), d, in.refC + s);
      hn::StoreU(hn::IfThenElse(iIsRef, si, sj), d, in.refS + s);
      hn::StoreU(hn::IfThenElse(iIsRef, xj, xi), d, in.incX + s);
      hn::StoreU(hn::IfThenElse(iIsRef, yj, yi), d, in.incY + s);
      hn::StoreU(hn::IfThenElse(iIsRef, cj, ci), d, in.incC + s);
      hn::StoreU(hn::IfThenElse(iIsRef, sj, si), d, in.incS + s);
    }
    if (hn::AllTrue(d, holds)) continue;
    std::uint8_t bits[8] = {};
    hn::StoreMaskBits(d, hn::Not(holds), bits);
    for (size_t l = 0; l < lanes; ++l) {
      if ((bits[l / 8] >> (l % 8)) & 1) failed[nFailed++] = static_cast<std::int32_t>(s + l);
    }
  }
  return nFailed + holdScalar(in, s, n, failed + nFailed);
}

int HoldSlots(const PolygonHoldInput& in, int count, std::int32_t* failed) {
  return in.refX ? HoldSlotsOf<true>(in, count, failed) : HoldSlotsOf<false>(in, count, failed);
}

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grainlab {
HWY_EXPORT(HoldSlots);

int holdPolygonSlots(const PolygonHoldInput& in, int count, std::int32_t* failed) {
  return HWY_DYNAMIC_DISPATCH(HoldSlots)(in, count, failed);
}

}  // namespace grainlab
#endif
#else  // a build without the wide path: the same answers one slot at a time
namespace grainlab {
int holdPolygonSlots(const PolygonHoldInput& in, int count, std::int32_t* failed) {
  return holdScalar(in, 0, static_cast<size_t>(count), failed);
}
}  // namespace grainlab
#endif

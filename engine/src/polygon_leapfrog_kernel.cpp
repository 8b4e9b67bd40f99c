// Compiled once per instruction set Highway targets (foreach_target re-includes this file);
// leapfrogPolygonsWide() dispatches at run time to the widest the CPU has.
#include "polygon_leapfrog_kernel.hpp"

#ifdef GRAINLAB_HAS_WIDE_SIMD
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "polygon_leapfrog_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>
#include <cstdint>

#include "incremental_rotation.hpp"
#include "leapfrog_lanes-inl.hpp"

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// rotateIncrementally(c, s, δ) in every lane: the same products and sums in the same order.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void RotateIncrementally(D d, V& c, V& s, V delta) {
  const auto one = hn::Set(d, 1.0);
  const auto half = hn::Set(d, 0.5);
  const auto d2 = hn::Mul(delta, delta);
  const auto cosD = hn::Sub(one, hn::Mul(hn::Mul(d2, half),
                                         hn::Sub(one, hn::Mul(hn::Mul(d2, hn::Set(d, 1.0 / 12)),
                                                              hn::Sub(one, hn::Mul(d2, hn::Set(d, 1.0 / 30)))))));
  const auto sinD = hn::Mul(
      delta, hn::Sub(one, hn::Mul(hn::Mul(d2, hn::Set(d, 1.0 / 6)),
                                  hn::Sub(one, hn::Mul(hn::Mul(d2, hn::Set(d, 1.0 / 20)),
                                                       hn::Sub(one, hn::Mul(d2, hn::Set(d, 1.0 / 42))))))));
  const auto c1 = hn::Sub(hn::Mul(c, cosD), hn::Mul(s, sinD));
  const auto s1 = hn::Add(hn::Mul(s, cosD), hn::Mul(c, sinD));
  const auto g = hn::Sub(hn::Set(d, 1.5), hn::Mul(half, hn::Add(hn::Mul(c1, c1), hn::Mul(s1, s1))));
  c = hn::Mul(c1, g);
  s = hn::Mul(s1, g);
}

void LeapfrogPolygons(ParticleStore& p, double dt, int begin, int end) {
  const hn::ScalableTag<double> d;
  const hn::RebindToUnsigned<decltype(d)> du;
  const hn::Rebind<std::uint32_t, decltype(d)> d32;
  const hn::Rebind<std::uint8_t, decltype(d)> d8;
  const int lanes = static_cast<int>(hn::Lanes(d));
  double* const cosAngle = p.cosAngle.data();
  double* const sinAngle = p.sinAngle.data();
  const double* const angle = p.angle.data();
  const std::uint8_t* const shape = reinterpret_cast<const std::uint8_t*>(p.shape.data());
  const auto step = hn::Set(d, dt);
  const auto zero = hn::Zero(d);
  const auto maxTurn = hn::Set(d, kMaxIncrementalTurn);
  const auto disc = hn::Set(du, static_cast<std::uint64_t>(ShapeKind::Disc));
  int k = KickDriftLanes(p, dt, begin, end, [&](int k, const auto& spin) HWY_ATTR {
    // Spinning polygons and clumps turn; discs keep their cos and sin as they are (unused).
    const auto oriented =
        hn::RebindMask(d, hn::Ne(hn::PromoteTo(du, hn::PromoteTo(d32, hn::LoadU(d8, shape + k))), disc));
    const auto turning = hn::And(oriented, hn::Ne(spin, zero));
    if (hn::AllFalse(d, turning)) return;
    const auto turn = hn::Mul(spin, step);
    const auto small = hn::Le(hn::Abs(turn), maxTurn);  // false for a NaN turn, as in advanceRotation()
    const auto c = hn::LoadU(d, cosAngle + k);
    const auto s = hn::LoadU(d, sinAngle + k);
    auto cTurned = c, sTurned = s;
    RotateIncrementally(d, cTurned, sTurned, turn);
    const auto series = hn::And(turning, small);
    hn::StoreU(hn::IfThenElse(series, cTurned, c), d, cosAngle + k);
    hn::StoreU(hn::IfThenElse(series, sTurned, s), d, sinAngle + k);
    // A turn beyond the series' reach: sincos of the new angle, one lane at a time.
    const auto large = hn::AndNot(small, turning);
    if (hn::AllFalse(d, large)) return;
    std::uint8_t bits[(hn::MaxLanes(d) + 7) / 8] = {};
    hn::StoreMaskBits(d, large, bits);
    for (int l = 0; l < lanes; ++l) {
      if (bits[l / 8] >> (l % 8) & 1) ::sincos(angle[k + l], &sinAngle[k + l], &cosAngle[k + l]);
    }
  });
  for (; k < end; ++k) {
    KickDriftOne(p, dt, k);
    if (p.shape[k] != ShapeKind::Disc && p.spin[k] != 0) {
      advanceRotation(cosAngle[k], sinAngle[k], p.spin[k] * dt, p.angle[k]);
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grainlab {
HWY_EXPORT(LeapfrogPolygons);

void leapfrogPolygonsWide(ParticleStore& particles, double dt, int begin, int end) {
  HWY_DYNAMIC_DISPATCH(LeapfrogPolygons)(particles, dt, begin, end);
}

}  // namespace grainlab
#endif
#else  // a build without the wide path: simdPath() is always the baseline, which never calls this
#include <stdexcept>

namespace grainlab {
void leapfrogPolygonsWide(ParticleStore&, double, int, int) {
  throw std::logic_error("leapfrogPolygonsWide: this build has no wide path");
}
}  // namespace grainlab
#endif

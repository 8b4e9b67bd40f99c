// Compiled once per instruction set Highway targets (foreach_target re-includes this file);
// discPairForces() dispatches at run time to the widest the CPU has.
#include "disc_pair_kernel.hpp"

#include <cstring>


#ifdef GRAINLAB_HAS_WIDE_SIMD
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "disc_pair_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// 1/√x for x > 0 in float's normal range (a touching pair's |d|² is, for grains between
// 1e-18 m and 1e18 m), to double's rounding level: the float estimate (relative error at most
// 1.5 · 2^-12 on every target) and three Newton steps y ← y (3/2 − x/2 · y²), each squaring
// the error. (AVX-512's 2^-14 double estimate with two steps measured no faster.)
template <class D, class V>
HWY_INLINE V reciprocalSqrt(D d, V x) {
  const hn::Rebind<float, D> df;
  V y = hn::PromoteTo(d, hn::ApproximateReciprocalSqrt(hn::DemoteTo(df, x)));
  const V halfX = hn::Mul(hn::Set(d, 0.5), x);
  const V threeHalves = hn::Set(d, 1.5);
  for (int k = 0; k < 3; ++k) y = hn::Mul(y, hn::NegMulAdd(halfX, hn::Mul(y, y), threeHalves));
  return y;
}

// to[0..1] += share[0..1] (kSign 1) or −= (kSign −1), both lanes in one instruction where
// the target has two-lane vectors; each lane rounds as a scalar add does.
template <int kSign>
HWY_INLINE void addShare(double* to, const double* share) {
#if HWY_TARGET == HWY_SCALAR
  to[0] = kSign > 0 ? to[0] + share[0] : to[0] - share[0];
  to[1] = kSign > 0 ? to[1] + share[1] : to[1] - share[1];
#else
  const hn::Full128<double> pair;
  const auto v = hn::LoadU(pair, to), by = hn::LoadU(pair, share);
  hn::StoreU(kSign > 0 ? hn::Add(v, by) : hn::Sub(v, by), pair, to);
#endif
}

// What a step's slots carry beside the disc law: nothing, rolling resistance (its couple; or,
// in a frictionless step, only its relative rotation, kept and cleared as the baseline does),
// or clump members (levers from their bodies' centroids).
enum class Extra { None, Rolling, RollingKept, Members };

// kPeriodic: the slots meet j's image in a periodic cell (DiscPairKernelInput::imageN1); the
// other instantiations are the same code as without the flag.
template <bool kFrictional, Extra kExtra, bool kPeriodic = false>
void forces(const DiscPairKernelInput& in, int begin, int end) {
  constexpr bool kRolling = kExtra == Extra::Rolling, kMembers = kExtra == Extra::Members;
  constexpr bool kRollingHistory = kRolling || kExtra == Extra::RollingKept;
  const hn::ScalableTag<double> d;
  const hn::RebindToSigned<decltype(d)> di;
  const size_t lanes = hn::Lanes(d);
  const auto zero = hn::Zero(d);
  const auto half = hn::Set(d, 0.5);
  const auto kn = hn::Set(d, in.normalStiffness);
  const auto negKt = hn::Set(d, -in.tangentialStiffness);
  const auto negInvKt = hn::Set(d, -1.0 / in.tangentialStiffness);
  const auto mu = hn::Set(d, in.friction);
  const auto dt = hn::Set(d, in.dt);
  HWY_ALIGN double out[6 * hn::MaxLanes(d)];
  double* const force = in.force;  // in locals: the stores below cannot then reload them
  double* const torque = in.torque;
  double* const ends = in.ends;
  const std::int32_t* const iEnd = in.iEnd;
  const std::int32_t* const jEnd = in.jEnd;
  const std::uint8_t* const blockDefers = in.blockDefers;
  // Where force and torque go: the pair's particles, or its members' bodies.
  const std::int64_t* const bodyI = kMembers ? in.bodyI : in.i;
  const std::int64_t* const bodyJ = kMembers ? in.bodyJ : in.j;
  const double apart[4] = {-0.0, -0.0, -0.0, 0.0};
  for (int s = begin; s < end; s += static_cast<int>(lanes)) {
    // Whether some end in this block waits in a record (several threads, where slices meet).
    const bool defers = blockDefers && blockDefers[s / kDiscPairBlock];
    const auto I = hn::LoadU(di, in.i + s), J = hn::LoadU(di, in.j + s);
    const auto I2 = hn::Add(I, I), J2 = hn::Add(J, J);
    const auto xi = hn::GatherIndex(d, in.position, I2), yi = hn::GatherIndex(d, in.position + 1, I2);
    auto xj = hn::GatherIndex(d, in.position, J2), yj = hn::GatherIndex(d, in.position + 1, J2);
    if constexpr (kPeriodic) {  // j's image, x_j + h n
      const auto n1 = hn::LoadU(d, in.imageN1 + s), n2 = hn::LoadU(d, in.imageN2 + s);
      xj = hn::Add(xj, hn::MulAdd(hn::Set(d, in.cellEdges[0]), n1, hn::Mul(hn::Set(d, in.cellEdges[1]), n2)));
      yj = hn::Add(yj, hn::MulAdd(hn::Set(d, in.cellEdges[2]), n1, hn::Mul(hn::Set(d, in.cellEdges[3]), n2)));
    }
    // A disc's radius sits beside its slot (DiscPairBatch::layRadii): two loads instead of two
    // gathers. Clump members' radii are gathered.
    const auto ri = kMembers ? hn::GatherIndex(d, in.radius, I) : hn::LoadU(d, in.radiusI + s);
    const auto rj = kMembers ? hn::GatherIndex(d, in.radius, J) : hn::LoadU(d, in.radiusJ + s);
    // touchDiscs()
    const auto dx = hn::Sub(xj, xi), dy = hn::Sub(yj, yi);
    const auto dist2 = hn::MulAdd(dx, dx, hn::Mul(dy, dy));
    const auto reach = hn::Add(ri, rj);
    const auto touchingRange = hn::And(hn::Lt(dist2, hn::Mul(reach, reach)), hn::Gt(dist2, zero));
    if (hn::AllFalse(d, touchingRange)) {  // a whole vector apart: common in a loose region
      hn::StoreU(zero, d, in.history + s);
      hn::StoreU(zero, d, in.fn + s);
      hn::StoreU(zero, d, in.ft + s);
      hn::StoreU(zero, d, in.overlap + s);
      if constexpr (kRollingHistory) hn::StoreU(zero, d, in.rollingHistory + s);
      if (defers) {
        for (size_t l = 0; l < lanes; ++l) {
          if (iEnd[s + l] >= 0) std::memcpy(ends + 4 * iEnd[s + l], apart, sizeof apart);
          if (jEnd[s + l] >= 0) std::memcpy(ends + 4 * jEnd[s + l], apart, sizeof apart);
        }
      }
      continue;
    }
    const auto inverse = reciprocalSqrt(d, dist2);
    const auto dist = hn::Mul(dist2, inverse);
    const auto nx = hn::Mul(dx, inverse), ny = hn::Mul(dy, inverse);
    const auto overlap = hn::Sub(reach, dist);
    const auto touching = hn::And(touchingRange, hn::Gt(overlap, zero));
    const auto halfOverlap = hn::Mul(half, overlap);
    const auto armI = hn::Sub(ri, halfOverlap), armJ = hn::Sub(rj, halfOverlap);
    // contactForce(DiscContact): the relative motion at the contact.
    const auto BI = kMembers ? hn::LoadU(di, bodyI + s) : I, BJ = kMembers ? hn::LoadU(di, bodyJ + s) : J;
    const auto BI2 = kMembers ? hn::Add(BI, BI) : I2, BJ2 = kMembers ? hn::Add(BJ, BJ) : J2;
    const auto vxi = hn::GatherIndex(d, in.velocity, BI2), vyi = hn::GatherIndex(d, in.velocity + 1, BI2);
    const auto vxj = hn::GatherIndex(d, in.velocity, BJ2), vyj = hn::GatherIndex(d, in.velocity + 1, BJ2);
    const auto wi = hn::GatherIndex(d, in.spin, BI), wj = hn::GatherIndex(d, in.spin, BJ);
    auto dvx = hn::Sub(vxj, vxi), dvy = hn::Sub(vyj, vyi);
    if constexpr (kPeriodic) {  // the image's affine velocity relative to i: L d, d = x_j + h n − x_i
      const double* L = in.velocityGradient;
      dvx = hn::Add(dvx, hn::MulAdd(hn::Set(d, L[0]), dx, hn::Mul(hn::Set(d, L[1]), dy)));
      dvy = hn::Add(dvy, hn::MulAdd(hn::Set(d, L[2]), dx, hn::Mul(hn::Set(d, L[3]), dy)));
    }
    // A member's lever L from its body's centroid adds ω × L = (−ω L_y, ω L_x) to its velocity.
    [[maybe_unused]] auto lxi = zero, lyi = zero, lxj = zero, lyj = zero;
    if constexpr (kMembers) {
      lxi = hn::GatherIndex(d, in.lever, I2), lyi = hn::GatherIndex(d, in.lever + 1, I2);
      lxj = hn::GatherIndex(d, in.lever, J2), lyj = hn::GatherIndex(d, in.lever + 1, J2);
      dvx = hn::Sub(hn::NegMulAdd(wj, lyj, dvx), hn::Mul(hn::Neg(wi), lyi));
      dvy = hn::Sub(hn::MulAdd(wj, lxj, dvy), hn::Mul(wi, lxi));
    }
    const auto spin = hn::MulAdd(wi, armI, hn::Mul(wj, armJ));
    // t = (−n_y, n_x)
    const auto vn = hn::MulAdd(dvx, nx, hn::Mul(dvy, ny));
    const auto vt = hn::Sub(hn::MulSub(dvy, nx, hn::Mul(dvx, ny)), spin);
    // The law (contact_law.hpp).
    const auto dampN = hn::LoadU(d, in.dampN + s);
    const auto fn = hn::NegMulAdd(dampN, vn, hn::Mul(kn, overlap));
    auto h = hn::LoadU(d, in.history + s);
    auto ft = zero;
    if constexpr (kFrictional) {
      const auto dampT = hn::LoadU(d, in.dampT + s);
      h = hn::MulAdd(vt, dt, h);
      ft = hn::NegMulAdd(dampT, vt, hn::Mul(negKt, h));
      const auto cap = hn::IfThenElseZero(hn::Gt(fn, zero), hn::Mul(mu, fn));
      const auto slides = hn::Gt(hn::Abs(ft), cap);
      ft = hn::IfThenElse(slides, hn::CopySign(cap, ft), ft);
      // Spring and dashpot sit at the cap: h = −(f_t + c_t v_t) / k_t.
      h = hn::IfThenElse(slides, hn::Mul(hn::MulAdd(dampT, vt, ft), negInvKt), h);
    }
    const auto fx = hn::NegMulAdd(ft, ny, hn::Mul(fn, nx));
    const auto fy = hn::MulAdd(ft, nx, hn::Mul(fn, ny));
    // The couple on j (its opposite on i) of RollingResistance::couple(): the spring on the
    // relative rotation, held at μ_r R* f_n (then plastic, the damper off).
    [[maybe_unused]] auto couple = zero;
    [[maybe_unused]] auto hr = zero;
    if constexpr (kRollingHistory) hr = hn::LoadU(d, in.rollingHistory + s);
    if constexpr (kRolling) {
      const auto rollingSpin = hn::Sub(wj, wi);
      hr = hn::MulAdd(rollingSpin, dt, hr);
      const auto spring = hn::Neg(hn::Mul(hn::LoadU(d, in.rollingStiffness + s), hr));
      const auto cap = hn::Max(hn::Mul(hn::LoadU(d, in.rollingCapPerForce + s), fn), zero);
      const auto held = hn::Min(hn::Max(spring, hn::Neg(cap)), cap);
      const auto plastic = hn::Ge(hn::Abs(spring), cap);
      hr = hn::IfThenElse(plastic, hn::Neg(hn::Mul(held, hn::LoadU(d, in.rollingCompliance + s))), hr);
      couple = hn::IfThenElse(plastic, held, hn::NegMulAdd(hn::LoadU(d, in.rollingDamping + s), rollingSpin, spring));
    }
    auto ti = kRolling ? hn::MulAdd(armI, ft, couple) : hn::Mul(armI, ft);
    auto tj = kRolling ? hn::NegMulAdd(armJ, ft, couple) : hn::Mul(hn::Neg(armJ), ft);
    if constexpr (kMembers) {  // and the lever's: L × F = L_x F_y − L_y F_x
      ti = hn::Add(ti, hn::MulSub(lxi, fy, hn::Mul(lyi, fx)));
      tj = hn::Add(tj, hn::MulSub(lxj, fy, hn::Mul(lyj, fx)));
    }
    // Each end's share: −F on i, F on j, each touching pair's at once, in slot (= pair) order.
    hn::Store(ti, d, out + 2 * lanes);
    hn::Store(tj, d, out + 3 * lanes);
    std::uint8_t bits[8] = {};
    hn::StoreMaskBits(d, touching, bits);
    if (!defers) {
      // Each lane's fx fy side by side, so that an end's force takes one two-lane subtract or
      // add (each lane rounds as the scalar one did).
      double* const forceXY = out + 4 * lanes;
      hn::StoreInterleaved2(fx, fy, d, forceXY);
      for (size_t l = 0; l < lanes; ++l) {
        if (!((bits[l / 8] >> (l % 8)) & 1)) continue;
        const std::int64_t pi = bodyI[s + l], pj = bodyJ[s + l];
        addShare<-1>(force + 2 * pi, forceXY + 2 * l);
        torque[pi] -= out[2 * lanes + l];
        addShare<1>(force + 2 * pj, forceXY + 2 * l);
        torque[pj] += out[3 * lanes + l];
      }
    } else {
      hn::Store(fx, d, out);
      hn::Store(fy, d, out + lanes);  // an end that waits takes its record, touching or not (x − y is x + (−y): stored negated on i)
      for (size_t l = 0; l < lanes; ++l) {
        const bool touches = (bits[l / 8] >> (l % 8)) & 1;
        const std::int64_t pi = bodyI[s + l], pj = bodyJ[s + l];
        if (const std::int32_t e = iEnd[s + l]; e >= 0) {
          double* at = ends + 4 * e;
          at[0] = touches ? -out[l] : -0.0;
          at[1] = touches ? -out[lanes + l] : -0.0;
          at[2] = touches ? -out[2 * lanes + l] : -0.0;
        } else if (touches) {
          force[2 * pi] -= out[l];
          force[2 * pi + 1] -= out[lanes + l];
          torque[pi] -= out[2 * lanes + l];
        }
        if (const std::int32_t e = jEnd[s + l]; e >= 0) {
          double* at = ends + 4 * e;
          at[0] = touches ? out[l] : -0.0;
          at[1] = touches ? out[lanes + l] : -0.0;
          at[2] = touches ? out[3 * lanes + l] : -0.0;
        } else if (touches) {
          force[2 * pj] += out[l];
          force[2 * pj + 1] += out[lanes + l];
          torque[pj] += out[3 * lanes + l];
        }
      }
    }
    // The pair's state (a pair apart keeps nothing).
    hn::StoreU(hn::IfThenElseZero(touching, h), d, in.history + s);
    hn::StoreU(hn::IfThenElseZero(touching, fn), d, in.fn + s);
    hn::StoreU(hn::IfThenElseZero(touching, ft), d, in.ft + s);
    hn::StoreU(hn::IfThenElseZero(touching, overlap), d, in.overlap + s);
    if constexpr (kRollingHistory) hn::StoreU(hn::IfThenElseZero(touching, hr), d, in.rollingHistory + s);
  }
}

template <bool kPeriodic>
void discForces(const DiscPairKernelInput& in, int begin, int end) {
  if (in.rollingHistory) {
    if (in.frictional) forces<true, Extra::Rolling, kPeriodic>(in, begin, end);
    else forces<false, Extra::RollingKept, kPeriodic>(in, begin, end);
  } else {
    if (in.frictional) forces<true, Extra::None, kPeriodic>(in, begin, end);
    else forces<false, Extra::None, kPeriodic>(in, begin, end);
  }
}

void DiscPairForces(const DiscPairKernelInput& in, int begin, int end) {
  if (in.bodyI) {  // clumps have no periodic cell
    if (in.frictional) forces<true, Extra::Members>(in, begin, end);
    else forces<false, Extra::Members>(in, begin, end);
  } else if (in.imageN1) {
    discForces<true>(in, begin, end);
  } else {
    discForces<false>(in, begin, end);
  }
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

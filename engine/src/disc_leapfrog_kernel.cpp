// Compiled once per instruction set Highway targets (foreach_target re-includes this file);
// leapfrogDiscsWide() dispatches at run time to the widest the CPU has.
#include "disc_leapfrog_kernel.hpp"

#include <cstdint>

#ifdef GRAINLAB_HAS_WIDE_SIMD
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "disc_leapfrog_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// One particle as leapfrogAdvance() steps a disc: the ranges' ends that do not fill a vector.
HWY_INLINE void advanceOne(ParticleStore& p, double dt, int k) {
  p.velocity[k] += p.force[k] * (p.invMass[k] * dt);
  p.spin[k] += p.torque[k] * (p.invInertia[k] * dt);
  p.position[k] += p.velocity[k] * dt;
  if (p.spin[k] != 0) p.angle[k] += p.spin[k] * dt;
  p.force[k] = p.bodyForce(k);
  p.torque[k] = 0;
}

void LeapfrogDiscs(ParticleStore& p, double dt, int begin, int end) {
  const hn::ScalableTag<double> d;
  const hn::RebindToUnsigned<decltype(d)> du;
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
  const auto gx = hn::Set(d, p.gravity.x()), gy = hn::Set(d, p.gravity.y());
  const auto dynamic = hn::Zero(du);  // Motion::Dynamic
  int k = begin;
  for (; k + lanes <= end; k += lanes) {
    hn::Vec<decltype(d)> vx, vy, fx, fy, px, py;
    hn::LoadInterleaved2(d, v + 2 * k, vx, vy);
    hn::LoadInterleaved2(d, f + 2 * k, fx, fy);
    hn::LoadInterleaved2(d, x + 2 * k, px, py);
    // v += f (m⁻¹ dt); ω += τ (I⁻¹ dt); x += v dt
    const auto kick = hn::Mul(hn::LoadU(d, invMass + k), step);
    vx = hn::Add(vx, hn::Mul(fx, kick));
    vy = hn::Add(vy, hn::Mul(fy, kick));
    const auto spin = hn::Add(hn::LoadU(d, w + k), hn::Mul(hn::LoadU(d, tau + k), hn::Mul(hn::LoadU(d, invInertia + k), step)));
    px = hn::Add(px, hn::Mul(vx, step));
    py = hn::Add(py, hn::Mul(vy, step));
    // A disc's angle moves only where it spins (adding a zero turn could flip a −0).
    const auto a = hn::LoadU(d, angle + k);
    hn::StoreU(hn::IfThenElse(hn::Ne(spin, zero), hn::Add(a, hn::Mul(spin, step)), a), d, angle + k);
    hn::StoreU(spin, d, w + k);
    hn::StoreInterleaved2(vx, vy, d, v + 2 * k);
    hn::StoreInterleaved2(px, py, d, x + 2 * k);
    // The next force starts from the weight (dynamic particles) or zero.
    const auto isDynamic = hn::RebindMask(d, hn::Eq(hn::PromoteTo(du, hn::PromoteTo(d32, hn::LoadU(d8, motion + k))), dynamic));
    const auto m = hn::LoadU(d, mass + k);
    hn::StoreInterleaved2(hn::IfThenElseZero(isDynamic, hn::Mul(m, gx)), hn::IfThenElseZero(isDynamic, hn::Mul(m, gy)), d,
                          f + 2 * k);
    hn::StoreU(zero, d, tau + k);
  }
  for (; k < end; ++k) advanceOne(p, dt, k);
}

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grainlab {
HWY_EXPORT(LeapfrogDiscs);

void leapfrogDiscsWide(ParticleStore& particles, double dt, int begin, int end) {
  HWY_DYNAMIC_DISPATCH(LeapfrogDiscs)(particles, dt, begin, end);
}

}  // namespace grainlab
#endif
#else  // a build without the wide path: simdPath() is always the baseline, which never calls this
#include <stdexcept>

namespace grainlab {
void leapfrogDiscsWide(ParticleStore&, double, int, int) {
  throw std::logic_error("leapfrogDiscsWide: this build has no wide path");
}
}  // namespace grainlab
#endif

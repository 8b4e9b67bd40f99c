// Compiled once per instruction set Highway targets (foreach_target re-includes this file);
// leapfrogDiscsWide() dispatches at run time to the widest the CPU has.
#include "disc_leapfrog_kernel.hpp"

#ifdef GRAINLAB_HAS_WIDE_SIMD
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "disc_leapfrog_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "leapfrog_lanes-inl.hpp"

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {

void LeapfrogDiscs(ParticleStore& p, double dt, int begin, int end) {
  // A disc's rotation is its angle alone: nothing to do once it is stepped.
  int k = KickDriftLanes(p, dt, begin, end, [](int, const auto&) HWY_ATTR {});
  for (; k < end; ++k) KickDriftOne(p, dt, k);
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

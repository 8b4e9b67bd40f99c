// Compiled once per instruction set Highway targets (foreach_target re-includes this file);
// movedBeyondWide() dispatches at run time to the widest the CPU has.
#include "skin_check_kernel.hpp"

#ifdef GRAINLAB_HAS_WIDE_SIMD
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "skin_check_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

bool MovedBeyond(const double* positions, const double* reference, int begin, int end, double limit2) {
  const hn::ScalableTag<double> d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto limit = hn::Set(d, limit2);
  int k = begin;
  for (; k + lanes <= end; k += lanes) {
    hn::Vec<decltype(d)> x, y, x0, y0;
    hn::LoadInterleaved2(d, positions + 2 * k, x, y);
    hn::LoadInterleaved2(d, reference + 2 * k, x0, y0);
    const auto dx = hn::Sub(x, x0), dy = hn::Sub(y, y0);
    if (!hn::AllFalse(d, hn::Gt(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy)), limit))) return true;
  }
  for (; k < end; ++k) {
    const double dx = positions[2 * k] - reference[2 * k], dy = positions[2 * k + 1] - reference[2 * k + 1];
    if (dx * dx + dy * dy > limit2) return true;
  }
  return false;
}

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grainlab {
HWY_EXPORT(MovedBeyond);

bool movedBeyondWide(const double* positions, const double* reference, int begin, int end, double limit2) {
  return HWY_DYNAMIC_DISPATCH(MovedBeyond)(positions, reference, begin, end, limit2);
}

}  // namespace grainlab
#endif
#else  // a build without the wide path: simdPath() is always the baseline, which never calls this
#include <stdexcept>

namespace grainlab {
bool movedBeyondWide(const double*, const double*, int, int, double) {
  throw std::logic_error("movedBeyondWide: this build has no wide path");
}
}  // namespace grainlab
#endif

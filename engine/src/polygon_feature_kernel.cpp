// Compiled once per instruction set Highway targets (foreach_target re-includes this file);
// the functions dispatch at run time to the widest the CPU has.
#include "polygon_feature_kernel.hpp"

#include <cstddef>
#include <limits>

#ifdef GRAINLAB_HAS_WIDE_SIMD
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "polygon_feature_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

constexpr size_t kSlots = kMaxPolygonVertices;

HWY_INLINE void Side(const FeatureSide& side) {
  const hn::CappedTag<double, kSlots> d;
  const size_t N = hn::Lanes(d);
  const PolygonFeatureTable &ref = *side.ref, &other = *side.other;
  const auto C = hn::Set(d, side.c), S = hn::Set(d, side.s);
  // x = dX + c u_x − s u_y; y = dY + s u_x + c u_y
  for (size_t i = 0; i < kSlots; i += N) {
    const auto ux = hn::LoadU(d, other.vx + i), uy = hn::LoadU(d, other.vy + i);
    hn::StoreU(hn::Sub(hn::Add(hn::Set(d, side.dX), hn::Mul(C, ux)), hn::Mul(S, uy)), d, side.wx + i);
    hn::StoreU(hn::Add(hn::Add(hn::Set(d, side.dY), hn::Mul(S, ux)), hn::Mul(C, uy)), d, side.wy + i);
  }
  // least over v of n_x x_v + n_y y_v − offset, each face slot in a lane
  for (size_t i = 0; i < kSlots; i += N) {
    const auto nx = hn::LoadU(d, ref.nx + i), ny = hn::LoadU(d, ref.ny + i), offset = hn::LoadU(d, ref.offset + i);
    auto least = hn::Set(d, std::numeric_limits<double>::infinity());
    for (int v = 0; v < side.count; ++v) {
      const auto x = hn::Set(d, side.wx[v]), y = hn::Set(d, side.wy[v]);
      least = hn::Min(least, hn::Sub(hn::Add(hn::Mul(nx, x), hn::Mul(ny, y)), offset));
    }
    hn::StoreU(least, d, side.separation + i);
  }
}

bool FeatureSides(const FeatureSide& first, int firstFaces, double reach, const FeatureSide& second) {
  Side(first);
  for (int e = 0; e < firstFaces; ++e) {
    if (first.separation[e] > reach) return false;
  }
  Side(second);
  return true;
}

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grainlab {
HWY_EXPORT(FeatureSides);

bool featureSidesWide(const FeatureSide& first, int firstFaces, double reach, const FeatureSide& second) {
  return HWY_DYNAMIC_DISPATCH(FeatureSides)(first, firstFaces, reach, second);
}

}  // namespace grainlab
#endif
#else  // a build without the wide path: simdPath() is always the baseline, which never calls this
#include <stdexcept>

namespace grainlab {
bool featureSidesWide(const FeatureSide&, int, double, const FeatureSide&) {
  throw std::logic_error("featureSidesWide: this build has no wide path");
}
}  // namespace grainlab
#endif

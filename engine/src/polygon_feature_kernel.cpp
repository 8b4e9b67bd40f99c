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

void FaceSeparations(const PolygonFeatureTable& ref, const PolygonFeatureTable& other, int count, double dX, double dY,
                     double c, double s, double* wx, double* wy, double* separation) {
  const hn::CappedTag<double, kSlots> d;
  const size_t N = hn::Lanes(d);
  const auto C = hn::Set(d, c), S = hn::Set(d, s);
  // x = dX + c u_x − s u_y; y = dY + s u_x + c u_y
  for (size_t i = 0; i < kSlots; i += N) {
    const auto ux = hn::LoadU(d, other.vx + i), uy = hn::LoadU(d, other.vy + i);
    hn::StoreU(hn::Sub(hn::Add(hn::Set(d, dX), hn::Mul(C, ux)), hn::Mul(S, uy)), d, wx + i);
    hn::StoreU(hn::Add(hn::Add(hn::Set(d, dY), hn::Mul(S, ux)), hn::Mul(C, uy)), d, wy + i);
  }
  // least over v of n_x x_v + n_y y_v − offset, each face slot in a lane
  for (size_t i = 0; i < kSlots; i += N) {
    const auto nx = hn::LoadU(d, ref.nx + i), ny = hn::LoadU(d, ref.ny + i), offset = hn::LoadU(d, ref.offset + i);
    auto least = hn::Set(d, std::numeric_limits<double>::infinity());
    for (int v = 0; v < count; ++v) {
      const auto sep = hn::Sub(hn::Add(hn::Mul(nx, hn::Set(d, wx[v])), hn::Mul(ny, hn::Set(d, wy[v]))), offset);
      least = hn::Min(least, sep);
    }
    hn::StoreU(least, d, separation + i);
  }
}

void IncidentFacing(const PolygonFeatureTable& incident, double nx, double ny, double c, double s, double* facing) {
  const hn::CappedTag<double, kSlots> d;
  const size_t N = hn::Lanes(d);
  const auto C = hn::Set(d, c), S = hn::Set(d, s), NX = hn::Set(d, nx), NY = hn::Set(d, ny);
  // n_x (c m_x − s m_y) + n_y (s m_x + c m_y)
  for (size_t i = 0; i < kSlots; i += N) {
    const auto mx = hn::LoadU(d, incident.nx + i), my = hn::LoadU(d, incident.ny + i);
    const auto tx = hn::Sub(hn::Mul(C, mx), hn::Mul(S, my)), ty = hn::Add(hn::Mul(S, mx), hn::Mul(C, my));
    hn::StoreU(hn::Add(hn::Mul(NX, tx), hn::Mul(NY, ty)), d, facing + i);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grainlab {
HWY_EXPORT(FaceSeparations);
HWY_EXPORT(IncidentFacing);

void faceSeparationsWide(const PolygonFeatureTable& ref, const PolygonFeatureTable& other, int count, double dX,
                         double dY, double c, double s, double* wx, double* wy, double* separation) {
  HWY_DYNAMIC_DISPATCH(FaceSeparations)(ref, other, count, dX, dY, c, s, wx, wy, separation);
}
void incidentFacingWide(const PolygonFeatureTable& incident, double nx, double ny, double c, double s,
                        double* facing) {
  HWY_DYNAMIC_DISPATCH(IncidentFacing)(incident, nx, ny, c, s, facing);
}

}  // namespace grainlab
#endif
#else  // a build without the wide path: simdPath() is always the baseline, which never calls this
#include <stdexcept>

namespace grainlab {
void faceSeparationsWide(const PolygonFeatureTable&, const PolygonFeatureTable&, int, double, double, double, double,
                         double*, double*, double*) {
  throw std::logic_error("faceSeparationsWide: this build has no wide path");
}
void incidentFacingWide(const PolygonFeatureTable&, double, double, double, double, double*) {
  throw std::logic_error("incidentFacingWide: this build has no wide path");
}
}  // namespace grainlab
#endif

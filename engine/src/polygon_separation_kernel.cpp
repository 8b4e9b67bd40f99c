// Compiled once per instruction set Highway targets (foreach_target re-includes this file);
// the functions at the end dispatch at run time to the widest the CPU has.
#include "polygon_separation_kernel.hpp"

#ifdef GRAINLAB_HAS_WIDE_SIMD
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "polygon_separation_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <limits>

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// At most a polygon's slots per vector: every vector width divides kMaxPolygonVertices, so whole
// vectors cover the slots.
using Tag = hn::CappedTag<double, kMaxPolygonVertices>;

// The first of a polygon's slots in `values` equal to `value`, and the greatest (or, with
// kLeast, the least) of the other slots' values. The callers fill the slots past the polygon's
// corners with −∞ (+∞), which never win.
template <bool kLeast>
int firstAndRest(const double* values, double value, double& rest) {
  const Tag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const double none = kLeast ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  int first = 0;
  for (int e = 0; e < kMaxPolygonVertices; e += lanes) {
    const intptr_t lane = hn::FindFirstTrue(d, hn::Eq(hn::LoadU(d, values + e), hn::Set(d, value)));
    if (lane >= 0) {
      first = e + static_cast<int>(lane);
      break;
    }
  }
  auto others = hn::Set(d, none);
  for (int e = 0; e < kMaxPolygonVertices; e += lanes) {
    const auto isFirst = hn::Eq(hn::Iota(d, e), hn::Set(d, static_cast<double>(first)));
    const auto v = hn::IfThenElse(isFirst, hn::Set(d, none), hn::LoadU(d, values + e));
    others = kLeast ? hn::Min(others, v) : hn::Max(others, v);
  }
  rest = hn::GetLane(kLeast ? hn::MinOfLanes(d, others) : hn::MaxOfLanes(d, others));
  return first;
}

double BestSeparatingFace(const PolygonFeatureTable& ref, const PolygonFeatureTable& other, double dx, double dy,
                          double c, double s, double* wx, double* wy, int& face, double& runnerUp) {
  const Tag d;
  const int faces = ref.count, count = other.count;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto Dx = hn::Set(d, dx), Dy = hn::Set(d, dy), C = hn::Set(d, c), S = hn::Set(d, s);
  for (int v = 0; v < kMaxPolygonVertices; v += lanes) {
    const auto ux = hn::LoadU(d, other.vx + v), uy = hn::LoadU(d, other.vy + v);
    hn::StoreU(hn::Sub(hn::Add(Dx, hn::Mul(C, ux)), hn::Mul(S, uy)), d, wx + v);  // d.x + c u.x − s u.y
    hn::StoreU(hn::Add(hn::Add(Dy, hn::Mul(S, ux)), hn::Mul(C, uy)), d, wy + v);  // d.y + s u.x + c u.y
  }
  const auto infinity = hn::Set(d, std::numeric_limits<double>::infinity());
  const auto below = hn::Neg(infinity);
  HWY_ALIGN double separation[kMaxPolygonVertices];
  auto greatest = below;
  for (int e = 0; e < kMaxPolygonVertices; e += lanes) {
    const auto nx = hn::LoadU(d, ref.nx + e), ny = hn::LoadU(d, ref.ny + e), offset = hn::LoadU(d, ref.offset + e);
    // Two running leasts (even and odd vertices), so that each compare waits on half as many.
    auto even = infinity, odd = infinity;
    int v = 0;
    for (; v + 1 < count; v += 2) {
      const auto s0 = hn::Sub(hn::Add(hn::Mul(nx, hn::Set(d, wx[v])), hn::Mul(ny, hn::Set(d, wy[v]))), offset);
      const auto s1 = hn::Sub(hn::Add(hn::Mul(nx, hn::Set(d, wx[v + 1])), hn::Mul(ny, hn::Set(d, wy[v + 1]))), offset);
      even = hn::IfThenElse(hn::Lt(s0, even), s0, even);
      odd = hn::IfThenElse(hn::Lt(s1, odd), s1, odd);
    }
    if (v < count) {
      const auto s0 = hn::Sub(hn::Add(hn::Mul(nx, hn::Set(d, wx[v])), hn::Mul(ny, hn::Set(d, wy[v]))), offset);
      even = hn::IfThenElse(hn::Lt(s0, even), s0, even);
    }
    const auto least = hn::IfThenElse(hn::Lt(odd, even), odd, even);
    const auto faceSlots = hn::Lt(hn::Iota(d, e), hn::Set(d, static_cast<double>(faces)));
    const auto separations = hn::IfThenElse(faceSlots, least, below);
    hn::Store(separations, d, separation + e);
    greatest = hn::Max(greatest, separations);
  }
  face = firstAndRest<false>(separation, hn::GetLane(hn::MaxOfLanes(d, greatest)), runnerUp);
  return separation[face];
}

int MostAntiParallelEdge(double nx, double ny, double c, double s, const PolygonFeatureTable& incident,
                         double& least, double& nextLeast) {
  const Tag d;
  const int count = incident.count;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto Nx = hn::Set(d, nx), Ny = hn::Set(d, ny), C = hn::Set(d, c), S = hn::Set(d, s);
  const auto above = hn::Set(d, std::numeric_limits<double>::infinity());
  HWY_ALIGN double facing[kMaxPolygonVertices];
  auto lowest = above;
  for (int q = 0; q < kMaxPolygonVertices; q += lanes) {
    const auto mx = hn::LoadU(d, incident.nx + q), my = hn::LoadU(d, incident.ny + q);
    // n·turn(m): n_x (c m_x − s m_y) + n_y (s m_x + c m_y)
    const auto f = hn::Add(hn::Mul(Nx, hn::Sub(hn::Mul(C, mx), hn::Mul(S, my))),
                           hn::Mul(Ny, hn::Add(hn::Mul(S, mx), hn::Mul(C, my))));
    const auto edges = hn::IfThenElse(hn::Lt(hn::Iota(d, q), hn::Set(d, static_cast<double>(count))), f, above);
    hn::Store(edges, d, facing + q);
    lowest = hn::Min(lowest, edges);
  }
  const int edge = firstAndRest<true>(facing, hn::GetLane(hn::MinOfLanes(d, lowest)), nextLeast);
  least = facing[edge];
  return edge;
}

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grainlab {
HWY_EXPORT(BestSeparatingFace);
HWY_EXPORT(MostAntiParallelEdge);

double bestSeparatingFaceWide(const PolygonFeatureTable& ref, const PolygonFeatureTable& other, double dx, double dy,
                              double c, double s, double* wx, double* wy, int& face, double& runnerUp) {
  return HWY_DYNAMIC_DISPATCH(BestSeparatingFace)(ref, other, dx, dy, c, s, wx, wy, face, runnerUp);
}

int mostAntiParallelEdgeWide(double nx, double ny, double c, double s, const PolygonFeatureTable& incident,
                             double& least, double& nextLeast) {
  return HWY_DYNAMIC_DISPATCH(MostAntiParallelEdge)(nx, ny, c, s, incident, least, nextLeast);
}

}  // namespace grainlab
#endif
#else  // a build without the wide path: simdPath() is always the baseline, which never calls these
#include <stdexcept>

namespace grainlab {
double bestSeparatingFaceWide(const PolygonFeatureTable&, const PolygonFeatureTable&, double, double, double, double,
                              double*, double*, int&, double&) {
  throw std::logic_error("bestSeparatingFaceWide: this build has no wide path");
}
int mostAntiParallelEdgeWide(double, double, double, double, const PolygonFeatureTable&, double&, double&) {
  throw std::logic_error("mostAntiParallelEdgeWide: this build has no wide path");
}
}  // namespace grainlab
#endif

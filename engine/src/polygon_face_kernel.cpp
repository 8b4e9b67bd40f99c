// Compiled once per instruction set Highway targets (foreach_target re-includes this file);
// measurePolygonFaces() dispatches at run time to the widest the CPU has.
#include "polygon_face_kernel.hpp"

#include <algorithm>
#include <cstddef>

#ifdef GRAINLAB_HAS_WIDE_SIMD
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "polygon_face_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace grainlab {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The slots' inputs from one slot on.
struct Lanes {
  const double *refX, *refY, *refC, *refS, *incX, *incY, *incC, *incS, *normalSign;
  const std::int64_t *face, *edge;
  const std::int32_t* pair;
};

// One vector of slots, of which the first `valid` are real: measurePolygons' operations, in
// its order, lane by lane (the scalar expression each line follows is beside it).
template <class Tag>
HWY_INLINE void measureVector(Tag d, const PolygonFaceKernelInput& in, const Lanes& at, size_t valid) {
  const hn::RebindToSigned<Tag> di;
  const auto zero = hn::Zero(d);
  const auto prx = hn::LoadU(d, at.refX), pry = hn::LoadU(d, at.refY);
  const auto prc = hn::LoadU(d, at.refC), prs = hn::LoadU(d, at.refS);
  const auto pic = hn::LoadU(d, at.incC), pis = hn::LoadU(d, at.incS);
  const auto F = hn::LoadU(di, at.face), E = hn::LoadU(di, at.edge);
  // dx = pi.x − pr.x; dX = c_r dx + s_r dy; dY = (−s_r) dx + c_r dy
  const auto dx = hn::Sub(hn::LoadU(d, at.incX), prx), dy = hn::Sub(hn::LoadU(d, at.incY), pry);
  const auto dX = hn::Add(hn::Mul(prc, dx), hn::Mul(prs, dy));
  const auto dY = hn::Add(hn::Mul(hn::Neg(prs), dx), hn::Mul(prc, dy));
  // c = c_r c_i + s_r s_i; s = c_r s_i − s_r c_i
  const auto c = hn::Add(hn::Mul(prc, pic), hn::Mul(prs, pis));
  const auto s = hn::Sub(hn::Mul(prc, pis), hn::Mul(prs, pic));
  const auto u0x = hn::GatherIndex(d, in.edges, E), u0y = hn::GatherIndex(d, in.edges + 1, E);
  const auto u1x = hn::GatherIndex(d, in.edges + 2, E), u1y = hn::GatherIndex(d, in.edges + 3, E);
  // x = dX + c u_x − s u_y; y = dY + s u_x + c u_y
  const auto x0 = hn::Sub(hn::Add(dX, hn::Mul(c, u0x)), hn::Mul(s, u0y));
  const auto y0 = hn::Add(hn::Add(dY, hn::Mul(s, u0x)), hn::Mul(c, u0y));
  const auto x1 = hn::Sub(hn::Add(dX, hn::Mul(c, u1x)), hn::Mul(s, u1y));
  const auto y1 = hn::Add(hn::Add(dY, hn::Mul(s, u1x)), hn::Mul(c, u1y));
  const auto nx = hn::GatherIndex(d, in.faces, F), ny = hn::GatherIndex(d, in.faces + 1, F);
  const auto lo = hn::GatherIndex(d, in.faces + 2, F), hi = hn::GatherIndex(d, in.faces + 3, F);
  const auto front = hn::GatherIndex(d, in.faces + 4, F);
  // s = n_x y − n_y x (along the face); h = n_x x + n_y y (above its line)
  const auto s0 = hn::Sub(hn::Mul(nx, y0), hn::Mul(ny, x0)), s1 = hn::Sub(hn::Mul(nx, y1), hn::Mul(ny, x1));
  const auto h0 = hn::Add(hn::Mul(nx, x0), hn::Mul(ny, y0)), h1 = hn::Add(hn::Mul(nx, x1), hn::Mul(ny, y1));
  // Touching unless !(s1 < s0) || s0 <= lo || s1 >= hi (the same tests, negated as written).
  const auto spans = hn::AndNot(hn::Or(hn::Le(s0, lo), hn::Ge(s1, hi)), hn::Lt(s1, s0));
  const auto D = hn::Sub(s0, s1), rise = hn::Sub(h1, h0);
  // std::min(s0, hi) is (hi < s0 ? hi : s0); std::max(s1, lo) is (s1 < lo ? lo : s1).
  const auto sa = hn::IfThenElse(hn::Lt(hi, s0), hi, s0), sb = hn::IfThenElse(hn::Lt(s1, lo), lo, s1);
  const auto below = hn::Sub(front, h0);
  const auto Da = hn::Add(hn::Mul(D, below), hn::Mul(hn::Sub(sa, s0), rise));
  const auto Db = hn::Add(hn::Mul(D, below), hn::Mul(hn::Sub(sb, s0), rise));
  const auto wa = hn::IfThenElseZero(hn::Gt(Da, zero), Da), wb = hn::IfThenElseZero(hn::Gt(Db, zero), Db);
  const auto weight = hn::Add(wa, wb);
  const auto touching = hn::AndNot(hn::Le(weight, zero), spans);
  // q = 1 / (D weight); ps = (wa sa + wb sb)(D q); ph = front − 0.5 (wa Da + wb Db) q
  const auto q = hn::Div(hn::Set(d, 1.0), hn::Mul(D, weight));
  const auto ps = hn::Mul(hn::Add(hn::Mul(wa, sa), hn::Mul(wb, sb)), hn::Mul(D, q));
  const auto ph = hn::Sub(front, hn::Mul(hn::Mul(hn::Set(d, 0.5), hn::Add(hn::Mul(wa, Da), hn::Mul(wb, Db))), q));
  // l = ps (−n_y, n_x) + ph n; point = x_r + R_r l; normal = ±R_r n
  const auto lx = hn::Add(hn::Mul(ps, hn::Neg(ny)), hn::Mul(ph, nx));
  const auto ly = hn::Add(hn::Mul(ps, nx), hn::Mul(ph, ny));
  const auto px = hn::Sub(hn::Add(prx, hn::Mul(prc, lx)), hn::Mul(prs, ly));
  const auto py = hn::Add(hn::Add(pry, hn::Mul(prs, lx)), hn::Mul(prc, ly));
  const auto sign = hn::LoadU(d, at.normalSign);
  const auto gnx = hn::Mul(sign, hn::Sub(hn::Mul(prc, nx), hn::Mul(prs, ny)));
  const auto gny = hn::Mul(sign, hn::Add(hn::Mul(prs, nx), hn::Mul(prc, ny)));
  // overlap = std::max(Da, Db) (weight q), std::max(Da, Db) being (Da < Db ? Db : Da)
  const auto overlap = hn::Mul(hn::IfThenElse(hn::Lt(Da, Db), Db, Da), hn::Mul(weight, q));

  constexpr size_t kMax = HWY_MAX_BYTES / sizeof(double);
  const size_t lanes = hn::Lanes(d);
  HWY_ALIGN double out[5 * kMax];
  hn::Store(gnx, d, out);
  hn::Store(gny, d, out + lanes);
  hn::Store(px, d, out + 2 * lanes);
  hn::Store(py, d, out + 3 * lanes);
  hn::Store(overlap, d, out + 4 * lanes);
  std::uint8_t bits[8] = {};
  hn::StoreMaskBits(d, touching, bits);
  for (size_t l = 0; l < valid; ++l) {
    ContactGeometry& g = in.contacts[at.pair[l]];
    if (!((bits[l / 8] >> (l % 8)) & 1)) {
      g = ContactGeometry{};
      continue;
    }
    g.normal = Vec2(out[l], out[lanes + l]);
    g.point = Vec2(out[2 * lanes + l], out[3 * lanes + l]);
    g.overlap = out[4 * lanes + l];
  }
}

void MeasurePolygonFaces(const PolygonFaceKernelInput& in, int count) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d), n = static_cast<size_t>(count);
  auto from = [&](size_t s) {
    return Lanes{in.refX + s, in.refY + s, in.refC + s, in.refS + s, in.incX + s, in.incY + s, in.incC + s,
                 in.incS + s, in.normalSign + s, in.face + s, in.edge + s, in.pair + s};
  };
  size_t s = 0;
  for (; s + lanes <= n; s += lanes) measureVector(d, in, from(s), lanes);
  if (s == n) return;
  // The last part-vector: its slots copied, the rest of the vector filled with its last slot
  // (measured and dropped), so no lane reads past the range (another thread's slots).
  constexpr size_t kMax = HWY_MAX_BYTES / sizeof(double);
  double buffer[9][kMax];
  std::int64_t index[2][kMax];
  std::int32_t pair[kMax];
  const double* sources[9] = {in.refX, in.refY, in.refC, in.refS, in.incX, in.incY, in.incC, in.incS, in.normalSign};
  const std::int64_t* indexSources[2] = {in.face, in.edge};
  for (size_t l = 0; l < lanes; ++l) {
    const size_t from = std::min(s + l, n - 1);
    for (int a = 0; a < 9; ++a) buffer[a][l] = sources[a][from];
    for (int a = 0; a < 2; ++a) index[a][l] = indexSources[a][from];
    pair[l] = in.pair[from];
  }
  const Lanes tail{buffer[0], buffer[1], buffer[2], buffer[3], buffer[4], buffer[5], buffer[6], buffer[7],
                   buffer[8], index[0], index[1], pair};
  measureVector(d, in, tail, n - s);
}

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grainlab {
HWY_EXPORT(MeasurePolygonFaces);

void measurePolygonFaces(const PolygonFaceKernelInput& in, int count) {
  HWY_DYNAMIC_DISPATCH(MeasurePolygonFaces)(in, count);
}

}  // namespace grainlab
#endif
#else  // a build without the wide path: simdPath() is always the baseline, which never calls this
#include <stdexcept>

namespace grainlab {
void measurePolygonFaces(const PolygonFaceKernelInput&, int) {
  throw std::logic_error("measurePolygonFaces: this build has no wide path");
}
}  // namespace grainlab
#endif

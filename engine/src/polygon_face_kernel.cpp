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

// The slots' inputs from one slot on (i and j only where the law is applied), and where the
// first of them writes its forces.
struct Lanes {
  const double *refX, *refY, *refC, *refS, *incX, *incY, *incC, *incS, *normalSign;
  const std::int64_t *face, *edge;
  const std::int32_t* pair;
  const std::int64_t *i = nullptr, *j = nullptr;
  size_t slot = 0;
};

// The law at one vector of contacts: ContactSolver::contactForce and lawForce for a pair of
// polygons, lane by lane, in their operations and order (the scalar expression each line
// follows is beside it). n is the normal from i to j, p the contact point; the touching lanes'
// state and contact go back to their pairs and every valid lane's outputs to its slot.
template <class Tag, class V>
HWY_INLINE void lawVector(Tag d, const PolygonFaceForceInput& f, ContactGeometry* contacts, const Lanes& at,
                          size_t valid, V nx, V ny, V px, V py, V overlap, V faceA, V prx, V pry, V inx, V iny,
                          const std::uint8_t* touchingBits) {
  const hn::RebindToSigned<Tag> di;
  constexpr size_t kMax = HWY_MAX_BYTES / sizeof(double);
  const size_t lanes = hn::Lanes(d);
  // The pairs' state, lane by lane (a pair's state is one cache line, read just before by
  // the pair loop).
  HWY_ALIGN double state[3 * kMax];
  for (size_t l = 0; l < lanes; ++l) {
    const PairState& p = f.pairs[at.pair[l]];
    state[l] = p.dampN;
    state[lanes + l] = p.dampT;
    state[2 * lanes + l] = p.history.tangential;
  }
  const auto dampN = hn::Load(d, state), dampT = hn::Load(d, state + lanes);
  auto history = hn::Load(d, state + 2 * lanes);
  const auto I = hn::LoadU(di, at.i), J = hn::LoadU(di, at.j);
  const auto vix = hn::GatherIndex(d, f.velocity, hn::Add(I, I)), viy = hn::GatherIndex(d, f.velocity + 1, hn::Add(I, I));
  const auto vjx = hn::GatherIndex(d, f.velocity, hn::Add(J, J)), vjy = hn::GatherIndex(d, f.velocity + 1, hn::Add(J, J));
  const auto wi = hn::GatherIndex(d, f.spin, I), wj = hn::GatherIndex(d, f.spin, J);
  // i is the reference body where its face is the reference face (normal sign +1).
  const auto isRef = hn::Gt(faceA, hn::Zero(d));
  const auto xix = hn::IfThenElse(isRef, prx, inx), xiy = hn::IfThenElse(isRef, pry, iny);
  const auto xjx = hn::IfThenElse(isRef, inx, prx), xjy = hn::IfThenElse(isRef, iny, pry);
  // t = perp(n) = (−n_y, n_x); r_i = p − x_i; dv = −(v_i + ω_i × r_i), ω × r = (−ω r_y, ω r_x)
  const auto tx = hn::Neg(ny), ty = nx;
  const auto rix = hn::Sub(px, xix), riy = hn::Sub(py, xiy);
  auto dvx = hn::Neg(hn::Add(vix, hn::Mul(hn::Neg(wi), riy)));
  auto dvy = hn::Neg(hn::Add(viy, hn::Mul(wi, rix)));
  // r_j = p − x_j; dv += v_j + ω_j × r_j
  const auto rjx = hn::Sub(px, xjx), rjy = hn::Sub(py, xjy);
  dvx = hn::Add(dvx, hn::Add(vjx, hn::Mul(hn::Neg(wj), rjy)));
  dvy = hn::Add(dvy, hn::Add(vjy, hn::Mul(wj, rjx)));
  // v_n = dv·n, v_t = dv·t; f_n = k_n δ − c_n v_n
  const auto vn = hn::Add(hn::Mul(dvx, nx), hn::Mul(dvy, ny));
  const auto vt = hn::Add(hn::Mul(dvx, tx), hn::Mul(dvy, ty));
  const auto fn = hn::Sub(hn::Mul(hn::Set(d, f.law.normalStiffness), overlap), hn::Mul(dampN, vn));
  auto ft = hn::Zero(d);
  if (f.law.frictional) {
    // h += v_t dt; f_t = −k_t h − c_t v_t; capped at μ f_n (0 where f_n <= 0), h then set so
    // that spring and dashpot sit at the cap: h = −(f_t + c_t v_t) / k_t.
    const auto kt = hn::Set(d, f.law.tangentialStiffness);
    history = hn::Add(history, hn::Mul(vt, hn::Set(d, f.law.dt)));
    ft = hn::Sub(hn::Mul(hn::Neg(kt), history), hn::Mul(dampT, vt));
    const auto zero = hn::Zero(d);
    const auto cap = hn::IfThenElse(hn::Gt(fn, zero), hn::Mul(hn::Set(d, f.law.friction), fn), zero);
    const auto slides = hn::Gt(hn::Abs(ft), cap);
    ft = hn::IfThenElse(slides, hn::CopySign(cap, ft), ft);
    history = hn::IfThenElse(slides, hn::Div(hn::Neg(hn::Add(ft, hn::Mul(dampT, vt))), kt), history);
  }
  // F = f_n n + f_t t; τ_i = r_i × F, τ_j = r_j × F
  const auto Fx = hn::Add(hn::Mul(fn, nx), hn::Mul(ft, tx)), Fy = hn::Add(hn::Mul(fn, ny), hn::Mul(ft, ty));
  const auto ti = hn::Sub(hn::Mul(rix, Fy), hn::Mul(riy, Fx));
  const auto tj = hn::Sub(hn::Mul(rjx, Fy), hn::Mul(rjy, Fx));
  HWY_ALIGN double out[12 * kMax];
  hn::Store(Fx, d, out);
  hn::Store(Fy, d, out + lanes);
  hn::Store(ti, d, out + 2 * lanes);
  hn::Store(tj, d, out + 3 * lanes);
  hn::Store(fn, d, out + 4 * lanes);
  hn::Store(ft, d, out + 5 * lanes);
  hn::Store(history, d, out + 6 * lanes);
  hn::Store(overlap, d, out + 7 * lanes);
  hn::Store(nx, d, out + 8 * lanes);
  hn::Store(ny, d, out + 9 * lanes);
  hn::Store(px, d, out + 10 * lanes);
  hn::Store(py, d, out + 11 * lanes);
  for (size_t l = 0; l < valid; ++l) {
    const size_t s = at.slot + l;
    const bool touches = (touchingBits[l / 8] >> (l % 8)) & 1;
    f.touching[s] = touches;
    if (!touches) continue;
    f.fx[s] = out[l];
    f.fy[s] = out[lanes + l];
    f.torqueI[s] = out[2 * lanes + l];
    f.torqueJ[s] = out[3 * lanes + l];
    PairState& p = f.pairs[at.pair[l]];
    p.fn = out[4 * lanes + l];
    p.ft = out[5 * lanes + l];
    if (f.law.frictional) p.history.tangential = out[6 * lanes + l];
    p.overlap = out[7 * lanes + l];
    ContactGeometry& g = contacts[at.pair[l]];
    g.normal = Vec2(out[8 * lanes + l], out[9 * lanes + l]);
    g.point = Vec2(out[10 * lanes + l], out[11 * lanes + l]);
    g.overlap = p.overlap;
  }
}

// One vector of slots, of which the first `valid` are real: measurePolygons' operations, in
// its order, lane by lane (the scalar expression each line follows is beside it).
// With `forces` (not null) the law follows (lawVector), which writes the touching lanes' contacts.
template <class Tag>
HWY_INLINE void measureVector(Tag d, const PolygonFaceKernelInput& in, const PolygonFaceForceInput* forces,
                              const Lanes& at, size_t valid) {
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

  std::uint8_t bits[8] = {};
  hn::StoreMaskBits(d, touching, bits);
  if (forces) {
    lawVector(d, *forces, in.contacts, at, valid, gnx, gny, px, py, overlap, sign, prx, pry, hn::LoadU(d, at.incX),
              hn::LoadU(d, at.incY), bits);
    return;
  }
  constexpr size_t kMax = HWY_MAX_BYTES / sizeof(double);
  const size_t lanes = hn::Lanes(d);
  HWY_ALIGN double out[5 * kMax];
  hn::Store(gnx, d, out);
  hn::Store(gny, d, out + lanes);
  hn::Store(px, d, out + 2 * lanes);
  hn::Store(py, d, out + 3 * lanes);
  hn::Store(overlap, d, out + 4 * lanes);
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

// Slots [0, count), with the law where `forces` is not null.
void MeasureSlots(const PolygonFaceKernelInput& in, const PolygonFaceForceInput* forces, int count) {
  const hn::ScalableTag<double> d;
  const size_t lanes = hn::Lanes(d), n = static_cast<size_t>(count);
  auto from = [&](size_t s) {
    Lanes at{in.refX + s, in.refY + s, in.refC + s, in.refS + s, in.incX + s, in.incY + s, in.incC + s,
             in.incS + s, in.normalSign + s, in.face + s, in.edge + s, in.pair + s};
    if (forces) {
      at.i = forces->i + s;
      at.j = forces->j + s;
    }
    at.slot = s;
    return at;
  };
  size_t s = 0;
  for (; s + lanes <= n; s += lanes) measureVector(d, in, forces, from(s), lanes);
  if (s == n) return;
  // The last part-vector: its slots copied, the rest of the vector filled with its last slot
  // (measured and dropped), so no lane reads past the range (another thread's slots).
  constexpr size_t kMax = HWY_MAX_BYTES / sizeof(double);
  double buffer[9][kMax];
  std::int64_t index[4][kMax];
  std::int32_t pair[kMax];
  const double* sources[9] = {in.refX, in.refY, in.refC, in.refS, in.incX, in.incY, in.incC, in.incS, in.normalSign};
  const std::int64_t* indexSources[4] = {in.face, in.edge, forces ? forces->i : nullptr, forces ? forces->j : nullptr};
  for (size_t l = 0; l < lanes; ++l) {
    const size_t from = std::min(s + l, n - 1);
    for (int a = 0; a < 9; ++a) buffer[a][l] = sources[a][from];
    for (int a = 0; a < 4; ++a) index[a][l] = indexSources[a] ? indexSources[a][from] : 0;
    pair[l] = in.pair[from];
  }
  Lanes tail{buffer[0], buffer[1], buffer[2], buffer[3], buffer[4], buffer[5], buffer[6], buffer[7],
             buffer[8], index[0], index[1], pair};
  tail.i = index[2];
  tail.j = index[3];
  tail.slot = s;
  measureVector(d, in, forces, tail, n - s);
}

void MeasurePolygonFaces(const PolygonFaceKernelInput& in, int count) { MeasureSlots(in, nullptr, count); }
void MeasurePolygonFaceForces(const PolygonFaceKernelInput& in, const PolygonFaceForceInput& forces, int count) {
  MeasureSlots(in, &forces, count);
}

}  // namespace HWY_NAMESPACE
}  // namespace grainlab
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grainlab {
HWY_EXPORT(MeasurePolygonFaces);
HWY_EXPORT(MeasurePolygonFaceForces);

void measurePolygonFaces(const PolygonFaceKernelInput& in, int count) {
  HWY_DYNAMIC_DISPATCH(MeasurePolygonFaces)(in, count);
}
void measurePolygonFaceForces(const PolygonFaceKernelInput& in, const PolygonFaceForceInput& forces, int count) {
  HWY_DYNAMIC_DISPATCH(MeasurePolygonFaceForces)(in, forces, count);
}

}  // namespace grainlab
#endif
#else  // a build without the wide path: simdPath() is always the baseline, which never calls this
#include <stdexcept>

namespace grainlab {
void measurePolygonFaces(const PolygonFaceKernelInput&, int) {
  throw std::logic_error("measurePolygonFaces: this build has no wide path");
}
void measurePolygonFaceForces(const PolygonFaceKernelInput&, const PolygonFaceForceInput&, int) {
  throw std::logic_error("measurePolygonFaceForces: this build has no wide path");
}
}  // namespace grainlab
#endif

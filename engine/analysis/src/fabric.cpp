#include "grainlab/analysis/fabric.hpp"

#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>

#include "grainlab/analysis/angles.hpp"
#include "grainlab/analysis/contact_ends.hpp"

namespace grainlab::analysis {

namespace {

using cplx = std::complex<double>;

struct Harmonics {
  double g0 = 0;
  cplx g2{};
};

// Solves M0 = g0 + ½ Re(G2 Ā_c), M2 = ½ (g0 A_c + G2) for g0 and G2: the exact expectation of
// the sample moments when g(θ) = g0 + Re(G2 e^{−2iθ}) and contacts follow E(θ).
Harmonics solveHarmonics(double M0, cplx M2, cplx Ac) {
  const double det = 1.0 - 0.5 * std::norm(Ac);
  // |A_c|² = 2 only when the ends span too few directions to separate the mean from the
  // second harmonic (e.g. two directions 45° apart); the plain mean is then the best guess.
  const double g0 = std::abs(det) > 1e-9 ? (M0 - (Ac * std::conj(M2)).real()) / det : M0;
  return {g0, 2.0 * M2 - g0 * Ac};
}

void setTerm(cplx A, double& a, double& thetaDeg) {
  a = std::abs(A);
  thetaDeg = axialDirectionDeg(A);
}

}  // namespace

cplx FabricState::A(Term k) const { return axialComplex(a(k), thetaDeg(k)); }

double FabricState::a(Term k) const {
  switch (k) {
    case Term::c: return a_c;
    case Term::n: return a_n;
    case Term::t: return a_t;
    case Term::ln: return a_ln;
    case Term::lt: return a_lt;
  }
  return 0;
}

double FabricState::thetaDeg(Term k) const {
  switch (k) {
    case Term::c: return theta_c_deg;
    case Term::n: return theta_n_deg;
    case Term::t: return theta_t_deg;
    case Term::ln: return theta_ln_deg;
    case Term::lt: return theta_lt_deg;
  }
  return 0;
}

double momentEquilibriumAw(const FabricState& s) {
  const double tc = radians(s.theta_c_deg), tn = radians(s.theta_n_deg),
               tt = radians(s.theta_t_deg), tln = radians(s.theta_ln_deg),
               tlt = radians(s.theta_lt_deg);
  auto S = [](double x, double y) { return std::sin(2.0 * (x - y)); };
  auto C = [](double x, double y) { return std::cos(2.0 * (x - y)); };
  const double num = s.a_c * s.a_t * S(tc, tt) + s.a_t * s.a_ln * S(tln, tt) -
                     s.a_lt * (s.a_n * S(tn, tlt) + s.a_c * S(tc, tlt));
  const double den = 2.0 + s.a_c * s.a_ln * C(tc, tln);
  // den ≥ 2 − a_c a_ln > 0 for any distribution the Fourier forms can describe (a ≤ 1); only
  // a handful of contacts can push the measured coefficients past that, and then the direct
  // measure is all there is.
  return den > 0 ? num / den : s.a_w_direct;
}

FabricState measureFabric(std::span<const ContactRecord> contacts, std::span<const Vec2> centroids,
                          std::span<const unsigned char> inside, const PeriodicCell* cell) {
  // Plain sums in contact order: deterministic, and the moments are all the estimators need.
  // Real and imaginary parts are kept as separate doubles so the loop stays simple scalar code.
  struct Sums {
    double n = 0, ec = 0, es = 0;
    double fn = 0, fnc = 0, fns = 0, ft = 0, ftc = 0, fts = 0;
    double ln = 0, lnc = 0, lns = 0, lt = 0, ltc = 0, lts = 0;
  } m;
  std::int64_t ends = 0, distinct = 0;
  std::size_t lastContact = std::numeric_limits<std::size_t>::max();
  forEachInsideEnd(contacts, centroids, inside, [&](const ContactEnd& e) {
    m.n += 1;
    m.ec += e.cos2, m.es += e.sin2;
    m.fn += e.fn, m.fnc += e.fn * e.cos2, m.fns += e.fn * e.sin2;
    m.ft += e.ft, m.ftc += e.ft * e.cos2, m.fts += e.ft * e.sin2;
    m.ln += e.ln, m.lnc += e.ln * e.cos2, m.lns += e.ln * e.sin2;
    m.lt += e.lt, m.ltc += e.lt * e.cos2, m.lts += e.lt * e.sin2;
    ++ends;
    if (e.contact != lastContact) {
      ++distinct;
      lastContact = e.contact;
    }
  }, cell);
  const double n = m.n;
  const cplx se(m.ec, m.es), sfne(m.fnc, m.fns), sfte(m.ftc, m.fts), slne(m.lnc, m.lns),
      slte(m.ltc, m.lts);
  const double sfn = m.fn, sft = m.ft, sln = m.ln, slt = m.lt;

  FabricState s;
  s.ends = ends;
  s.contacts = distinct;
  if (ends == 0) return s;

  const double inv = 1.0 / n;
  const cplx Ac = 2.0 * inv * se;
  setTerm(Ac, s.a_c, s.theta_c_deg);

  const cplx I(0, 1);
  const Harmonics fn = solveHarmonics(sfn * inv, sfne * inv, Ac);
  const Harmonics ft = solveHarmonics(sft * inv, sfte * inv, Ac);
  const Harmonics ln = solveHarmonics(sln * inv, slne * inv, Ac);
  const Harmonics lt = solveHarmonics(slt * inv, slte * inv, Ac);

  s.f0 = fn.g0;
  if (s.f0 != 0) {
    setTerm(fn.g2 / s.f0, s.a_n, s.theta_n_deg);
    // f_t = f0[a_w − a_t sin 2(θ − θ_t)] has G2 = −i f0 A_t.
    setTerm(I * ft.g2 / s.f0, s.a_t, s.theta_t_deg);
    s.a_w_direct = ft.g0 / s.f0;
  }
  s.l0 = ln.g0;
  if (s.l0 != 0) {
    setTerm(ln.g2 / s.l0, s.a_ln, s.theta_ln_deg);
    setTerm(I * lt.g2 / s.l0, s.a_lt, s.theta_lt_deg);
    s.lt0_ratio = lt.g0 / s.l0;
  }
  s.a_w = momentEquilibriumAw(s);
  return s;
}

}  // namespace grainlab::analysis

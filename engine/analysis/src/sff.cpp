#include "grainlab/analysis/sff.hpp"

#include <cmath>

#include "grainlab/math.hpp"

namespace grainlab::analysis {

SffForm sffClosedForm(const FabricState& s) {
  using cplx = std::complex<double>;
  const cplx Ac = s.A(Term::c), An = s.A(Term::n), At = s.A(Term::t), Aln = s.A(Term::ln),
             Alt = s.A(Term::lt);
  const double tc = radians(s.theta_c_deg), tn = radians(s.theta_n_deg),
               tt = radians(s.theta_t_deg), tln = radians(s.theta_ln_deg),
               tlt = radians(s.theta_lt_deg);
  auto S = [](double x, double y) { return std::sin(2.0 * (x - y)); };
  auto C = [](double x, double y) { return std::cos(2.0 * (x - y)); };
  const double ac = s.a_c, an = s.a_n, at = s.a_t, aln = s.a_ln, alt = s.a_lt, aw = s.a_w;

  SffForm r;
  r.T = 1.0 +
        0.5 * (ac * an * C(tc, tn) + ac * aln * C(tc, tln) + an * aln * C(tn, tln) +
               at * alt * C(tt, tlt)) -
        0.5 * ac * alt * aw * S(tc, tlt);
  const cplx I(0, 1);
  r.Z = 0.5 * (Ac + An + At + Aln + Alt) + 0.5 * I * aw * (Ac + Aln + Alt) +
        0.125 * (Ac * (An + At) * (std::conj(Aln) - std::conj(Alt)) +
                 Ac * (std::conj(An) - std::conj(At)) * (Aln + Alt) +
                 std::conj(Ac) * (An + At) * (Aln + Alt));
  r.M = aw * (1.0 + 0.5 * ac * aln * C(tc, tln)) - 0.5 * ac * at * S(tc, tt) -
        0.5 * at * aln * S(tln, tt) + 0.5 * alt * (an * S(tn, tlt) + ac * S(tc, tlt));
  return r;
}

StressTensor sffStress(const FabricState& s, double endDensity) {
  const SffForm f = sffClosedForm(s);
  const double K = endDensity * s.f0 * s.l0;
  const double trace = K * f.T, diff = K * f.Z.real(), symShear = K * f.Z.imag(),
               skew = -K * f.M;  // σ12 − σ21
  StressTensor t;
  t.s11 = 0.5 * (trace + diff);
  t.s22 = 0.5 * (trace - diff);
  t.s12 = 0.5 * (symShear + skew);
  t.s21 = 0.5 * (symShear - skew);
  return t;
}

}  // namespace grainlab::analysis

// The stress-force-fabric relation on a real sheared DEM packing (circular-quick sheared to 20%
// axial strain, about 1 s): at every shearing sample, the stress that docs/micromechanics.md's
// exact closed form (sffStress) builds from the fabric measured on the contacts matches the
// contact stress (paper Eq. 1) within the error the formulas leave, and Eq. (7)'s θσ stays within
// its second-order error of the macro θσ. Both bounds are computed from the sample's own
// contacts and coefficients, not from what the code printed.
//
// Why the closed form can be held so tightly here. The estimators fit each per-end quantity g
// with g0 + Re(G2 e^{−2iθ}) so that the Fourier forms reproduce the moments ⟨g⟩ and ⟨g e^{2iθ}⟩
// exactly. For discs the branch vector is l = l_n n (l_t = 0), so the contact stress is
// T = m_v ⟨l_n f_n⟩ and Z = m_v ⟨l_n (f_n + i f_t) e^{2iθ}⟩: with l_n a constant l0 these are
// exactly the moments the closed form reproduces, whatever the higher harmonics of the real
// distributions. What is left is (a) l_n's departure η from l0 (equal discs: half an overlap,
// correlated with the force), giving |ΔT|, |ΔZ| ≤ m_v [η_rms |f|_rms + |G2[η]| f̄max (1 + a_c)], and
// (b) moment imbalance: the closed form takes a_w from moment equilibrium, the contacts carry
// a_w_direct, a difference of ½|a_w_direct − a_w|(a_c + a_ln) in Z (units of K = m_v f0 l0).
//
// Eq. (7) is the first-order part Z1 = ½ Σ_k A_k of the exact Z; the terms it drops are
// R = ½ i a_w (A_c + A_ln + A_lt) + ⅛[three products of three A's], so
// |R| ≤ ½ a_w (a_c + a_ln + a_lt) + ⅜ a_c (a_n + a_t)(a_ln + a_lt), and its direction is off the
// exact one by at most ½ asin(|R| / |Z1|). Adding the closed form's own distance from the contact
// stress, ½ asin(|ΔZ| / |Z|), bounds |θσ(Eq. 7) − θσ(macro)|.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "grainlab/analysis/fabric.hpp"
#include "grainlab/analysis/sff.hpp"
#include "grainlab/analysis/stress_direction.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/stress.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

using analysis::FabricState;
using analysis::Term;
using cd = std::complex<double>;

double axialDiffDeg(double a, double b) { return std::abs(std::remainder(a - b, 180.0)); }
double halfAsinDeg(double x) { return 0.5 * std::asin(std::min(x, 1.0)) * 180 / kPi; }
cd deviator(const StressTensor& s) { return {s.s11 - s.s22, s.s12 + s.s21}; }

class SffProbe : public RunObserver {
 public:
  void onSample(const Sample& sample, const World& world) override {
    if (sample.stage != "shearing") return;
    const auto column = [&](const char* name) { return sample.values[seriesColumnIndex(name)]; };
    world.contacts(contacts_);
    const auto x = world.positions();
    std::vector<unsigned char> inside(world.size());
    for (int k = 0; k < world.size(); ++k) inside[k] = world.boundaryFlags()[k] ? 0 : 1;
    const double area = column("area");
    const StressTensor contact = contactStress(contacts_, x, inside, area);
    // The same specimen and area as the series: the run's own σ.
    const double p = column("p");
    worstSeries = std::max({worstSeries, std::abs(contact.s11 - column("sigma11")) / p,
                            std::abs(contact.s22 - column("sigma22")) / p, std::abs(contact.s12 - column("sigma12")) / p});

    const FabricState f = analysis::measureFabric(contacts_, x, inside);
    const double endDensity = static_cast<double>(f.ends) / area;
    const StressTensor sff = analysis::sffStress(f, endDensity);
    const double K = endDensity * f.f0 * f.l0;

    // (a): the spread of l_n about l0, and of the force magnitude, over the specimen's ends.
    double etaSquares = 0, forceSquares = 0;
    std::int64_t ends = 0;
    for (const ContactRecord& c : contacts_) {
      for (const bool first : {true, false}) {
        const int owner = first ? c.i : c.j;
        if (!first && c.isWall()) continue;
        if (!inside[owner]) continue;
        const Vec2 n = first ? c.normal : Vec2(-c.normal);
        const double eta = (c.point - x[owner]).dot(n) - f.l0;
        etaSquares += eta * eta;
        forceSquares += c.fn * c.fn + c.ft * c.ft;
        ++ends;
      }
    }
    ASSERT_EQ(ends, f.ends);
    // By Cauchy-Schwarz |⟨η g⟩| ≤ η_rms g_rms, so |ΔT|, |ΔZ| from the contacts' side ≤ m_v η_rms |f|_rms;
    // on the closed form's side the l_n term l0 A_ln = G2[l_n] = G2[η] = 2⟨η e^{2iθ}⟩ (g0[η] = 0,
    // as η is l_n less g0[l_n]), at most 2 η_rms, weighs the Fourier forces
    // f̄ ≤ f0 (1 + a_n + a_t + |a_w|) under 2πE ≤ 1 + a_c.
    const double etaRms = std::sqrt(etaSquares / ends), forceRms = std::sqrt(forceSquares / ends);
    const double ac = f.a_c, g2Eta = 2 * etaRms;
    const double fMax = f.f0 * (1 + f.a_n + f.a_t + std::abs(f.a_w)), eMax = 1 + ac;
    const double boundA = endDensity * (etaRms * forceRms + g2Eta * fMax * eMax);
    const double boundB = 0.5 * std::abs(f.a_w_direct - f.a_w) * (f.a_c + f.a_ln) * K;
    const double bound = boundA + boundB;
    const double dT = std::abs((sff.s11 + sff.s22) - (contact.s11 + contact.s22));
    const double dZ = std::abs(deviator(sff) - deviator(contact));
    worstSff = std::max({worstSff, dT / bound, dZ / bound});
    largestBound = std::max(largestBound, bound / (2 * contact.p()));

    // Eq. (7) against the macro direction, where the stress has a direction to speak of.
    if (contact.q() < 0.1 * contact.p()) return;
    cd z1 = 0;
    for (Term k : {Term::c, Term::n, Term::t, Term::ln, Term::lt}) z1 += 0.5 * f.A(k);
    const double r = 0.5 * std::abs(f.a_w) * (f.a_c + f.a_ln + f.a_lt) + 0.375 * f.a_c * (f.a_n + f.a_t) * (f.a_ln + f.a_lt);
    const double allowed = halfAsinDeg(r / std::abs(z1)) + halfAsinDeg(dZ / std::abs(deviator(contact)));
    const double macro = analysis::thetaSigmaMacroDeg(contact);
    const double eq7 = column("theta_sigma_micro_deg");
    worstEq7 = std::max(worstEq7, axialDiffDeg(eq7, macro) / allowed);
    largestEq7Error = std::max(largestEq7Error, axialDiffDeg(eq7, macro));
    largestAllowed = std::max(largestAllowed, allowed);
    largestQ = std::max(largestQ, contact.q() / contact.p());
    ++directed;
  }

  double worstSeries = 0, worstSff = 0, largestBound = 0, worstEq7 = 0, largestEq7Error = 0, largestAllowed = 0,
         largestQ = 0;
  int directed = 0;

 private:
  std::vector<ContactRecord> contacts_;
};

TEST(ShearedPackingSff, ClosedFormStressAndEq7DirectionMatchTheContactStressWithinTheirErrors) {
  SffProbe probe;
  const RunSummary summary = runScene(parseScene(presetScene("circular-quick")), probe);
  ASSERT_EQ(summary.status, RunStatus::Completed) << summary.error;
  std::printf("worst |σ(sff) − σ(contacts)| / bound = %.3f (bound at most %.2e of T); worst |θσ(Eq. 7) − θσ(macro)| "
              "= %.3f°, / its bound = %.3f (bound at most %.3f°) over %d samples, q/p up to %.3f\n",
              probe.worstSff, probe.largestBound, probe.largestEq7Error, probe.worstEq7, probe.largestAllowed,
              probe.directed, probe.largestQ);
  EXPECT_LT(probe.worstSeries, 1e-12);  // the ends and area the series used
  EXPECT_LE(probe.worstSff, 1.0);
  EXPECT_LE(probe.worstEq7, 1.0);
  // Not vacuous: sheared well past the first samples, and a bound tighter than the dropped terms
  // it has to tell apart (an error of a_c·a_n ~ 0.05 of T in the closed form would show): at
  // most half of them.
  EXPECT_GT(probe.directed, 20);
  EXPECT_GT(probe.largestQ, 0.3);
  EXPECT_LT(probe.largestBound, 0.025);
}

}  // namespace
}  // namespace grainlab

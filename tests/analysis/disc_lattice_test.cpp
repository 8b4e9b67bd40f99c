// Issue 4, test 3: mono-sized discs on a hexagonal lattice, contacts built by hand from the
// geometry. Disc branch vectors are R·n, so a_ln = a_lt = 0; the fabric and the stress turn
// with the assembly.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "grainlab/analysis/angles.hpp"
#include "grainlab/analysis/fabric.hpp"
#include "grainlab/analysis/sff.hpp"
#include "grainlab/stress.hpp"

namespace grainlab::analysis {
namespace {

constexpr double kR = 1e-3;   // disc radius, m
constexpr double kF = 250.0;  // force scale, N/m

struct Assembly {
  std::vector<Vec2> centroids;
  std::vector<unsigned char> inside;
  std::vector<ContactRecord> contacts;
};

// Mean force curves, a function of the contact direction only (θ radians): a_n = 0.4 at 30°,
// a_t = 0.2 at 75°, a_w = 0. Compressive everywhere.
double fnOf(double th) { return kF * (1 + 0.4 * std::cos(2 * (th - radians(30)))); }
double ftOf(double th) { return kF * (-0.2 * std::sin(2 * (th - radians(75)))); }

// Discs of radius R touching on a hexagonal lattice. `keep(m, n)` selects lattice sites
// (site m a1 + n a2 with a1 = (2R, 0), a2 = (R, √3 R)); `isInside` flags the specimen.
template <class Keep, class Inside>
Assembly hexPatch(Keep keep, Inside isInside, int extent) {
  Assembly a;
  std::map<std::pair<int, int>, int> index;  // ordered: the contact order is deterministic
  for (int n = -extent; n <= extent; ++n)
    for (int m = -extent; m <= extent; ++m) {
      if (!keep(m, n)) continue;
      const Vec2 x = Vec2(2 * kR, 0) * m + Vec2(kR, std::sqrt(3.0) * kR) * n;
      index[{m, n}] = static_cast<int>(a.centroids.size());
      a.centroids.push_back(x);
      a.inside.push_back(isInside(m, n) ? 1 : 0);
    }
  // Each touching pair once, i < j along the three lattice directions 0°, 60°, 120°.
  const std::pair<int, int> steps[] = {{1, 0}, {0, 1}, {-1, 1}};
  for (const auto& [site, i] : index)
    for (const auto& [dm, dn] : steps) {
      const auto it = index.find({site.first + dm, site.second + dn});
      if (it == index.end()) continue;
      const int j = it->second;
      ContactRecord c;
      c.i = i;
      c.j = j;
      const Vec2 d = a.centroids[static_cast<size_t>(j)] - a.centroids[static_cast<size_t>(i)];
      c.normal = d.normalized();
      c.point = a.centroids[static_cast<size_t>(i)] + kR * c.normal;
      const double th = std::atan2(c.normal.y(), c.normal.x());
      c.fn = fnOf(th);
      c.ft = ftOf(th);
      a.contacts.push_back(c);
    }
  return a;
}

// A round patch whose inside particles all keep their six neighbours.
Assembly roundPatch() {
  auto radius2 = [](int m, int n) {  // |m a1 + n a2|² / (2R)²
    const double x = m + 0.5 * n, y = 0.5 * std::sqrt(3.0) * n;
    return x * x + y * y;
  };
  return hexPatch([&](int m, int n) { return radius2(m, n) <= 8.0 * 8.0; },
                  [&](int m, int n) { return radius2(m, n) <= 6.0 * 6.0; }, 10);
}

// A long strip, all inside: its edge particles lack neighbours, so contacts along the strip
// outnumber the others and a_c ≠ 0.
Assembly stripPatch() {
  return hexPatch([](int m, int n) { return std::abs(n) <= 2 && std::abs(2 * m + n) <= 24; },
                  [](int, int) { return true; }, 20);
}

Assembly rotated(const Assembly& a, double deg) {
  Assembly r = a;
  const double b = radians(deg);
  for (Vec2& x : r.centroids) x = rotate(x, b);
  for (ContactRecord& c : r.contacts) {
    c.point = rotate(c.point, b);
    c.normal = rotate(c.normal, b);
  }
  return r;
}

FabricState measure(const Assembly& a) { return measureFabric(a.contacts, a.centroids, a.inside); }

TEST(DiscLattice, NoBranchAnisotropyAndExactForceTerms) {
  const Assembly a = roundPatch();
  const FabricState f = measure(a);
  ASSERT_GT(f.ends, 300);
  // Every end of a disc has l = R n: l_n = R exactly, l_t = 0.
  EXPECT_NEAR(f.a_ln, 0.0, 1e-12);
  EXPECT_NEAR(f.a_lt, 0.0, 1e-12);
  EXPECT_NEAR(f.l0, kR, 1e-12 * kR);
  EXPECT_NEAR(f.lt0_ratio, 0.0, 1e-12);
  // Inside particles all have their six neighbours: three directions 60° apart, isotropic.
  EXPECT_NEAR(f.a_c, 0.0, 1e-12);
  // Three directions equally spaced on 2θ determine a second-order curve exactly.
  EXPECT_NEAR(f.f0, kF, 1e-12 * kF);
  EXPECT_NEAR(f.a_n, 0.4, 1e-12);
  EXPECT_NEAR(wrapAxialDeg(f.theta_n_deg - 30), 0.0, 1e-9);
  EXPECT_NEAR(f.a_t, 0.2, 1e-12);
  EXPECT_NEAR(wrapAxialDeg(f.theta_t_deg - 75), 0.0, 1e-9);
  EXPECT_NEAR(f.a_w, 0.0, 1e-12);
  EXPECT_NEAR(f.a_w_direct, 0.0, 1e-12);
}

TEST(DiscLattice, ContactStressIsTheClosedFormAndSymmetric) {
  const Assembly a = roundPatch();
  const double area = 1.0;
  const StressTensor s = contactStress(a.contacts, a.centroids, a.inside, area);
  const FabricState f = measure(a);
  // Every particle is in force and moment equilibrium (f_t sums to zero over three directions
  // 60° apart), so the stress is symmetric.
  const double p = s.p();
  ASSERT_GT(p, 0);
  EXPECT_NEAR(s.s12 - s.s21, 0.0, 1e-12 * p);
  // With three directions equally spaced on 2θ the products up to the 4th harmonic in Eq. (1)
  // average exactly, so the discrete stress is the closed form to rounding.
  const StressTensor c = sffStress(f, static_cast<double>(f.ends) / area);
  EXPECT_NEAR(s.s11, c.s11, 1e-12 * p);
  EXPECT_NEAR(s.s12, c.s12, 1e-12 * p);
  EXPECT_NEAR(s.s21, c.s21, 1e-12 * p);
  EXPECT_NEAR(s.s22, c.s22, 1e-12 * p);
}

TEST(DiscLattice, RotationShiftsDirectionsAndKeepsCoefficients) {
  for (const Assembly& a : {roundPatch(), stripPatch()}) {
    const FabricState f0 = measure(a);
    const StressTensor s0 = contactStress(a.contacts, a.centroids, a.inside, 1.0);
    for (double beta : {17.0, 100.0, 233.0, -61.0}) {
      SCOPED_TRACE(beta);
      const Assembly r = rotated(a, beta);
      const FabricState f = measure(r);
      EXPECT_EQ(f.ends, f0.ends);
      EXPECT_EQ(f.contacts, f0.contacts);
      for (Term k : {Term::c, Term::n, Term::t, Term::ln, Term::lt}) {
        EXPECT_NEAR(f.a(k), f0.a(k), 1e-12);
        // A direction exists only where its coefficient is clear of rounding.
        if (f0.a(k) > 1e-6) {
          EXPECT_NEAR(wrapAxialDeg(f.thetaDeg(k) - f0.thetaDeg(k) - beta), 0.0, 1e-9);
        }
      }
      EXPECT_NEAR(f.f0, f0.f0, 1e-12 * kF);
      EXPECT_NEAR(f.l0, f0.l0, 1e-12 * kR);
      EXPECT_NEAR(f.a_w, f0.a_w, 1e-12);
      // And the stress turns as a tensor: σ' = Q σ Qᵀ.
      const double b = radians(beta);
      Eigen::Matrix2d Q;
      Q << std::cos(b), -std::sin(b), std::sin(b), std::cos(b);
      Eigen::Matrix2d S0;
      S0 << s0.s11, s0.s12, s0.s21, s0.s22;
      const Eigen::Matrix2d want = Q * S0 * Q.transpose();
      const StressTensor s = contactStress(r.contacts, r.centroids, r.inside, 1.0);
      const double tol = 1e-12 * s0.p();
      EXPECT_NEAR(s.s11, want(0, 0), tol);
      EXPECT_NEAR(s.s12, want(0, 1), tol);
      EXPECT_NEAR(s.s21, want(1, 0), tol);
      EXPECT_NEAR(s.s22, want(1, 1), tol);
    }
  }
}

TEST(DiscLattice, StripHasContactAnisotropyAlongItsLength) {
  const FabricState f = measure(stripPatch());
  // Rows of contacts along the strip (0°) are complete; the 60° and 120° ones are cut at the
  // two long edges, so the contact normals favour the strip's axis.
  EXPECT_GT(f.a_c, 0.05);
  EXPECT_NEAR(wrapAxialDeg(f.theta_c_deg - 0.0), 0.0, 1e-9);
  EXPECT_NEAR(f.a_ln, 0.0, 1e-12);
  EXPECT_NEAR(f.a_lt, 0.0, 1e-12);
}

}  // namespace
}  // namespace grainlab::analysis

// Issue 24, part 3: the sign of ω. A hexagonal lattice of discs, unstressed, is compressed
// along the 2-axis with no shear strain (affine displacement u = (0, −ε y)); each contact is a
// linear spring, f_n = k(θ)·δ with δ = ε |d| sin²θ, f_t = −k_t·(Δd·t) = k_t ε |d| sinθ cosθ.
// Solved by hand, the stress tilts toward the stiffest direction: a stiff direction between
// 90° and 180° gives σ12 < 0, θσ > 90°, ω = θσ − 90° > 0. These tests pin grainlab's
// conventions for θσ, θ_c, θ_n, θ_t and ω (strain-rate direction 90°) to that reading of the
// paper's Fig. 3 and Eq. (8), so a negative ω in a simulation cannot be a sign slip here.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "grainlab/analysis/angles.hpp"
#include "grainlab/analysis/fabric.hpp"
#include "grainlab/analysis/stress_direction.hpp"
#include "grainlab/stress.hpp"

namespace grainlab::analysis {
namespace {

constexpr double kR = 1e-3;       // disc radius, m
constexpr double kStrain = 1e-4;  // ε22, compression positive
constexpr double kK = 1e8;        // normal spring stiffness, N/m per metre

struct Assembly {
  std::vector<Vec2> centroids;
  std::vector<unsigned char> inside;
  std::vector<ContactRecord> contacts;
};

using Stiffness = std::function<double(double thetaDeg)>;  // k(θ), θ of the normal in [0, 180)

// A round hexagonal patch turned by `turnDeg` (lattice directions turnDeg + 0, 60, 120°); the
// inside particles all keep their six neighbours, so each carries the same three directions.
// `keep` selects sites (m, n) beyond the round patch's default.
Assembly springLattice(double turnDeg, const Stiffness& kn, double kt,
                       const std::function<bool(int, int)>& keep, const std::function<bool(int, int)>& isInside) {
  Assembly a;
  std::map<std::pair<int, int>, int> index;
  const double b = radians(turnDeg);
  for (int n = -20; n <= 20; ++n)
    for (int m = -30; m <= 30; ++m) {
      if (!keep(m, n)) continue;
      const Vec2 x = rotate(Vec2(2 * kR, 0) * m + Vec2(kR, std::sqrt(3.0) * kR) * n, b);
      index[{m, n}] = static_cast<int>(a.centroids.size());
      a.centroids.push_back(x);
      a.inside.push_back(isInside(m, n) ? 1 : 0);
    }
  const std::pair<int, int> steps[] = {{1, 0}, {0, 1}, {-1, 1}};
  for (const auto& [site, i] : index)
    for (const auto& [dm, dn] : steps) {
      const auto it = index.find({site.first + dm, site.second + dn});
      if (it == index.end()) continue;
      const int j = it->second;
      const Vec2 d = a.centroids[static_cast<size_t>(j)] - a.centroids[static_cast<size_t>(i)];
      ContactRecord c;
      c.i = i;
      c.j = j;
      c.normal = d.normalized();
      c.point = a.centroids[static_cast<size_t>(i)] + kR * c.normal;
      const double th = std::atan2(c.normal.y(), c.normal.x());
      const double len = d.norm();
      // Relative displacement of j from i under u = (0, −ε y): Δd = (0, −ε d_y).
      c.fn = kn(axialDeg(degrees(th))) * kStrain * len * std::sin(th) * std::sin(th);
      c.ft = kt * kStrain * len * std::sin(th) * std::cos(th);
      a.contacts.push_back(c);
    }
  return a;
}

double radius2(int m, int n) {
  const double x = m + 0.5 * n, y = 0.5 * std::sqrt(3.0) * n;
  return x * x + y * y;
}

Assembly roundLattice(double turnDeg, const Stiffness& kn, double kt) {
  return springLattice(
      turnDeg, kn, kt, [](int m, int n) { return radius2(m, n) <= 8.0 * 8.0; },
      [](int m, int n) { return radius2(m, n) <= 6.0 * 6.0; });
}

// The major principal direction of a symmetric 2×2 matrix from its eigenvector, in [0, 180):
// independent of the atan2 formula thetaSigmaMacroDeg uses.
double majorDirectionDeg(double s11, double s12, double s22) {
  Eigen::Matrix2d m;
  m << s11, s12, s12, s22;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(m);
  const Eigen::Vector2d v = eig.eigenvectors().col(1);  // largest eigenvalue last
  return axialDeg(degrees(std::atan2(v.y(), v.x())));
}

StressTensor stressOf(const Assembly& a) { return contactStress(a.contacts, a.centroids, a.inside, 1.0); }
FabricState fabricOf(const Assembly& a) { return measureFabric(a.contacts, a.centroids, a.inside); }

TEST(StressSignConvention, IsotropicSpringsGiveCoaxialStressAndForcesAlongTheLoad) {
  // All directions equally stiff: by hand, f_n = ½kε|d|(1 − cos 2θ) = f0[1 + cos 2(θ − 90°)],
  // so a_n = 1, θ_n = 90°; f_t = ½k_t ε|d| sin 2θ = −f0 (k_t/k) sin 2(θ − 90°), so a_t = k_t/k,
  // θ_t = 90°; the hexagonal lattice is isotropic, so θσ = 90° and ω = 0.
  const double kt = 0.5 * kK;
  const Assembly a = roundLattice(20.0, [](double) { return kK; }, kt);
  const StressTensor s = stressOf(a);
  const FabricState f = fabricOf(a);
  EXPECT_GT(s.s22, 0);  // compression positive
  EXPECT_GT(s.s22, s.s11);
  EXPECT_NEAR(s.s12 + s.s21, 0.0, 1e-9 * s.p());
  EXPECT_NEAR(thetaSigmaMacroDeg(s), 90.0, 1e-6);
  EXPECT_NEAR(omegaDeg(thetaSigmaMacroDeg(s)), 0.0, 1e-6);
  EXPECT_NEAR(f.a_c, 0.0, 1e-12);
  EXPECT_NEAR(f.a_n, 1.0, 1e-9);
  EXPECT_NEAR(wrapAxialDeg(f.theta_n_deg - 90), 0.0, 1e-6);
  EXPECT_NEAR(f.a_t, kt / kK, 1e-9);
  EXPECT_NEAR(wrapAxialDeg(f.theta_t_deg - 90), 0.0, 1e-6);
}

TEST(StressSignConvention, StiffDirectionAbove90TiltsTheStressAbove90) {
  // Lattice directions 20°, 80°, 140°; the 140° contacts three times stiffer, no tangential
  // springs. By hand, per inside particle σ ∝ Σ_θ k(θ) sin²θ n⊗n, and
  // σ12 ∝ Σ k sin³θ cosθ = k(0.0376 + 0.1665 − 3 × 0.2032) < 0: the major axis leans from
  // 90° toward 140°, so θσ ∈ (90°, 140°) and ω > 0. θ_n leans the same way.
  const Stiffness stiff140 = [](double th) { return std::abs(th - 140.0) < 1.0 ? 3 * kK : kK; };
  const Assembly a = roundLattice(20.0, stiff140, 0.0);
  const StressTensor s = stressOf(a);
  EXPECT_LT(s.s12, 0);
  EXPECT_LT(s.s21, 0);
  const double theta = thetaSigmaMacroDeg(s);
  EXPECT_GT(theta, 90.0);
  EXPECT_LT(theta, 140.0);
  EXPECT_GT(omegaDeg(theta), 0.0);

  // The hand sum over one inside particle's six ends (l = R n, both ends of each direction).
  double h11 = 0, h12 = 0, h22 = 0;
  for (double deg : {20.0, 80.0, 140.0}) {
    const double th = radians(deg), w = stiff140(deg) * kStrain * 2 * kR * std::pow(std::sin(th), 2);
    h11 += w * std::cos(th) * std::cos(th);
    h12 += w * std::cos(th) * std::sin(th);
    h22 += w * std::sin(th) * std::sin(th);
  }
  EXPECT_NEAR(theta, majorDirectionDeg(h11, h12, h22), 1e-9);
  EXPECT_NEAR(theta, majorDirectionDeg(s.s11, 0.5 * (s.s12 + s.s21), s.s22), 1e-9);

  // θ_n by hand: three directions equally spaced on 2θ fix f0 and A_n exactly.
  std::complex<double> m2 = 0;
  double m0 = 0;
  for (double deg : {20.0, 80.0, 140.0}) {
    const double th = radians(deg), fn = stiff140(deg) * std::pow(std::sin(th), 2);
    m0 += fn / 3;
    m2 += fn / 3 * std::polar(1.0, 2 * th);
  }
  const std::complex<double> an = 2.0 * m2 / m0;
  const FabricState f = fabricOf(a);
  EXPECT_NEAR(f.a_n, std::abs(an), 1e-9);
  EXPECT_NEAR(wrapAxialDeg(f.theta_n_deg - axialDeg(degrees(0.5 * std::arg(an)))), 0.0, 1e-6);
  EXPECT_GT(f.theta_n_deg, 90.0);
  EXPECT_LT(f.theta_n_deg, 180.0);
}

TEST(StressSignConvention, FabricAt90PlusAlphaTiltsTheStressTowardIt) {
  // The bedding reading: contact normals favouring 90° + α (α = 30°), equal springs. A strip of
  // five rows along 120° has its 120° contacts complete and the 0° and 60° ones cut at its
  // edges; loaded along 2 from a stress-free state, the 0° contacts carry nothing (sin²0 = 0)
  // and the extra 120° contacts outweigh the 60° ones: σ12 ∝ N_120·(−0.433) + N_60·0.433 < 0,
  // so θσ lies between 90° and θ_c = 120°: ω > 0, the sign a natural reading of the paper expects.
  const Assembly a = springLattice(
      120.0, [](double) { return kK; }, 0.0, [](int m, int n) { return std::abs(n) <= 2 && std::abs(2 * m + n) <= 24; },
      [](int, int) { return true; });
  const FabricState f = fabricOf(a);
  EXPECT_GT(f.a_c, 0.05);
  EXPECT_NEAR(wrapAxialDeg(f.theta_c_deg - 120.0), 0.0, 1e-9);
  const StressTensor s = stressOf(a);
  EXPECT_LT(s.s12 + s.s21, 0);
  const double theta = thetaSigmaMacroDeg(s);
  EXPECT_GT(theta, 90.0);
  EXPECT_LT(theta, 120.0);
  EXPECT_GT(omegaDeg(theta), 0.0);
  // Mirrored (α = −30°, θ_c = 60°): the tilt changes sign with the fabric.
  const Assembly mirror = springLattice(
      60.0, [](double) { return kK; }, 0.0, [](int m, int n) { return std::abs(n) <= 2 && std::abs(2 * m + n) <= 24; },
      [](int, int) { return true; });
  EXPECT_NEAR(omegaDeg(thetaSigmaMacroDeg(stressOf(mirror))), -omegaDeg(theta), 1e-9);
}

}  // namespace
}  // namespace grainlab::analysis

// Love's stress in a periodic cell against the closed-form elasticity of a hexagonal lattice.
//
// Equal discs of radius r on a hexagonal lattice of spacing d0 = 2r − δ0 (every neighbour
// overlaps by δ0), filling a periodic cell, deformed by a constant symmetric L for a time T
// (small strain E = L T). Each disc is a centre of symmetry of a Bravais lattice, so the forces
// on it cancel and the lattice deforms affinely: the fluctuations stay zero. For a pure strain
// the three bond directions θ = 0°, 60°, 120° also cancel each other's torques
// (Σ t·E n = ½(E22 − E11) Σ sin 2θ + E12 Σ cos 2θ = 0), so the discs do not spin.
//
// Per bond (direction n, tangent t = n turned +90°): Δf_n = −k_n d0 (n·E n) (a stretch relieves
// the overlap) and Δf_t = −k_t d0 (t·E n) (the Cundall-Strack spring, no slip, no dashpot at
// restitution 1). Love's formula, each contact once with its branch d0 n to the neighbour (or
// its image across an edge), over the area per disc A_p = (√3/2) d0²:
//   Δσ = (3 d0²/A_p) [k_n ⟨n⊗n (n·E n)⟩ + k_t ⟨t⊗n (t·E n)⟩] · (−1)
// and over three directions 60° apart ⟨n⊗n (n·E n)⟩ = (tr E I + 2E)/8, ⟨t⊗n (t·E n)⟩ = dev E/4
// (dev E = E − ½ tr E I), so (compression positive, hence the sign)
//   Δσ = −(√3/4) [(k_n − k_t) tr E I + 2 (k_n + k_t) E],
// Lamé constants λ = (√3/4)(k_n − k_t), μ = (√3/4)(k_n + k_t) (Cauchy's λ = μ when k_t = 0).
//
// Two checks: the same sums over the three bonds with the exact deformed geometry (x = F X,
// normal forces from the exact lengths; only the tangential springs are linearised, an error of
// relative order |E| = 1e-4), to 1e-3 of |Δσ|; and the Lamé form, which also drops the prestress
// carried through the deformation (relative order (δ0/d0)/|E|·|E| = δ0/d0 = 1e-3 of σ0 against
// Δσ ~ k|E|: about 0.5 % here), to 2 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Dense>

#include "grainlab/periodic_cell.hpp"
#include "grainlab/stress.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

using Mat2 = Eigen::Matrix2d;

Mat2 asMatrix(const StressTensor& s) {
  Mat2 m;
  m << s.s11, s.s12, s.s21, s.s22;
  return m;
}

struct Lattice {
  double r = 0.001, delta0 = 2e-6;
  double d0() const { return 2 * r - delta0; }
  int columns = 6, rows = 6;  // rows even: the cell tiles the lattice
  Mat2 cell() const {
    Mat2 h;
    h << columns * d0(), 0, 0, rows * std::sqrt(3.0) / 2 * d0();
    return h;
  }
};

// Stress of the hexagonal lattice after the affine deformation F, with tangential spring
// elongations linearised: u = d0 t0·E n0 for each bond of undeformed direction n0.
Mat2 latticeStress(const Lattice& lat, const Mat2& F, const Mat2& E, double kn, double kt) {
  const double d0 = lat.d0();
  const double area = std::sqrt(3.0) / 2 * d0 * d0 * F.determinant();
  Mat2 s = Mat2::Zero();
  for (double deg : {0.0, 60.0, 120.0}) {
    const Vec2 n0(std::cos(radians(deg)), std::sin(radians(deg)));
    const Vec2 t0 = perp(n0);
    const Vec2 d = F * (d0 * n0);
    const Vec2 n = d.normalized(), t = perp(n);
    const double fn = kn * (2 * lat.r - d.norm());
    const double ft = -kt * d0 * t0.dot(E * n0);
    s += d.norm() * (fn * n * n.transpose() + ft * t * n.transpose());
  }
  return s / area;
}

// Δσ = −(λ tr E I + 2 μ E) for the symmetric part of E.
Mat2 lameForm(const Mat2& E, const Material& m) {
  const double Es = 0.5 * (E(0, 1) + E(1, 0));
  Mat2 Esym;
  Esym << E(0, 0), Es, Es, E(1, 1);
  const double lambda = std::sqrt(3.0) / 4 * (m.normalStiffness - m.tangentialStiffness);
  const double mu = std::sqrt(3.0) / 4 * (m.normalStiffness + m.tangentialStiffness);
  return -(lambda * Esym.trace() * Mat2::Identity() + 2 * mu * Esym);
}

TEST(PeriodicLatticeStress, HexagonalLatticeUnderPureStrainGivesTheClosedFormElasticStress) {
  const Lattice lat;
  Material m;
  m.normalStiffness = 1e7;
  m.tangentialStiffness = 4e6;
  m.friction = 0.5;      // never reached: |f_t|/f_n ≈ k_t d0 |E| / (k_n δ0) ≈ 0.04
  m.restitution = 1;     // no dashpots: the stress is the springs' alone
  m.localDamping = 0;
  World world(m);
  world.setPeriodicCell(lat.cell());
  const double d0 = lat.d0(), rowHeight = std::sqrt(3.0) / 2 * d0;
  for (int j = 0; j < lat.rows; ++j) {
    for (int i = 0; i < lat.columns; ++i) {
      ParticleSpec p;
      p.radius = lat.r;
      p.position = {(i + 0.5 * (j % 2) + 0.25) * d0, (j + 0.5) * rowHeight};
      world.addParticle(p);
    }
  }
  world.initialize();
  const int steps = 2000;
  const double T = steps * world.timestep();
  Mat2 D;
  D << 1.0, 0.4, 0.4, -0.6;  // a pure strain with a volume change and a shear
  D *= 1e-4 / T;             // |E| about 1e-4: the elastic range
  world.setCellVelocityGradient(D);

  std::vector<ContactRecord> contacts;
  const std::vector<unsigned char> inside(static_cast<size_t>(world.size()), 1);
  world.contacts(contacts);
  ASSERT_EQ(contacts.size(), 3u * world.size()) << "every disc touches six neighbours";
  const PeriodicCell& cell = *world.periodicCell();
  const Mat2 before = asMatrix(contactStress(contacts, world.positions(), inside, cell.area(), &cell));
  for (int s = 0; s < steps; ++s) world.step();
  world.contacts(contacts);
  ASSERT_EQ(contacts.size(), 3u * world.size());
  int across = 0;
  for (const ContactRecord& c : contacts) across += (world.positions()[c.j] - world.positions()[c.i]).norm() > 3 * lat.r;
  ASSERT_GT(across, 10) << "some contacts must cross the cell's edges";
  const Mat2 after = asMatrix(contactStress(contacts, world.positions(), inside, cell.area(), &cell));

  const Mat2& F = cell.deformation();
  const Mat2 E = F - Mat2::Identity();  // = L T to first order; F is what the particles followed
  const Mat2 change = after - before;
  const double scale = change.norm();
  ASSERT_GT(scale, 0);
  // Exact geometry.
  const Mat2 expected = latticeStress(lat, F, E, m.normalStiffness, m.tangentialStiffness) -
                        latticeStress(lat, Mat2::Identity(), Mat2::Zero(), m.normalStiffness, m.tangentialStiffness);
  std::printf("hexagonal lattice: |dsigma| = %.6g Pa, off the exact-geometry form by %.3g, off Lame's by %.3g (relative)\n",
              scale, (change - expected).norm() / scale, (change - lameForm(E, m)).norm() / scale);
  EXPECT_LT((change - expected).norm(), 1e-3 * scale) << "measured\n" << change << "\nexpected\n" << expected;
  // The prestress itself: σ0 = √3 k_n δ0 / d0 · I (three bonds of force k_n δ0 and length d0 over A_p).
  const double p0 = std::sqrt(3.0) * m.normalStiffness * lat.delta0 / d0;
  EXPECT_NEAR(before(0, 0), p0, 1e-9 * p0);
  EXPECT_NEAR(before(1, 1), p0, 1e-9 * p0);
  EXPECT_NEAR(before(0, 1), 0, 1e-9 * p0);
  // Lamé's form.
  const Mat2 lame = lameForm(E, m);
  EXPECT_LT((change - lame).norm(), 0.02 * scale) << "measured\n" << change << "\nLamé\n" << lame;
  // Fluctuations and spins stay at rounding level: the lattice deformed affinely. A lattice
  // that did not would show fluctuations of the order of the neighbours' affine relative
  // velocity |D| d0 and spins of the order of |D|; the forces on a disc cancel to ~1e-15 of
  // their size, which leaves about 1e-7 of those after 2000 steps.
  for (int k = 0; k < world.size(); ++k) {
    EXPECT_LT(world.velocities()[k].norm(), 1e-5 * D.norm() * d0) << k;
    EXPECT_LT(std::abs(world.spins()[k]), 1e-5 * D.norm()) << k;
  }
}

// The same lattice measured without the cell (branch vectors not taken to the image): the
// contacts across an edge then count with a branch of a cell's length, and the stress is far
// off. Shows that the image matters, i.e. that the check above can fail.
TEST(PeriodicLatticeStress, WithoutTheImageTheBranchVectorsAcrossAnEdgeAreWrong) {
  const Lattice lat;
  Material m;
  m.restitution = 1;
  World world(m);
  world.setPeriodicCell(lat.cell());
  const double d0 = lat.d0(), rowHeight = std::sqrt(3.0) / 2 * d0;
  for (int j = 0; j < lat.rows; ++j) {
    for (int i = 0; i < lat.columns; ++i) {
      ParticleSpec p;
      p.radius = lat.r;
      p.position = {(i + 0.5 * (j % 2) + 0.25) * d0, (j + 0.5) * rowHeight};
      world.addParticle(p);
    }
  }
  world.initialize();
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  const std::vector<unsigned char> inside(static_cast<size_t>(world.size()), 1);
  const PeriodicCell& cell = *world.periodicCell();
  const double p0 = std::sqrt(3.0) * m.normalStiffness * lat.delta0 / d0;
  const StressTensor with = contactStress(contacts, world.positions(), inside, cell.area(), &cell);
  const StressTensor without = contactStress(contacts, world.positions(), inside, cell.area());
  EXPECT_NEAR(with.s11, p0, 1e-9 * p0);
  EXPECT_GT(std::abs(without.s11 - p0), 0.5 * p0);
}

}  // namespace
}  // namespace grainlab

// The periodic cell's kinematics: particles move with the cell's affine field L x plus their
// fluctuation velocity, and the cell's edges follow ḣ = L h by the same step map. A gas with no
// contacts and no fluctuations must therefore stay on x = F X (modulo the cell's images) with
// its fluctuations exactly zero, whatever L, also when the cell is remapped on the way; and a
// dense packing in the cell steps to the same bits on one thread or three.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include <Eigen/Dense>

#include "grainlab/periodic_cell.hpp"
#include "world_helpers.hpp"

namespace grainlab {
namespace {

using Mat2 = Eigen::Matrix2d;
using test::disc;

Mat2 matrix(double a, double b, double c, double d) {
  Mat2 m;
  m << a, b, c, d;
  return m;
}

TEST(PeriodicKinematics, AnAffinelyDeformedGasStaysOnXEqualsFXWithZeroFluctuations) {
  const Mat2 h0 = matrix(0.05, 0.01, 0, 0.04);
  // Stretch, shear and spin at once; over 0.25 s the cell shears by more than half an edge
  // and is remapped.
  const Mat2 L = matrix(0.8, 4.0, -0.5, -0.6);
  World world(test::material(1e6, 0.5, 0.5));
  world.setPeriodicCell(h0);
  std::vector<Vec2> reference;
  for (int a = 0; a < 6; ++a) {
    for (int b = 0; b < 5; ++b) {
      // Spread over the cell and beyond it (wrapped at the first build); never closer than
      // 5 mm, against radii of 0.5 mm: no contact as the cell deforms by up to ~2x.
      const Vec2 X = h0 * Vec2((a + 0.3) / 6.0, (b + 0.6) / 5.0) + (a == 5 ? Vec2(h0.col(1)) : Vec2::Zero());
      world.addParticle(disc(0.0005, X));
      reference.push_back(X);
    }
  }
  world.setCellVelocityGradient(L);
  world.setTimestep(1e-5);
  world.initialize();
  const PeriodicCell& cell = *world.periodicCell();
  const Mat2 tiltBefore = cell.edges();
  bool remapped = false;
  std::vector<ContactRecord> contacts;
  for (int s = 0; s < 25000; ++s) {
    world.step();
    remapped = remapped || cell.edges().col(1).isApprox(cell.deformation() * h0.col(1), 1e-9) == false;
    if (s % 5000 == 4999) {
      world.contacts(contacts);
      ASSERT_TRUE(contacts.empty()) << "the gas touched: the test no longer tests an affine motion";
    }
  }
  EXPECT_TRUE(remapped) << "the cell was never remapped (" << tiltBefore << ")";
  const Mat2& F = cell.deformation();
  ASSERT_GT((F - Mat2::Identity()).norm(), 0.5) << "too little deformation to tell";
  for (int k = 0; k < world.size(); ++k) {
    // Fluctuations: no force ever acted, so they are zero to the bit.
    EXPECT_EQ(world.velocities()[k], Vec2::Zero()) << k;
    EXPECT_EQ(world.spins()[k], 0.0) << k;
    // Positions: F X up to a whole image, to rounding (relative 1e-12 of the cell's size).
    const Vec2 off = cell.minimumImage(world.positions()[k] - F * reference[k]);
    EXPECT_LT(off.norm(), 1e-12 * cell.edges().norm()) << k;
    // And inside the cell, up to what the particle has drifted since the last wrap.
    const Vec2 s = cell.fractional(world.positions()[k]);
    EXPECT_GT(s.minCoeff(), -0.2);
    EXPECT_LT(s.maxCoeff(), 1.2);
  }
  // The edges span the same lattice as F h0: h = F h0 M with M whole and det M = 1.
  const Mat2 M = (F * h0).inverse() * cell.edges();
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(M(k), std::round(M(k)), 1e-9);
  EXPECT_NEAR(cell.area(), (F * h0).determinant(), 1e-12 * cell.area());
  EXPECT_EQ(world.kineticEnergy(), 0.0);
}

// A jammed packing (discs, or boxes) in a cell under shear: the same bits on 1, 2 and 3 threads
// (the slots that keep the parallel sums in order work on image pairs as on any other).
std::vector<Vec2> shearedPacking(int threads, bool polygons = false) {
  WorldSettings settings;
  settings.threads = threads;
  World world(test::material(1e6, 0.5, 0.5), settings);
  const int n = 12;
  const double r = 0.002, spacing = 2 * r * 0.92;  // denser than hexagonal: jammed
  world.setPeriodicCell(matrix(n * spacing, 0, 0, n * spacing));
  std::uint64_t state = 11;
  auto uniform = [&] {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53 - 0.5;
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double size = r * (1 + 0.04 * uniform());
      const Vec2 x(i * spacing, j * spacing), v(0.05 * uniform(), 0.05 * uniform());
      if (!polygons) {
        world.addParticle(disc(size, x, v));
      } else {
        ParticleSpec box = test::box(1.95 * size, 1.85 * size, x, 0.1 * uniform());
        box.velocity = v;
        world.addParticle(box);
      }
    }
  }
  world.setCellVelocityGradient(matrix(0, 2.0, 0, 0));
  world.initialize();
  for (int s = 0; s < 3000; ++s) world.step();
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  EXPECT_GT(contacts.size(), 100u) << "a packing, not a gas";
  std::vector<Vec2> out(world.positions().begin(), world.positions().end());
  out.insert(out.end(), world.velocities().begin(), world.velocities().end());
  return out;
}

TEST(PeriodicKinematics, SameBitsOnOneTwoAndThreeThreads) {
  for (const bool polygons : {false, true}) {
    SCOPED_TRACE(polygons ? "polygons" : "discs");
    const std::vector<Vec2> one = shearedPacking(1, polygons);
    for (int threads : {2, 3}) {
      const std::vector<Vec2> other = shearedPacking(threads, polygons);
      ASSERT_EQ(one.size(), other.size());
      EXPECT_EQ(std::memcmp(one.data(), other.data(), one.size() * sizeof(Vec2)), 0) << threads << " threads";
    }
  }
}

// Sheared far (γ = 3: the cell is remapped three times), a dense packing keeps every contact
// in the neighbour list: at regular steps the touching pairs the world reports are exactly
// those a brute-force search over all pairs and their nearest images finds.
TEST(PeriodicKinematics, AFarShearedPackingMissesNoContactThroughRemaps) {
  World world(test::material(1e6, 0.5, 0.5));
  const int n = 12;
  const double r = 0.002, spacing = 2 * r * 0.97;
  world.setPeriodicCell(matrix(n * spacing, 0, 0, n * spacing));
  std::uint64_t state = 23;
  auto uniform = [&] {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53 - 0.5;
  };
  std::vector<double> radius;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      radius.push_back(r * (1 + 0.02 * uniform()));
      world.addParticle(disc(radius.back(), {i * spacing, j * spacing}));
    }
  }
  const double rate = 20;  // 1/s
  world.setCellVelocityGradient(matrix(0, rate, 0, 0));
  world.initialize();
  const int steps = static_cast<int>(3.0 / rate / world.timestep());
  int remaps = 0, checks = 0;
  double tilt = 0;
  std::vector<ContactRecord> contacts;
  for (int s = 1; s <= steps; ++s) {
    world.step();
    const PeriodicCell& cell = *world.periodicCell();
    const double now = cell.edges()(0, 1) / cell.edges()(0, 0);
    remaps += now < tilt - 0.5;  // the tilt jumps back by a whole edge at a remap
    tilt = now;
    if (s % 100 != 0) continue;
    world.contacts(contacts);
    std::vector<std::pair<int, int>> reported, found;
    for (const ContactRecord& c : contacts) reported.emplace_back(c.i, c.j);
    const auto x = world.positions();
    for (int i = 0; i < world.size(); ++i) {
      for (int j = i + 1; j < world.size(); ++j) {
        if (cell.minimumImage(x[j] - x[i]).norm() < radius[i] + radius[j]) found.emplace_back(i, j);
      }
    }
    ASSERT_GT(found.size(), 50u) << "too few contacts to test anything";
    EXPECT_EQ(reported, found) << "step " << s;
    ++checks;
  }
  EXPECT_GE(remaps, 3);
  EXPECT_GT(checks, 20);
}

}  // namespace
}  // namespace grainlab

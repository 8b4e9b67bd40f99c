// The wide contact path in a periodic cell: each slot meets j's image x_j + h n and adds the
// image's affine velocity L (x_j + h n − x_i) to the relative velocity, as the baseline's
// periodic loop does. It must give the baseline's forces to rounding, the same bits with any
// number of threads, and the same bits after a resume: each on every instruction set this build
// compiled, forced in turn (vectors of 1 to 8 doubles).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "grainlab/periodic_cell.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/state_archive.hpp"
#include "wide_path_support.hpp"
#include "world_helpers.hpp"

namespace grainlab {
namespace {

using Mat2 = Eigen::Matrix2d;

constexpr double kEpsilon = 0x1p-52;  // one unit in the last place at 1

// n × n polydisperse discs (radii 0.9-1.1 mm) on a shuffled square lattice 1.94 mm apart in a
// square cell tilted by `tilt` edges: every neighbour overlaps, many of them across the edges,
// and the discs move with seeded random fluctuations while the cell shears at 20 /s and
// shortens along 2 at 5 /s.
struct CellPacking {
  Material material;
  std::vector<ParticleSpec> particles;
  Mat2 h, L;
  double largestRadius = 0;
};

CellPacking cellPacking(int n, double tilt) {
  CellPacking c;
  c.material = test::material(1e8, 0.5, 0.5);
  c.material.localDamping = 0.1;
  const double spacing = 0.00194, edge = n * spacing;
  c.h << edge, tilt * edge, 0, edge;
  c.L << 0, 20, 0, -5;
  std::uint64_t state = 11;
  auto uniform = [&] {  // splitmix64: the same numbers with any standard library
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53 - 0.5;
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double r = 0.001 * (1 + 0.2 * uniform());
      c.largestRadius = std::max(c.largestRadius, r);
      // Lattice rows follow the cell's tilt, so the packing is as dense across the edges.
      const Vec2 x = c.h * Vec2((i + 0.5) / n, (j + 0.5) / n);
      c.particles.push_back(test::disc(r, x, {0.05 * uniform(), 0.05 * uniform()}, 20 * uniform()));
    }
  }
  std::mt19937_64 rng(7);  // indices that do not follow space: threads share particles
  std::shuffle(c.particles.begin(), c.particles.end(), rng);
  return c;
}

CellPacking rollingPacking(int n, double tilt) {
  CellPacking c = cellPacking(n, tilt);
  c.material.rollingFriction = 0.1;
  c.material.rollingDamping = 0.3;
  return c;
}

std::unique_ptr<World> makeWorld(const CellPacking& c, int threads) {
  WorldSettings settings;
  settings.threads = threads;
  auto w = std::make_unique<World>(c.material, settings);
  w->setPeriodicCell(c.h);
  for (const ParticleSpec& p : c.particles) w->addParticle(p);
  w->setCellVelocityGradient(c.L);
  w->initialize();
  return w;
}

// The bits of every position, velocity, spin, force, torque, contact and the cell's edges.
std::uint64_t hashOf(const World& w) {
  std::uint64_t hash = 1469598103934665603ull;
  auto mix = [&](const double* v, int n) {
    for (int k = 0; k < n; ++k) {
      std::uint64_t bits;
      std::memcpy(&bits, v + k, sizeof bits);
      hash = (hash ^ bits) * 1099511628211ull;
    }
  };
  for (const Vec2& x : w.positions()) mix(x.data(), 2);
  for (const Vec2& v : w.velocities()) mix(v.data(), 2);
  for (const Vec2& f : w.forces()) mix(f.data(), 2);
  for (double s : w.spins()) mix(&s, 1);
  for (double t : w.torques()) mix(&t, 1);
  std::vector<ContactRecord> contacts;
  w.contacts(contacts);
  for (const ContactRecord& c : contacts) {
    const double values[] = {c.fn, c.ft, c.overlap, c.point.x(), c.point.y()};
    mix(values, 5);
  }
  mix(w.periodicCell()->edges().data(), 4);
  return hash;
}

class WidePeriodic : public ::testing::Test {
 protected:
  void SetUp() override {
    overrideSimdPath(SimdPath::Wide);
    const bool built = simdPath() == SimdPath::Wide;
    if (!built) {
      overrideSimdPath(std::nullopt);
      GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
    }
  }
  void TearDown() override { overrideSimdPath(std::nullopt); }
};

// Two worlds step the packing in lockstep on the baseline (the same bits), then take one step
// each, one on the wide path; the largest gaps between their particles' forces and torques,
// the largest of each on the baseline, the gap between their springs' stored energies, and the
// baseline's contacts (how many cross an edge, the largest force).
struct ForceGaps {
  double force = 0, torque = 0, largestForce = 0, largestTorque = 0;
  double energy = 0, largestContactForce = 0;
  size_t contacts = 0, acrossEdges = 0;
};
ForceGaps oneWideStep(const CellPacking& c, int threads, int steps) {
  overrideSimdPath(SimdPath::Baseline);
  const std::unique_ptr<World> baseline = makeWorld(c, threads), wide = makeWorld(c, threads);
  for (int k = 0; k < steps; ++k) {
    baseline->step();
    wide->step();
  }
  baseline->step();
  overrideSimdPath(SimdPath::Wide);
  wide->step();
  ForceGaps g;
  for (int p = 0; p < baseline->size(); ++p) {
    g.force = std::max(g.force, (wide->forces()[p] - baseline->forces()[p]).norm());
    g.torque = std::max(g.torque, std::abs(wide->torques()[p] - baseline->torques()[p]));
    g.largestForce = std::max(g.largestForce, baseline->forces()[p].norm());
    g.largestTorque = std::max(g.largestTorque, std::abs(baseline->torques()[p]));
  }
  g.energy = std::abs(wide->elasticEnergy() - baseline->elasticEnergy());
  std::vector<ContactRecord> contacts;
  baseline->contacts(contacts);
  g.contacts = contacts.size();
  const auto x = baseline->positions();
  for (const ContactRecord& r : contacts) {
    g.largestContactForce = std::max(g.largestContactForce, std::hypot(r.fn, r.ft));
    // Centres farther apart than any reach: the pair touches through an image.
    if ((x[r.j] - x[r.i]).norm() > 4 * c.largestRadius) ++g.acrossEdges;
  }
  return g;
}

// The bound. In the ring, 64 k_n ε 2r bounds a particle's force gap (wide_path_test.cpp: a few
// units in the last place of |d| ≈ 2r move each normal force by k_n ε 2r, a particle sums a
// few neighbours). In the cell the separation is d = (x_j + h n) − x_i, formed from positions
// as large as the image's, |x_j + h n| ≤ X = 2 (|h₁| + |h₂|) (positions are wrapped into the
// cell, an image is at most one edge of each beyond it): the shift h n, its sum with x_j and
// the difference each round at ε X, differently on the two paths (fused or not), so the gap
// in |d| grows by a few ε X and the bound becomes 64 k_n ε (2r + X). The image's affine
// velocity L d adds rounding of ε |L| X to the relative velocity, which moves a force by
// c ε |L| X, c ≤ 2 √(m k_n) the dashpot: below k_n ε X by the factor 2 |L| √(m / k_n)
// (about 1e-4 here). The stored energies as in wide_path_test.cpp. A term missing or of the
// wrong sign is far above: without the image's affine velocity, the dashpot alone misses
// c |L d| ≈ 250 N·s/m × 20 /s × 2 mm ≈ 10 N per contact, against a bound of about 2e-7 N.
double forceBound(const CellPacking& c) {
  const double X = 2 * (c.h.col(0).norm() + c.h.col(1).norm());
  return 64 * c.material.normalStiffness * kEpsilon * (2 * c.largestRadius + X);
}

double energyBound(const ForceGaps& g, const Material& m, double forceBound) {
  const double rolling = m.rollingFriction * m.rollingFriction / m.rollingStiffnessRatio;
  return static_cast<double>(g.contacts) * g.largestContactForce * forceBound *
         (1 / m.normalStiffness + (1 + rolling) / m.tangentialStiffness);
}

TEST_F(WidePeriodic, GivesTheBaselinesForcesToRounding) {
  test::onEveryWideTarget([&](const std::string& target) {
    SCOPED_TRACE(target);
    for (const bool rolling : {false, true}) {
      for (int threads : {1, 2}) {
        SCOPED_TRACE(testing::Message() << threads << " threads" << (rolling ? ", rolling" : ""));
        const CellPacking c = rolling ? rollingPacking(12, 0.2) : cellPacking(12, 0.2);
        const ForceGaps g = oneWideStep(c, threads, 1500);
        const double fBound = forceBound(c);
        const double tBound = (1 + c.material.rollingFriction) * fBound * c.largestRadius;
        std::printf("force gap %.3g N (bound %.3g, largest %.3g), torque gap %.3g N·m (bound %.3g), energy gap %.3g J "
                    "(bound %.3g), %zu contacts of which %zu across an edge\n",
                    g.force, fBound, g.largestForce, g.torque, tBound, g.energy, energyBound(g, c.material, fBound),
                    g.contacts, g.acrossEdges);
        EXPECT_GT(g.force, 0) << "the wide path was not taken: its rounding differs from the baseline's";
        EXPECT_GT(g.acrossEdges, 10u) << "contacts must cross the cell's edges";
        EXPECT_GT(g.largestForce, 1e6 * fBound) << "the packing is pressed: its forces are far above the bound";
        EXPECT_GT(g.largestTorque, 1e3 * tBound) << "the contacts turn the discs";
        EXPECT_LE(g.force, fBound);
        EXPECT_LE(g.torque, tBound);
        EXPECT_LE(g.energy, energyBound(g, c.material, fBound));
      }
    }
  });
}

// A run of 3000 steps: the list rebuilt as the cell shears, and the cell, tilted by 0.49 edge
// at the start, remapped (LAMMPS's flip) on the way. Threads share particles (shuffled).
TEST_F(WidePeriodic, GivesTheSameBitsWithAnyThreadCount) {
  test::onEveryWideTarget([&](const std::string& target) {
    SCOPED_TRACE(target);
    enum class Law { Friction, Frictionless, Rolling };
    for (const Law law : {Law::Friction, Law::Frictionless, Law::Rolling}) {
      CellPacking c = law == Law::Rolling ? rollingPacking(12, 0.49) : cellPacking(12, 0.49);
      if (law == Law::Frictionless) c.material.friction = 0;
      auto run = [&](int threads) {
        const std::unique_ptr<World> w = makeWorld(c, threads);
        for (int k = 0; k < 3000; ++k) w->step();
        return std::make_pair(hashOf(*w), w->periodicCell()->edges()(0, 1) / w->periodicCell()->edges()(0, 0));
      };
      const auto [serial, tilt] = run(1);
      EXPECT_LT(tilt, 0.45) << "the cell was not remapped";
      EXPECT_EQ(serial, run(1).first) << "a second serial run";
      EXPECT_EQ(serial, run(2).first) << "2 threads";
      EXPECT_EQ(serial, run(3).first) << "3 threads";
    }
  });
}

// Saved mid-run (the wide path's pair state in its own arrays, handed back to the list),
// loaded into a world built from the same packing, the run continues to the same bits.
TEST_F(WidePeriodic, AResumedRunContinuesToTheSameBits) {
  test::onEveryWideTarget([&](const std::string& target) {
    SCOPED_TRACE(target);
    for (const bool rolling : {false, true}) {
      for (int threads : {1, 2}) {
        SCOPED_TRACE(testing::Message() << threads << " threads" << (rolling ? ", rolling" : ""));
        const CellPacking c = rolling ? rollingPacking(12, 0.49) : cellPacking(12, 0.49);
        const std::unique_ptr<World> straight = makeWorld(c, threads);
        for (int k = 0; k < 1500; ++k) straight->step();
        StateArchive saved;
        straight->persist(saved);
        for (int k = 0; k < 1500; ++k) straight->step();
        std::vector<ContactRecord> contacts;
        straight->contacts(contacts);
        ASSERT_GT(contacts.size(), 200u) << "the packing must be in contact";
        const std::unique_ptr<World> resumed = makeWorld(c, threads);
        StateArchive load(saved.bytes());
        resumed->persist(load);
        for (int k = 0; k < 1500; ++k) resumed->step();
        EXPECT_EQ(hashOf(*straight), hashOf(*resumed));
      }
    }
  });
}

}  // namespace
}  // namespace grainlab

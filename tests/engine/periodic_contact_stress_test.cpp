// World::contactStress sums the contact stress straight from the solver's pair state (what the
// cell's servo measures every few steps). It must be grainlab::contactStress over
// World::contacts() to the bit: the same terms in the same order, on either contact path,
// with any number of threads, in a tilted shearing cell (contacts across its edges, branch
// vectors that need their nearest image), with polygons, and in a box with walls. With polygons
// in a box, the wide path reads the contacts its force pass kept instead of measuring them again:
// the same bits at every step, and right after a checkpoint is loaded (nothing kept yet).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <vector>

#include "grainlab/periodic_cell.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/state_archive.hpp"
#include "grainlab/stress.hpp"
#include "world_helpers.hpp"

namespace grainlab {
namespace {

std::uint64_t bitsOf(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

void expectSameBits(const StressTensor& a, const StressTensor& b) {
  EXPECT_EQ(bitsOf(a.s11), bitsOf(b.s11)) << a.s11 << " against " << b.s11;
  EXPECT_EQ(bitsOf(a.s12), bitsOf(b.s12)) << a.s12 << " against " << b.s12;
  EXPECT_EQ(bitsOf(a.s21), bitsOf(b.s21)) << a.s21 << " against " << b.s21;
  EXPECT_EQ(bitsOf(a.s22), bitsOf(b.s22)) << a.s22 << " against " << b.s22;
}

double uniform(std::uint64_t& state) {  // splitmix64 in [-0.5, 0.5): the same with any library
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53 - 0.5;
}

// n × n discs (radii 0.9-1.1 mm) 1.94 mm apart in a cell tilted by 0.3 of an edge, shearing
// at 20 /s and shortening at 5 /s, with seeded random velocities; every `polygonEvery`-th
// particle a 1.8 mm square instead (0: discs only).
std::unique_ptr<World> shearingCell(int n, int threads, int polygonEvery) {
  WorldSettings settings;
  settings.threads = threads;
  Material m = test::material(1e8, 0.5, 0.5);
  m.localDamping = 0.1;
  auto w = std::make_unique<World>(m, settings);
  const double edge = n * 0.00194;
  Eigen::Matrix2d h, L;
  h << edge, 0.3 * edge, 0, edge;
  L << 0, 20, 0, -5;
  w->setPeriodicCell(h);
  std::uint64_t state = 5;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Vec2 x = h * Vec2((i + 0.5) / n, (j + 0.5) / n);
      const int k = i * n + j;
      ParticleSpec p = polygonEvery > 0 && k % polygonEvery == 0 ? test::box(0.0018, 0.0018, x, uniform(state))
                                                                 : test::disc(0.001 * (1 + 0.2 * uniform(state)), x);
      p.velocity = {0.05 * uniform(state), 0.05 * uniform(state)};
      w->addParticle(p);
    }
  }
  w->setCellVelocityGradient(L);
  w->initialize();
  return w;
}

// Every third particle outside the specimen: both ends' flags are read.
std::vector<unsigned char> someInside(int n) {
  std::vector<unsigned char> inside(static_cast<size_t>(n), 1);
  for (size_t k = 0; k < inside.size(); k += 3) inside[k] = 0;
  return inside;
}

StressTensor throughRecords(const World& w, const std::vector<unsigned char>& inside, double area) {
  std::vector<ContactRecord> contacts;
  w.contacts(contacts);
  return contactStress(contacts, w.positions(), inside, area, w.periodicCell());
}

// How many touching contacts have a branch (from a centroid to the contact point) that is not
// its own nearest image: the contact meets j's image across an edge.
int acrossEdges(const World& w) {
  std::vector<ContactRecord> contacts;
  w.contacts(contacts);
  int across = 0;
  for (const ContactRecord& c : contacts) {
    const Vec2 branch = c.point - w.positions()[static_cast<size_t>(c.j)];
    if (!(w.periodicCell()->nearestImage(branch) == ImageShift{})) ++across;
  }
  return across;
}

class PeriodicContactStress : public ::testing::TestWithParam<SimdPath> {
 protected:
  void SetUp() override {
    overrideSimdPath(GetParam());
    if (simdPath() != GetParam()) {
      overrideSimdPath(std::nullopt);
      GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
    }
  }
  void TearDown() override { overrideSimdPath(std::nullopt); }
};

TEST_P(PeriodicContactStress, IsTheRecordsSumToTheBitInAShearingCell) {
  for (const int polygonEvery : {0, 7}) {
    for (const int threads : {1, 2, 3}) {
      SCOPED_TRACE(testing::Message() << threads << " threads" << (polygonEvery ? ", with squares" : ""));
      const std::unique_ptr<World> w = shearingCell(14, threads, polygonEvery);
      const std::vector<unsigned char> all(static_cast<size_t>(w->size()), 1), some = someInside(w->size());
      // Every step: the wide path's state is the batch's between the steps that write it back
      // (a rebuild, a read through the records) and the list's right after them.
      for (int step = 1; step <= 1200; ++step) {
        w->step();
        const double area = w->periodicCell()->area();
        // The direct sums first: reading the records writes the wide path's state back.
        const StressTensor direct = w->contactStress(all, area), directSome = w->contactStress(some, area);
        expectSameBits(direct, throughRecords(*w, all, area));
        expectSameBits(directSome, throughRecords(*w, some, area));
      }
      // Not an empty sum: the packing is pressed and sheared, and contacts cross the edges.
      const StressTensor s = w->contactStress(all, w->periodicCell()->area());
      std::printf("p %.4g Pa, (s12 + s21)/2 %.4g Pa, %d contacts across the edges, %d rebuilds\n", s.p(),
                  0.5 * (s.s12 + s.s21), acrossEdges(*w), static_cast<int>(w->profile().rebuilds));
      EXPECT_GT(s.p(), 1e4) << "the packing must be pressed";
      EXPECT_GT(std::abs(s.s12 + s.s21), 1e-4 * s.p()) << "and sheared: the off-diagonal terms are summed too";
      EXPECT_GT(acrossEdges(*w), 10) << "contacts must meet images across the edges";
      EXPECT_GT(w->profile().rebuilds, 2) << "the list must be rebuilt between measures";
    }
  }
}

TEST_P(PeriodicContactStress, IsTheRecordsSumToTheBitWithWalls) {
  std::vector<Wall> walls;
  const std::vector<ParticleSpec> particles = test::jammedLattice(10, walls);
  for (const int threads : {1, 2}) {
    SCOPED_TRACE(testing::Message() << threads << " threads");
    WorldSettings settings;
    settings.threads = threads;
    World w(test::material(1e8, 0.5, 0.5), settings);
    for (const ParticleSpec& p : particles) w.addParticle(p);
    for (const Wall& wall : walls) w.addWall(wall);
    w.initialize();
    const std::vector<unsigned char> all(static_cast<size_t>(w.size()), 1), some = someInside(w.size());
    for (int step = 1; step <= 300; ++step) {
      w.step();
      if (step % 50 != 0) continue;
      const StressTensor direct = w.contactStress(all, 1e-3), directSome = w.contactStress(some, 1e-3);
      expectSameBits(direct, throughRecords(w, all, 1e-3));
      expectSameBits(directSome, throughRecords(w, some, 1e-3));
    }
    std::vector<ContactRecord> contacts;
    w.contacts(contacts);
    int wallContacts = 0;
    for (const ContactRecord& c : contacts) wallContacts += c.isWall();
    EXPECT_GT(wallContacts, 10) << "the walls must be touched";
  }
}

// The walls' lattice with every other disc a square of about its diameter at a small random
// angle: squares press on squares face to face and on discs, and corners meet faces.
void addSquaresInABox(World& w) {
  std::vector<Wall> walls;
  const std::vector<ParticleSpec> discs = test::jammedLattice(10, walls);
  std::uint64_t state = 11;
  for (size_t k = 0; k < discs.size(); ++k) {
    ParticleSpec p = k % 2 == 0 ? test::box(0.00396, 0.00396, discs[k].position, 0.1 * uniform(state)) : discs[k];
    p.velocity = discs[k].velocity;
    w.addParticle(p);
  }
  for (const Wall& wall : walls) w.addWall(wall);
}

TEST_P(PeriodicContactStress, IsTheRecordsSumToTheBitWithPolygonsInABox) {
  for (const int threads : {1, 2, 3}) {
    SCOPED_TRACE(testing::Message() << threads << " threads");
    WorldSettings settings;
    settings.threads = threads;
    World w(test::material(1e8, 0.5, 0.5), settings);
    addSquaresInABox(w);
    w.initialize();
    const std::vector<unsigned char> all(static_cast<size_t>(w.size()), 1), some = someInside(w.size());
    int polygonPairs = 0;
    for (int step = 1; step <= 400; ++step) {
      w.step();
      expectSameBits(w.contactStress(all, 1e-3), throughRecords(w, all, 1e-3));
      expectSameBits(w.contactStress(some, 1e-3), throughRecords(w, some, 1e-3));
      if (step % 100 != 0) continue;
      // A checkpoint loaded into a world built alike: its first measure, before any step.
      StateArchive saved;
      w.persist(saved);
      World resumed(test::material(1e8, 0.5, 0.5), settings);
      addSquaresInABox(resumed);
      resumed.initialize();
      StateArchive load(saved.bytes());
      resumed.persist(load);
      expectSameBits(resumed.contactStress(all, 1e-3), w.contactStress(all, 1e-3));
      resumed.step();
      w.step();
      ++step;
      expectSameBits(resumed.contactStress(some, 1e-3), w.contactStress(some, 1e-3));
      expectSameBits(w.contactStress(some, 1e-3), throughRecords(w, some, 1e-3));
    }
    std::vector<ContactRecord> contacts;
    w.contacts(contacts);
    for (const ContactRecord& c : contacts) polygonPairs += c.j >= 0 && c.i % 2 == 0 && c.j % 2 == 0;
    const StressTensor s = w.contactStress(all, 1e-3);
    EXPECT_GT(polygonPairs, 30) << "squares must press on squares";
    EXPECT_GT(s.p(), 1e3) << "the packing must be pressed";
  }
}

TEST(PeriodicContactStressInput, NamesTheBadArgument) {
  const std::unique_ptr<World> w = shearingCell(4, 1, 0);
  const std::vector<unsigned char> all(static_cast<size_t>(w->size()), 1), short_(3, 1);
  EXPECT_THROW(w->contactStress(all, 0), std::invalid_argument);
  EXPECT_THROW(w->contactStress(short_, 1), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Paths, PeriodicContactStress, ::testing::Values(SimdPath::Baseline, SimdPath::Wide),
                         [](const auto& info) { return info.param == SimdPath::Wide ? "Wide" : "Baseline"; });

}  // namespace
}  // namespace grainlab

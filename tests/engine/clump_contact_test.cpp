// Clumps in the DEM: contacts between members of different bodies only, each member's force
// and torque (lever from the clump's centroid) on its clump. Checked by conservation laws, by
// statics, and bit for bit against lone discs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "engine/world_helpers.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/state_archive.hpp"

namespace grainlab {
namespace {

// `count` discs of radius r in a line along the body's x axis, `spacing` apart, about the
// reference point.
ParticleSpec lineClump(int count, double r, double spacing, Vec2 x, double angle = 0, Vec2 v = Vec2::Zero(),
                       double spin = 0) {
  ParticleSpec p;
  p.shape = ShapeKind::Clump;
  for (int k = 0; k < count; ++k) p.members.push_back({Vec2((k - 0.5 * (count - 1)) * spacing, 0), r});
  p.position = x;
  p.angle = angle;
  p.velocity = v;
  p.spin = spin;
  return p;
}

// An L-shaped clump (no symmetry: its centroid is off every member's centre).
ParticleSpec lClump(Vec2 x, double angle, Vec2 v, double spin) {
  ParticleSpec p;
  p.shape = ShapeKind::Clump;
  p.members = {{{0, 0}, 0.002}, {{0.0025, 0}, 0.0018}, {{0.005, 0}, 0.0015}, {{0, 0.0025}, 0.0016}};
  p.position = x;
  p.angle = angle;
  p.velocity = v;
  p.spin = spin;
  return p;
}

template <class T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

TEST(ClumpContact, NoContactInsideAClump) {
  World world(test::material(1e8, 0.5, 0.5));
  // Members overlapping by 60% of a radius: as lone discs they would push apart hard.
  world.addParticle(lineClump(3, 0.002, 0.0016, {0, 0}, 0.3, {0.01, -0.02}, 5.0));
  const Vec2 v0 = world.velocities()[0];
  const double w0 = world.spins()[0];
  for (int k = 0; k < 200; ++k) world.step();
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  EXPECT_TRUE(contacts.empty());
  EXPECT_TRUE(sameBits(world.velocities()[0], v0));
  EXPECT_EQ(world.spins()[0], w0);
  EXPECT_NEAR(world.angles()[0], 0.3 + 200 * world.timestep() * 5.0, 1e-12);
}

struct Momenta {
  Vec2 linear = Vec2::Zero();
  double angular = 0;  // about the origin
  double scale = 0;    // Σ |m v| and Σ (|m x × v| + |I ω|): what rounding errors are relative to
  double angularScale = 0;
};
Momenta momenta(const World& w) {
  Momenta m;
  for (int k = 0; k < w.size(); ++k) {
    const Vec2 p = w.masses()[k] * w.velocities()[k];
    m.linear += p;
    m.angular += cross(w.positions()[k], p) + w.inertias()[k] * w.spins()[k];
    m.scale += p.norm();
    m.angularScale += std::abs(cross(w.positions()[k], p)) + std::abs(w.inertias()[k] * w.spins()[k]);
  }
  return m;
}

TEST(ClumpContact, FreeCollisionConservesLinearAndAngularMomentum) {
  // Two unlike clumps meet off-centre with friction: the members' forces act on levers from
  // each clump's centroid. A lever from the member's centre instead would leave the normal
  // forces' torque out and break the angular balance at first contact.
  World world(test::material(1e7, 0.6, 0.5));
  world.addParticle(lClump({-0.006, 0.001}, 0.4, {0.5, 0.0}, 3.0));
  world.addParticle(lineClump(3, 0.0015, 0.002, {0.006, -0.001}, 1.2, {-0.4, 0.05}, -2.0));
  const Momenta before = momenta(world);
  int touching = 0;
  for (int k = 0; k < 20000; ++k) {
    world.step();
    std::vector<ContactRecord> c;
    world.contacts(c);
    touching += !c.empty();
  }
  ASSERT_GT(touching, 10);  // they did collide, for many steps
  const Momenta after = momenta(world);
  // The collision changed each body's motion a lot...
  EXPECT_GT(std::abs(world.spins()[0] - 3.0), 3.0);
  EXPECT_GT(world.velocities()[0].x(), -1.0);
  EXPECT_LT(world.velocities()[0].x(), 0.4);
  // ...and the sums not at all, beyond rounding (1e-16 per operation, 20000 steps).
  EXPECT_NEAR(after.linear.x(), before.linear.x(), 1e-11 * before.scale);
  EXPECT_NEAR(after.linear.y(), before.linear.y(), 1e-11 * before.scale);
  EXPECT_NEAR(after.angular, before.angular, 1e-11 * before.angularScale);
}

TEST(ClumpContact, ATiltedClumpSettlesFlatOnAWallCarryingItsWeight) {
  Material material = test::material(1e7, 0.3, 0.5);
  material.localDamping = 0.3;
  World world(material);
  world.setGravity({0, -9.81});
  world.addWall({{0, 0}, {0, 1}});
  const double r = 0.002;
  world.addParticle(lineClump(3, r, 1.5 * r, {0, 0.006}, 0.25));
  for (int k = 0; k < 60000; ++k) world.step();
  // Lying flat: every member on the wall. Only the normal forces' lever from the centroid
  // turns a clump that lands on an end disc down onto its others.
  EXPECT_NEAR(std::remainder(world.angles()[0], kPi), 0, 1e-3);
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  ASSERT_EQ(contacts.size(), 3u);
  double lift = 0;
  for (const ContactRecord& c : contacts) lift += -(c.fn * c.normal + c.ft * perp(c.normal)).y();
  const double weight = world.masses()[0] * 9.81;
  // Settled: what is left is the acceleration of a residual vibration, far below 1e-6 g.
  ASSERT_LT(world.velocities()[0].norm(), 1e-6);
  EXPECT_NEAR(lift, weight, 1e-6 * weight);
}

// The jammed, vibrating, spinning lattice of the disc-path test, as lone discs or each disc a
// one-member clump (its member given off the reference point, to exercise the centroid).
void fillLattice(World& world, bool asClumps) {
  std::vector<Wall> walls;
  std::vector<ParticleSpec> discs = test::jammedLattice(12, walls);
  std::uint64_t state = 11;
  for (ParticleSpec& p : discs) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    p.spin = 24.0 * (static_cast<double>(state >> 11) * 0x1.0p-53 - 0.5);
    if (asClumps) {
      p.shape = ShapeKind::Clump;
      p.members = {{Vec2(0.001, -0.0005), p.radius}};
      p.position -= Vec2(0.001, -0.0005);  // the member, and so the body, where the disc was
    }
    world.addParticle(p);
  }
  for (const Wall& w : walls) world.addWall(w);
}

TEST(ClumpContact, AOneDiscClumpIsThatDiscBitForBit) {
  // Member contacts run the scalar disc law: the lone discs take the same (baseline) path.
  struct BaselinePath {
    BaselinePath() { overrideSimdPath(SimdPath::Baseline); }
    ~BaselinePath() { overrideSimdPath(std::nullopt); }
  } baseline;
  const Material material = test::material(1e8, 0.5, 0.5);
  World discs(material), clumps(material);
  WorldSettings threaded;
  threaded.threads = 2;
  World clumpsThreaded(material, threaded);
  fillLattice(discs, false);
  fillLattice(clumps, true);
  fillLattice(clumpsThreaded, true);
  ASSERT_EQ(discs.timestep(), clumps.timestep());  // the same critical timestep
  for (int step = 0; step < 400; ++step) {
    discs.step();
    clumps.step();
    clumpsThreaded.step();
  }
  std::vector<ContactRecord> contacts;
  clumps.contacts(contacts);
  ASSERT_GT(contacts.size(), 100u);
  for (int k = 0; k < discs.size(); ++k) {
    for (const World* w : {&clumps, &clumpsThreaded}) {
      ASSERT_TRUE(sameBits(w->positions()[k], discs.positions()[k])) << k;
      ASSERT_TRUE(sameBits(w->velocities()[k], discs.velocities()[k])) << k;
      ASSERT_TRUE(sameBits(w->spins()[k], discs.spins()[k])) << k;
      ASSERT_TRUE(sameBits(w->angles()[k], discs.angles()[k])) << k;
    }
  }
}

// A box of three-disc clumps and lone discs shaken under gravity.
void fillMixedBox(World& world) {
  world.setGravity({0, -9.81});
  world.addWall({{0, 0}, {0, 1}});
  world.addWall({{-0.03, 0}, {1, 0}});
  world.addWall({{0.03, 0}, {-1, 0}});
  for (int row = 0; row < 8; ++row) {
    for (int col = 0; col < 5; ++col) {
      const Vec2 x(-0.024 + col * 0.012 + (row % 2) * 0.003, 0.004 + row * 0.007);
      if ((row + col) % 3 == 0) world.addParticle(test::disc(0.002, x, {0.05 * (col - 2), 0}));
      else world.addParticle(lineClump(3, 0.0018, 0.0018, x, 0.3 * (row - col), {0.05 * (2 - col), 0}, 3.0 * (col - 2)));
    }
  }
}

TEST(ClumpContact, ResumesFromACheckpointBitForBit) {
  Material material = test::material(1e7, 0.5, 0.5);
  material.localDamping = 0.1;
  World run(material);
  fillMixedBox(run);
  for (int k = 0; k < 3000; ++k) run.step();
  StateArchive saved;
  run.persist(saved);
  for (int k = 0; k < 3000; ++k) run.step();

  World resumed(material);
  fillMixedBox(resumed);
  resumed.initialize();
  StateArchive load(saved.bytes());
  resumed.persist(load);
  for (int k = 0; k < 3000; ++k) resumed.step();
  std::vector<ContactRecord> contacts;
  run.contacts(contacts);
  ASSERT_GT(contacts.size(), 5u);
  for (int k = 0; k < run.size(); ++k) {
    ASSERT_TRUE(sameBits(run.positions()[k], resumed.positions()[k])) << k;
    ASSERT_TRUE(sameBits(run.velocities()[k], resumed.velocities()[k])) << k;
    ASSERT_TRUE(sameBits(run.angles()[k], resumed.angles()[k])) << k;
  }
}

TEST(ClumpContact, ContactsAreBetweenBodiesAtTheMembersTouchPoint) {
  World world(test::material(1e7, 0.5, 0.5));
  world.addParticle(lineClump(2, 0.002, 0.003, {0, 0}));
  world.addParticle(test::disc(0.002, {0.0015 + 0.0039, 0}));  // 0.1 mm into the right member
  world.initialize();
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].i, 0);
  EXPECT_EQ(contacts[0].j, 1);
  EXPECT_NEAR(contacts[0].overlap, 1e-4, 1e-15);
  EXPECT_NEAR(contacts[0].point.x(), 0.0015 + 0.00195, 1e-15);
  EXPECT_NEAR(world.area(0), 2 * discArea(0.002) - (2 * 4e-6 * std::acos(0.75) - 0.0015 * std::sqrt(16e-6 - 9e-6)), 1e-18);
}

TEST(ClumpContact, ClumpsWithPolygonsAreRefused) {
  World world(test::material(1e7, 0.5, 0.5));
  world.addParticle(lineClump(2, 0.002, 0.003, {0, 0}));
  world.addParticle(test::box(0.004, 0.004, {0.02, 0}));
  EXPECT_THROW(world.initialize(), SimulationError);
}

}  // namespace
}  // namespace grainlab

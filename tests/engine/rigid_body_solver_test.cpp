// The box2d engine (RigidBodySolver): Box2D's rigid-body solver moving the World's particles.
// Tolerances come from the solver: Box2D leaves up to its linear slop (0.005 units, a
// two-hundredth of the mean radius here) of penetration, and works in single precision.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "grainlab/errors.hpp"
#include "grainlab/scene.hpp"
#include "world_helpers.hpp"

namespace grainlab {
namespace {

using test::box;
using test::disc;
using test::material;

constexpr double kG = 9.81;
constexpr double kSlopUnits = 0.005;  // b2_linearSlop
constexpr double kSkinUnits = 0.01;   // b2_polygonRadius

WorldSettings box2d(int velocityIterations = 8, int positionIterations = 3) {
  WorldSettings s;
  s.engine = WorldSettings::Engine::Box2d;
  s.velocityIterations = velocityIterations;
  s.positionIterations = positionIterations;
  return s;
}

void run(World& world, double seconds) {
  const int steps = static_cast<int>(std::ceil(seconds / world.timestep()));
  for (int k = 0; k < steps; ++k) world.step();
  world.checkHealth();
}

std::vector<ContactRecord> contactsOf(const World& world) {
  std::vector<ContactRecord> c;
  world.contacts(c);
  return c;
}

TEST(RigidBodySolver, DiscDroppedOnAWallRestsWithItsWeightOnIt) {
  const double r = 0.002;
  World world(material(3e8, 0.5, 0.5), box2d());
  world.addParticle(disc(r, {0.0, r + 0.0005}));  // half a millimetre above the wall
  world.addWall(Wall{Vec2(0, 0), Vec2(0, 1)});
  world.setGravity({0, -kG});
  run(world, 0.3);
  const double weight = world.masses()[0] * kG;
  const auto c = contactsOf(world);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].i, 0);
  EXPECT_EQ(c[0].j, -1);  // wall 0
  EXPECT_NEAR(c[0].normal.y(), -1.0, 1e-6);  // from the disc into the wall
  EXPECT_NEAR(c[0].fn, weight, 0.02 * weight);  // Σ normal impulse / dt
  EXPECT_NEAR(c[0].point.y(), 0.0, 2e-5);
  // At rest on the wall, in it by no more than Box2D's slop (the mean radius is one unit).
  const double slop = kSlopUnits * r;
  EXPECT_GE(c[0].overlap, 0.0);
  EXPECT_LE(c[0].overlap, 1.2 * slop);
  EXPECT_NEAR(world.positions()[0].y(), r - c[0].overlap, 1e-7);
  EXPECT_LT(world.velocities()[0].norm(), 1e-3);
  // The World's forces carry the contact: gravity and the wall's push cancel.
  EXPECT_LT(world.forces()[0].norm(), 0.02 * weight);
  EXPECT_EQ(world.elasticEnergy(), 0.0);  // rigid contacts store none
}

// A block of 4 × 2 mm on another of 6 × 2 mm, on a wall. `topFirst` creates the top block
// first so that Box2D's A and B and our i < j disagree in one of the two orders.
void checkStack(bool topFirst) {
  const double h = 0.002;
  World world(material(3e8, 0.5, 0.5), box2d());
  const ParticleSpec bottom = box(0.006, h, {0.0, h / 2});
  const ParticleSpec top = box(0.004, h, {0.0005, 1.5 * h});
  const int t = topFirst ? world.addParticle(top) : -1;
  const int b = world.addParticle(bottom);
  const int tt = topFirst ? t : world.addParticle(top);
  world.addWall(Wall{Vec2(0, 0), Vec2(0, 1)});
  world.setGravity({0, -kG});
  run(world, 0.3);
  const double mTop = world.masses()[tt], mBottom = world.masses()[b];
  const auto contacts = contactsOf(world);
  ASSERT_EQ(contacts.size(), 2u);
  for (const ContactRecord& c : contacts) {
    if (c.isWall()) {
      EXPECT_EQ(c.i, b);
      EXPECT_NEAR(c.fn, (mTop + mBottom) * kG, 0.03 * (mTop + mBottom) * kG);
      continue;
    }
    EXPECT_EQ(c.i, std::min(b, tt));
    EXPECT_EQ(c.j, std::max(b, tt));
    // n points from i to j: up if the bottom block is i, down if it is j.
    EXPECT_NEAR(c.normal.y(), c.i == b ? 1.0 : -1.0, 1e-5);
    EXPECT_NEAR(c.fn, mTop * kG, 0.03 * mTop * kG);
    EXPECT_LT(std::abs(c.ft), 0.01 * mTop * kG);
  }
  // Equal and opposite: the force on each block, contacts and gravity, is zero.
  EXPECT_LT(world.forces()[tt].norm(), 0.03 * mTop * kG);
  EXPECT_LT(world.forces()[b].norm(), 0.03 * mTop * kG);
  EXPECT_LT(std::abs(world.torques()[tt]), 0.03 * mTop * kG * h);
}

TEST(RigidBodySolver, StackedPolygonsPushEqualAndOpposite) { checkStack(false); }
TEST(RigidBodySolver, StackedPolygonsPushEqualAndOppositeInEitherCreationOrder) { checkStack(true); }

// A disc resting on a fixed block: Box2D always makes the polygon its A, so with the disc
// first (i) the normal must be flipped to run from the disc down into the block.
void checkDiscOnBlock(bool discFirst) {
  const double r = 0.002;
  World world(material(3e8, 0.5, 0.5), box2d());
  ParticleSpec block = box(0.01, 0.004, {0.0, -0.002});
  block.motion = Motion::Fixed;
  const ParticleSpec ball = disc(r, {0.001, r});
  const int d = discFirst ? world.addParticle(ball) : -1;
  const int b = world.addParticle(block);
  const int dd = discFirst ? d : world.addParticle(ball);
  world.setGravity({0, -kG});
  run(world, 0.2);
  const auto c = contactsOf(world);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].i, std::min(b, dd));
  EXPECT_NEAR(c[0].normal.y(), c[0].i == dd ? -1.0 : 1.0, 1e-6);
  const double weight = world.masses()[dd] * kG;
  EXPECT_NEAR(c[0].fn, weight, 0.02 * weight);
  EXPECT_NEAR(c[0].point.x(), 0.001, 1e-6);
  EXPECT_LT(world.forces()[dd].norm(), 0.02 * weight);
}

TEST(RigidBodySolver, DiscOnAPolygonPushesDownOnItInEitherCreationOrder) {
  checkDiscOnBlock(true);
  checkDiscOnBlock(false);
}

// A 4 × 2 mm block resting on a slope of angle θ (a tilted wall) under gravity; returns its
// acceleration down the slope, m/s², measured between 0.05 and 0.15 s.
// `dtScale` multiplies the default timestep.
double slideAcceleration(double thetaDeg, double mu, WorldSettings settings = box2d(), double dtScale = 1) {
  const double th = radians(thetaDeg), h = 0.002;
  const Vec2 n(-std::sin(th), std::cos(th)), down(-std::cos(th), -std::sin(th));
  World world(material(3e8, 0.5, mu), settings);
  world.addParticle(box(0.004, h, n * (h / 2), th));
  world.addWall(Wall{Vec2(0, 0), n});
  world.setGravity({0, -kG});
  world.setTimestep(world.timestep() * dtScale);
  run(world, 0.05);
  const double v0 = world.velocities()[0].dot(down), t0 = world.time();
  run(world, 0.1);
  // Still on the slope, not tumbling.
  EXPECT_NEAR((world.positions()[0]).dot(n), h / 2, 0.01 * h);
  EXPECT_NEAR(std::remainder(world.angles()[0] - th, 2 * kPi), 0.0, 1e-3);
  return (world.velocities()[0].dot(down) - v0) / (world.time() - t0);
}

TEST(RigidBodySolver, BlockOnASlopeSticksBelowTheFrictionAngleAndSlidesAbove) {
  const double mu = 0.5;  // friction angle 26.6°
  EXPECT_NEAR(slideAcceleration(20, mu), 0.0, 0.005);
  EXPECT_NEAR(slideAcceleration(25, mu), 0.0, 0.005);
  for (double deg : {30.0, 40.0}) {
    const double th = radians(deg);
    const double expected = kG * (std::sin(th) - mu * std::cos(th));
    // Measured: within 0.02% at 30° and 40°, for 8 or 30 iterations and dt from 1/4 to 4×.
    EXPECT_NEAR(slideAcceleration(deg, mu), expected, 0.01 * expected) << deg << "°";
    EXPECT_NEAR(slideAcceleration(deg, mu, box2d(30, 10), 0.25), expected, 0.01 * expected) << deg << "°";
  }
}

TEST(RigidBodySolver, HeadOnElasticCollisionOfEqualDiscsExchangesVelocities) {
  const double r = 0.002;
  World world(material(3e8, 1.0, 0.0), box2d());
  world.addParticle(disc(r, {0, 0}, {0.5, 0}));
  world.addParticle(disc(r, {0.006, 0}, {0, 0}));
  const double p0 = world.masses()[0] * 0.5;
  run(world, 0.01);  // meets after 4 ms
  const auto v = world.velocities();
  EXPECT_NEAR(v[0].x(), 0.0, 0.02 * 0.5);
  EXPECT_NEAR(v[1].x(), 0.5, 0.02 * 0.5);
  EXPECT_NEAR(world.masses()[0] * v[0].x() + world.masses()[1] * v[1].x(), p0, 1e-5 * p0);
  EXPECT_NEAR(v[0].y() + v[1].y(), 0.0, 1e-9);
  EXPECT_NEAR(world.kineticEnergy(), 0.5 * world.masses()[0] * 0.25, 0.04 * 0.5 * world.masses()[0] * 0.25);
}

TEST(RigidBodySolver, PolygonRestsOnAWallAtItsTrueHeightNotOnBox2dsSkin) {
  // Box2D rounds polygons with a 0.01-unit skin; the solver shrinks them by it, so the block
  // sits at h/2 less at most the slop of penetration, not a skin higher.
  const double w = 0.004, h = 0.002;
  World world(material(3e8, 0.5, 0.5), box2d());
  world.addParticle(box(w, h, {0.0, h / 2 + 0.0002}));
  world.addWall(Wall{Vec2(0, 0), Vec2(0, 1)});
  world.setGravity({0, -kG});
  run(world, 0.3);
  const double unit = world.boundingRadii()[0];  // one particle: its radius is the unit
  const double y = world.positions()[0].y();
  EXPECT_GT(y, h / 2 - 1.2 * kSlopUnits * unit);
  EXPECT_LT(y, h / 2 + 0.2 * kSlopUnits * unit);  // with the skin it would be h/2 + 0.01 unit
  EXPECT_GT(kSkinUnits * unit, 1.4 * kSlopUnits * unit);  // so the test can tell them apart
  const auto c = contactsOf(world);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].overlap, h / 2 - y, 1e-3 * kSlopUnits * unit + 1e-8);
  EXPECT_NEAR(c[0].fn, world.masses()[0] * kG, 0.02 * world.masses()[0] * kG);
  EXPECT_NEAR(c[0].point.x(), 0.0, 1e-6);  // the two corners' impulses balance
}

TEST(RigidBodySolver, FrictionChangesTakeEffectOnExistingContacts) {
  // The block sticks on a 30° slope at μ = 0.7; dropping μ to 0.1 mid-run makes it slide.
  const double th = radians(30), h = 0.002;
  const Vec2 n(-std::sin(th), std::cos(th)), down(-std::cos(th), -std::sin(th));
  World world(material(3e8, 0.5, 0.7), box2d());
  world.addParticle(box(0.004, h, n * (h / 2), th));
  world.addWall(Wall{Vec2(0, 0), n});
  world.setGravity({0, -kG});
  run(world, 0.05);
  EXPECT_LT(std::abs(world.velocities()[0].dot(down)), 1e-4);
  world.setFriction(0.1);
  const double t0 = world.time(), v0 = world.velocities()[0].dot(down);
  run(world, 0.05);
  const double expected = kG * (std::sin(th) - 0.1 * std::cos(th));
  EXPECT_NEAR((world.velocities()[0].dot(down) - v0) / (world.time() - t0), expected, 0.03 * expected);
}

std::vector<double> finalState(int threads) {
  std::vector<Wall> walls;
  std::vector<ParticleSpec> particles = test::jammedLattice(6, walls);
  particles.push_back(box(0.004, 0.002, {0.004, 0.03}, 0.3));  // a polygon falling in
  WorldSettings settings = box2d();
  settings.threads = threads;  // unused by box2d: must not matter
  World world(material(3e8, 0.5, 0.5), settings);
  for (const ParticleSpec& p : particles) world.addParticle(p);
  for (const Wall& w : walls) world.addWall(w);
  world.setGravity({0, -kG});
  run(world, 0.05);
  std::vector<double> out;
  for (int k = 0; k < world.size(); ++k) {
    out.insert(out.end(), {world.positions()[k].x(), world.positions()[k].y(), world.angles()[k],
                           world.velocities()[k].x(), world.spins()[k]});
  }
  for (const ContactRecord& c : contactsOf(world)) out.insert(out.end(), {c.fn, c.ft, c.point.x(), c.overlap});
  return out;
}

TEST(RigidBodySolver, SameSceneTwiceGivesBitIdenticalState) {
  const std::vector<double> a = finalState(1), b = finalState(1), c = finalState(2);
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) ASSERT_EQ(a[k], b[k]) << k;  // exact
  ASSERT_EQ(a, c);
}

TEST(RigidBodySolver, KinematicParticlesMoveAtTheirPrescribedVelocity) {
  World world(material(3e8, 0.5, 0.5), box2d());
  ParticleSpec pusher = disc(0.002, {0, 0});
  pusher.motion = Motion::Kinematic;
  world.addParticle(pusher);
  world.addParticle(disc(0.002, {0.0045, 0}));
  world.initialize();
  world.setKinematicVelocity(0, {0.1, 0}, 2.0);
  run(world, 0.02);
  EXPECT_NEAR(world.positions()[0].x(), 0.1 * world.time(), 1e-12);  // integrated in double
  EXPECT_NEAR(world.angles()[0], 2.0 * world.time(), 1e-12);
  // It pushed the other disc along: it moves ahead at least as fast.
  EXPECT_GE(world.velocities()[1].x(), 0.1 * 0.99);
}

TEST(RigidBodySolver, DefaultTimestepIsTenTimesTheDemDefaultAndNotBoundByTheSprings) {
  World dem(material(3e8, 0.5, 0.5)), rigid(material(3e8, 0.5, 0.5), box2d());
  dem.addParticle(disc(0.002, {0, 0}));
  rigid.addParticle(disc(0.002, {0, 0}));
  EXPECT_DOUBLE_EQ(rigid.timestep(), 10 * dem.timestep());
  rigid.setTimestep(5 * rigid.criticalTimestep());  // would be refused by the DEM
  EXPECT_NO_THROW(rigid.initialize());
}

TEST(RigidBodySolver, SceneErrorsForIterationCountsNameTheField) {
  auto fieldOf = [](nlohmann::json solver) {
    nlohmann::json j = {{"particles", {{{"shape", "disc"}, {"radius", 0.002}, {"position", {0, 0}}}}}};
    j["solver"] = solver;
    try {
      parseScene(j);
    } catch (const SceneError& e) {
      return e.field() + ": " + e.reason();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(fieldOf({{"engine", "box2d"}, {"velocity_iterations", 0}}),
            "solver.velocity_iterations: must be an integer in 1..100, got 0");
  EXPECT_EQ(fieldOf({{"engine", "box2d"}, {"velocity_iterations", 2.5}}),
            "solver.velocity_iterations: must be an integer in 1..100, got 2.5");
  EXPECT_EQ(fieldOf({{"engine", "box2d"}, {"position_iterations", 101}}),
            "solver.position_iterations: must be an integer in 1..100, got 101");
  EXPECT_EQ(fieldOf({{"engine", "box2d"}, {"position_iterations", "3"}}),
            "solver.position_iterations: must be an integer in 1..100, got \"3\"");
  EXPECT_EQ(fieldOf({{"velocity_iterations", 8}}).rfind("solver.velocity_iterations: only the box2d engine", 0), 0u);
  EXPECT_EQ(fieldOf({{"engine", "box2d"}, {"velocity_iterations", 12}, {"position_iterations", 4}}), "(accepted)");
  const Scene s = parseScene({{"particles", {{{"shape", "disc"}, {"radius", 0.002}}}},
                              {"solver", {{"engine", "box2d"}, {"velocity_iterations", 12}}}});
  EXPECT_EQ(s.solver.engine, SolverSpec::Engine::Box2d);
  EXPECT_EQ(s.solver.velocityIterations, 12);
  EXPECT_EQ(s.solver.positionIterations, 3);
}

}  // namespace
}  // namespace grainlab

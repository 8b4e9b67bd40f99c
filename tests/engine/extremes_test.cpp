// The engine at the edges of its parameter space: a timestep far beyond the critical one,
// stiffness over eight decades, friction 0 and 10, a 10:1 size ratio, a 5:1 aspect ratio,
// confining stresses of 1 kPa and 100 MPa, particles that start overlapping, a lone particle.
// Each case either behaves as the physics says or stops with a message that says why; none
// writes a NaN. (Undamped energy drift: energy_test; an empty scene: scene_test; a jammed
// packing at 3× the critical timestep: stability_test.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "engine/world_helpers.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"

namespace grainlab {
namespace {

using test::box;
using test::disc;
constexpr double kG = 9.81;  // m/s²

// Keeps every series row as CSV text, the last sample's p, and the final contacts.
class Recorder : public RunObserver {
 public:
  void onSample(const Sample& s, const World&) override {
    rows += formatSeriesRow(s) + "\n";
    const auto& columns = seriesColumns();
    const size_t p = static_cast<size_t>(std::find(columns.begin(), columns.end(), "p") - columns.begin());
    lastP = p < s.values.size() ? s.values[p] : NAN;
  }
  void onFinish(const RunSummary&, const World& world) override {
    world.contacts(contacts);
    finalPositions.assign(world.positions().begin(), world.positions().end());
    finalVelocities.assign(world.velocities().begin(), world.velocities().end());
  }
  bool hasNonFinite() const { return rows.find("nan") != std::string::npos || rows.find("inf") != std::string::npos; }

  std::string rows;
  double lastP = NAN;
  std::vector<ContactRecord> contacts;
  std::vector<Vec2> finalPositions, finalVelocities;
};

bool finiteState(const World& world) {
  for (int k = 0; k < world.size(); ++k) {
    if (!std::isfinite(world.positions()[k].x()) || !std::isfinite(world.positions()[k].y()) ||
        !std::isfinite(world.velocities()[k].x()) || !std::isfinite(world.velocities()[k].y()) ||
        !std::isfinite(world.spins()[k])) {
      return false;
    }
  }
  return true;
}

// ---- timestep beyond the critical one ----

// Two discs colliding head-on at a timestep `factor` × critical, run through runScene.
Scene collisionAt(double factor) {
  Scene scene;
  scene.material = test::material(1e8, 0.5, 0.5);
  const double r = 0.002;
  scene.particles = {disc(r, {0, 0}, {0.5, 0}), disc(r, {2.001 * r, 0}, {-0.5, 0})};
  World probe(scene.material);
  for (const ParticleSpec& p : scene.particles) probe.addParticle(p);
  scene.solver.timestep = factor * probe.criticalTimestep();
  StageSpec free;
  free.name = "free";
  free.duration = 2000 * scene.solver.timestep;
  scene.stages = {free};
  scene.output.sampleInterval = 5 * scene.solver.timestep;
  return scene;
}

TEST(Extremes, BinaryCollisionFarBeyondCriticalTimestepFailsWithReason) {
  // At 10 and 100 × critical the contact spring is integrated unstably: the pair must not
  // leave faster than it came (e ≤ 1), so the run must stop and say why.
  for (double factor : {10.0, 100.0}) {
    Recorder rec;
    const RunSummary s = runScene(collisionAt(factor), rec);
    EXPECT_FALSE(rec.hasNonFinite()) << factor;
    // Before 274c9fe this run completed with the pair leaving at 135 m/s.
    ASSERT_EQ(s.status, RunStatus::Failed) << "factor " << factor;
    EXPECT_NE(s.error.find("timestep"), std::string::npos) << s.error;
  }
}

TEST(Extremes, PresetWithTimestepSafetyFiveFailsWithReason) {
  // The parser takes timestep_safety up to 10; the membrane stages at 5 × critical must stop
  // with the cause named, not stream NaN into the series.
  nlohmann::json j = presetScene("circular-quick");
  j["solver"]["timestep_safety"] = 5.0;
  j["stages"] = nlohmann::json::array({j["stages"][0], j["stages"][1]});
  Recorder rec;
  const RunSummary s = runScene(parseScene(j), rec);
  EXPECT_EQ(s.status, RunStatus::Failed);
  EXPECT_NE(s.error.find("timestep"), std::string::npos) << s.error;
  EXPECT_FALSE(rec.hasNonFinite());
}

// ---- normal stiffness over eight decades ----

TEST(Extremes, DiscSettlesAtMgOverKnFrom1e4To1e12) {
  // Dropped from touching with no speed, a damped disc oscillates about m g / k_n and comes
  // to rest there. The default timestep (0.2 × critical) follows the stiffness, so every case
  // takes the same number of steps per contact period (about 22).
  const double r = 0.002;
  for (double kn = 1e4; kn <= 1e12; kn *= 100) {
    World world(test::material(kn, 0.3, 0.5));
    world.addWall({Vec2(0, 0), Vec2(0, 1)});
    world.addParticle(disc(r, {0, r}));
    world.setGravity({0, -kG});
    for (int k = 0; k < 3000; ++k) world.step();
    world.checkHealth();
    const double expected = world.masses()[0] * kG / kn;
    const double overlap = r - world.positions()[0].y();
    // Residual oscillation after ~140 periods at ζ = 0.36 is nil; what remains is the
    // rounding of y (≈ 2e-16 × r), which at k_n = 1e12 is 1e-6 of the overlap.
    EXPECT_NEAR(overlap, expected, 1e-5 * expected) << "k_n = " << kn;
  }
}

// ---- friction 0 and 10 ----

// A flat 4:1 block on a 45° incline (gravity tilted, the wall y = 0): its slide in `seconds`.
double slideOn45(double mu, double seconds) {
  const double kn = 1e7, w = 0.008, h = 0.002, t = radians(45);
  World world(test::material(kn, 0.3, mu));
  world.addWall({Vec2(0, 0), Vec2(0, 1)});
  const double m = 2650 * w * h;
  world.addParticle(box(w, h, {0, h / 2 - m * kG * std::cos(t) / kn}));
  world.setGravity({kG * std::sin(t), -kG * std::cos(t)});
  const double x0 = world.positions()[0].x();
  while (world.time() < seconds) world.step();
  world.checkHealth();
  // 4:1 cannot tip at 45°. With one depth-weighted contact point the block tilts by about
  // (h/2 · tan θ)/(w/2) × 2δ / w ≈ 2e-6 rad to bring that point under its weight.
  EXPECT_NEAR(world.angles()[0], 0.0, 1e-4);
  return world.positions()[0].x() - x0;
}

TEST(Extremes, FrictionlessBlockSlidesAtGSinTheta) {
  const double t = 0.2;
  const double expected = 0.5 * kG * std::sin(radians(45)) * t * t;
  // Leapfrog integrates a constant acceleration exactly up to one step's offset (dt / t ~ 1e-5).
  EXPECT_NEAR(slideOn45(0.0, t), expected, 1e-3 * expected);
}

TEST(Extremes, FrictionTenSticksAt45Degrees) {
  // tan 45° = 1 ≪ 10: static friction holds; only the tangential spring's elastic set,
  // m g sin θ / k_t ≈ 6e-8 m, may show.
  EXPECT_LT(std::abs(slideOn45(10.0, 0.2)), 1e-6);
}

// ---- size ratio 10:1 ----

TEST(Extremes, BigDiscOnSmallOnesSizeRatioTen) {
  // A disc of 10 mm radius dropped on three layers of 1 mm discs in a box.
  const double r = 0.001, R = 10 * r, kn = 1e7, width = 40 * r;
  Material mat = test::material(kn, 0.3, 0.5);
  mat.localDamping = 0.1;  // to come to rest within the run
  World world(mat);
  world.addWall({Vec2(0, 0), Vec2(0, 1)});
  world.addWall({Vec2(0, 0), Vec2(1, 0)});
  world.addWall({Vec2(width, 0), Vec2(-1, 0)});
  int small = 0;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 19; ++col) {
      world.addParticle(disc(r, {(2 * col + 1 + (row % 2)) * 1.02 * r, (1 + 2 * row) * 1.02 * r}));
      ++small;
    }
  }
  const int big = world.addParticle(disc(R, {width / 2, 6.5 * r + R}));
  world.setGravity({0, -kG});
  while (world.time() < 0.4) world.step();
  world.checkHealth();

  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  // The neighbour grid (cells as wide as the biggest pair) finds every touching pair: a
  // brute-force check over all pairs finds none it missed.
  const auto x = world.positions();
  const auto rad = world.boundingRadii();
  int touching = 0, bigContacts = 0;
  double maxOverlap = 0;
  for (int i = 0; i < world.size(); ++i) {
    for (int j = i + 1; j < world.size(); ++j) {
      if ((x[j] - x[i]).norm() < rad[i] + rad[j]) ++touching;
    }
  }
  int particlePairs = 0;
  for (const ContactRecord& c : contacts) {
    if (c.j >= 0) ++particlePairs;
    if (c.i == big || c.j == big) ++bigContacts;
    maxOverlap = std::max(maxOverlap, c.overlap);
  }
  EXPECT_EQ(particlePairs, touching);
  EXPECT_GE(bigContacts, 1);
  // At rest no contact carries more than the weight of everything: overlap ≤ Σ m g / k_n.
  double weight = 0;
  for (double m : world.masses()) weight += m * kG;
  EXPECT_LT(maxOverlap, weight / kn);
  EXPECT_GT(x[big].y(), 5 * r + R);  // on top of the bed, not sunk into it
  // Supported: no longer falling (it may still roll slowly into a hollow of the bed).
  EXPECT_LT(std::abs(world.velocities()[big].y()), 1e-3);
  EXPECT_EQ(small, 57);
}

// ---- aspect ratio 5 ----

TEST(Extremes, FiveToOneRectangleRestsOnItsLongSideOnAWall) {
  // Dropped tilted by 3° from touching at one corner, it falls flat and rests on its long
  // side at overlap m g / k_n (the wall contact is computed in double precision).
  const double kn = 1e7, w = 0.010, h = 0.002, tilt = radians(3);
  World world(test::material(kn, 0.3, 0.5));
  world.addWall({Vec2(0, 0), Vec2(0, 1)});
  const double lowCorner = 0.5 * w * std::sin(tilt) + 0.5 * h * std::cos(tilt);
  world.addParticle(box(w, h, {0, lowCorner}, tilt));
  world.setGravity({0, -kG});
  while (world.time() < 0.5) world.step();
  world.checkHealth();
  const double m = world.masses()[0];
  EXPECT_NEAR(std::remainder(world.angles()[0], kPi), 0.0, 1e-6);
  EXPECT_NEAR(h / 2 - world.positions()[0].y(), m * kG / kn, 1e-4 * m * kG / kn);
}

TEST(Extremes, FiveToOneRectangleRestsOnAnotherWithinBox2dFloatTolerance) {
  // The same block on a fixed copy of itself: the polygon pair goes through Box2D in single
  // precision, in a frame scaled to about one unit per particle, so the overlap is known to
  // a few float epsilons of the circumradius.
  const double kn = 1e7, w = 0.010, h = 0.002;
  World world(test::material(kn, 0.3, 0.5));
  ParticleSpec base = box(w, h, {0, 0});
  base.motion = Motion::Fixed;
  world.addParticle(base);
  world.addParticle(box(w, h, {0, h}));
  world.setGravity({0, -kG});
  while (world.time() < 0.5) world.step();
  world.checkHealth();
  const double m = world.masses()[1];
  const double circumradius = 0.5 * std::hypot(w, h);
  const double tolerance = 1e-4 * m * kG / kn + 16 * FLT_EPSILON * circumradius;
  EXPECT_NEAR(std::remainder(world.angles()[1], kPi), 0.0, 1e-5);
  EXPECT_NEAR(h - world.positions()[1].y(), m * kG / kn, tolerance);
}

// ---- confining stress ----

// circular-quick's compaction and consolidation to `pressure` (compaction at 1% of it).
Scene consolidationTo(double pressure) {
  nlohmann::json j = presetScene("circular-quick");
  j["stages"] = nlohmann::json::array({j["stages"][0], j["stages"][1]});
  j["stages"][0]["pressure"] = 0.01 * pressure;
  j["stages"][1]["pressure"] = pressure;
  j["output"]["histograms"] = false;
  return parseScene(j);
}

TEST(Extremes, ConsolidationToOneKilopascal) {
  const double p = 1e3;
  const Scene scene = consolidationTo(p);
  Recorder rec;
  const RunSummary s = runScene(scene, rec);
  ASSERT_EQ(s.status, RunStatus::Completed) << s.error;
  EXPECT_TRUE(s.notes.empty()) << s.notes.front();  // ended on its criterion, not a time limit
  EXPECT_NEAR(rec.lastP, p, 0.01 * p);
  EXPECT_FALSE(rec.hasNonFinite());
  // The mean contact force of discs at pressure p is about 2π r p / (Z φ) (Z ≈ 4, φ ≈ 0.8):
  // δ/r ≈ 2π p / (3.2 k_n) ≈ 7e-6 here. Force chains carry a few times the mean.
  const double r = 0.002, kn = scene.material.normalStiffness;
  const double meanRelative = 2 * kPi * p / (3.2 * kn);
  double worst = 0;
  for (const ContactRecord& c : rec.contacts) worst = std::max(worst, c.overlap / r);
  EXPECT_GT(rec.contacts.size(), 100u);
  EXPECT_LT(worst, 10 * meanRelative);
}

TEST(Extremes, ConsolidationToOneHundredMegapascalsCompletesOrSaysWhy) {
  // With k_n = 3e8 the mean overlap at 100 MPa would be about 65% of the radius: past
  // checkHealth's runaway limit (half the smaller radius). The run must either reach the
  // pressure or stop naming the overlap; never NaN.
  const double p = 100e6;
  Recorder rec;
  const RunSummary s = runScene(consolidationTo(p), rec);
  EXPECT_FALSE(rec.hasNonFinite());
  if (s.status == RunStatus::Completed) {
    EXPECT_NEAR(rec.lastP, p, 0.01 * p);
  } else {
    EXPECT_EQ(s.status, RunStatus::Failed);
    EXPECT_NE(s.error.find("overlap"), std::string::npos) << s.error;
  }
}

// ---- initially overlapping particles ----

TEST(Extremes, DiscsStartingSixtyPercentOverlappedAreRefused) {
  // Beyond half a radius checkHealth calls the overlap a runaway: the run must refuse the
  // pair (at the first sample, before any step) and name it.
  Scene scene;
  scene.material = test::material(3e8, 0.5, 0.5);
  const double r = 0.002;
  scene.particles = {disc(r, {0, 0}), disc(r, {1.4 * r, 0})};
  StageSpec free;
  free.name = "free";
  free.duration = 1e-3;
  scene.stages = {free};
  Recorder rec;
  const RunSummary s = runScene(scene, rec);
  EXPECT_FALSE(rec.hasNonFinite());
  // Before 274c9fe the pair was accepted (the first health check saw no pairs yet) and flew
  // apart at 59 m/s.
  EXPECT_EQ(s.status, RunStatus::Failed);
  EXPECT_NE(s.error.find("runaway overlap"), std::string::npos) << s.error;
  EXPECT_NE(s.error.find("particles 0 and 1"), std::string::npos) << s.error;
}

TEST(Extremes, DiscsStartingHalfARadiusOverlappedSpringApartElastically) {
  // At exactly half a radius the overlap is at checkHealth's limit, not past it: the pair is
  // accepted and the spring pushes it apart. With e = 1 the stored energy ½ k_n δ² becomes
  // kinetic energy: each disc leaves at δ √(k_n / (2 m)) (m* = m/2). Not gentle (tens of m/s
  // with k_n = 3e8), but finite, energy-conserving and what the contact law says.
  const double r = 0.002, kn = 3e8, delta = 0.5 * r;
  World world(test::material(kn, 1.0, 0.0));
  world.addParticle(disc(r, {0, 0}));
  world.addParticle(disc(r, {2 * r - delta, 0}));
  world.checkHealth();  // accepted
  for (int k = 0; k < 200; ++k) world.step();
  world.checkHealth();
  ASSERT_TRUE(finiteState(world));
  const double m = world.masses()[0];
  const double expected = delta * std::sqrt(kn / (2 * m));
  // Leapfrog keeps a shadow energy: the speed it reports after separation is high by about
  // (ω dt)² / 8, ω = √(k_n / m*) — 1.4% at the default timestep. Allow twice that.
  const double wdt = std::sqrt(2 * kn / m) * world.timestep();
  const double tolerance = wdt * wdt / 4 * expected;
  EXPECT_NEAR(world.velocities()[1].x(), expected, tolerance);
  EXPECT_NEAR(world.velocities()[0].x(), -expected, tolerance);
  EXPECT_GT((world.positions()[1] - world.positions()[0]).norm(), 2 * r);  // apart
}

// ---- a single particle ----

TEST(Extremes, SingleDiscFallsFreelyThroughTheWholeRun) {
  Scene scene;
  scene.material = test::material(1e8, 0.5, 0.5);
  scene.particles = {disc(0.002, {0, 0}, {0.1, 0})};
  scene.gravity = Vec2(0, -kG);
  StageSpec free;
  free.name = "free";
  free.duration = 0.05;
  scene.stages = {free};
  Recorder rec;
  const RunSummary s = runScene(scene, rec);
  ASSERT_EQ(s.status, RunStatus::Completed) << s.error;
  EXPECT_EQ(s.particles, 1);
  EXPECT_FALSE(rec.hasNonFinite());
  ASSERT_EQ(rec.finalPositions.size(), 1u);
  const double t = 0.05;
  // Time is a whole number of steps just past t; the kick-drift offset is one step (dt/t ≪ 1e-3).
  EXPECT_NEAR(rec.finalPositions[0].x(), 0.1 * t, 1e-3 * 0.1 * t);
  EXPECT_NEAR(rec.finalPositions[0].y(), -0.5 * kG * t * t, 1e-3 * 0.5 * kG * t * t);
  EXPECT_TRUE(rec.contacts.empty());
}

TEST(Extremes, SinglePolygonRestsOnAWallThroughTheWholeRun) {
  Scene scene;
  scene.material = test::material(1e8, 0.5, 0.5);
  const double side = 0.004;
  const double m = 2650 * side * side;
  scene.particles = {box(side, side, {0, side / 2 - m * kG / 1e8})};
  scene.walls = {Wall{Vec2(0, 0), Vec2(0, 1)}};
  scene.gravity = Vec2(0, -kG);
  StageSpec free;
  free.name = "free";
  free.duration = 0.05;
  scene.stages = {free};
  Recorder rec;
  const RunSummary s = runScene(scene, rec);
  ASSERT_EQ(s.status, RunStatus::Completed) << s.error;
  EXPECT_FALSE(rec.hasNonFinite());
  ASSERT_EQ(rec.contacts.size(), 1u);
  EXPECT_NEAR(rec.contacts[0].overlap, m * kG / 1e8, 1e-3 * m * kG / 1e8);
}

}  // namespace
}  // namespace grainlab

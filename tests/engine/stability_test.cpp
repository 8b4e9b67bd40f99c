// A diverging simulation stops with a message that says why, and writes no NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "engine/world_helpers.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"

namespace grainlab {
namespace {

class RowCollector : public RunObserver {
 public:
  void onSample(const Sample& s, const World&) override { rows += formatSeriesRow(s) + "\n"; }
  std::string rows;
};

// The jammed lattice: beyond the critical timestep its stored energy blows up.
Scene jammed(double timestepOverCritical) {
  Scene scene;
  scene.material = test::material(1e8, 1.0, 0.5);
  scene.particles = test::jammedLattice(10, scene.walls);
  World probe(scene.material);
  for (const ParticleSpec& p : scene.particles) probe.addParticle(p);
  scene.solver.timestep = timestepOverCritical * probe.criticalTimestep();
  StageSpec free;
  free.name = "free";
  free.duration = 3000 * scene.solver.timestep;
  scene.stages = {free};
  scene.output.sampleInterval = 10 * scene.solver.timestep;
  return scene;
}

TEST(Stability, TimestepBeyondCriticalFailsWithReasonAndNoNaN) {
  RowCollector rows;
  const RunSummary s = runScene(jammed(3.0), rows);
  EXPECT_EQ(s.status, "failed");
  EXPECT_NE(s.error.find("timestep"), std::string::npos) << s.error;
  EXPECT_EQ(rows.rows.find("nan"), std::string::npos);
  EXPECT_EQ(rows.rows.find("inf"), std::string::npos);
}

TEST(Stability, TimestepBelowCriticalCompletes) {
  RowCollector rows;
  EXPECT_EQ(runScene(jammed(0.2), rows).status, "completed");
}

TEST(Stability, CriticalTimestepMatchesTheStiffestLightestContact) {
  const double r = 0.002, kn = 1e8, kt = 5e7;
  World world(test::material(kn, 1.0, 0.5, kt));
  world.addParticle(test::disc(r, {0, 0}));
  world.addParticle(test::disc(2 * r, {1, 0}));
  const double m = 2650 * kPi * r * r;  // the lighter disc; rotational factor 1 + m r²/I = 3
  EXPECT_NEAR(world.criticalTimestep(), 2 * std::sqrt(0.5 * m / std::max(kn, 3 * kt)), 1e-15);
  EXPECT_NEAR(world.timestep(), 0.2 * world.criticalTimestep(), 1e-18);
}

TEST(Stability, PolygonCriticalTimestepSeesTheNormalSpringThroughRotation) {
  // A square of side s: I = m s²/6 and R = s/√2, so 1 + m R²/I = 4 for both springs.
  const double side = 0.004, kn = 1e8, kt = 5e7;
  World world(test::material(kn, 1.0, 0.5, kt));
  world.addParticle(test::box(side, side, {0, 0}));
  const double m = 2650 * side * side;
  EXPECT_NEAR(world.criticalTimestep(), 2 * std::sqrt(0.5 * m / (4 * kn)), 1e-15);
}

}  // namespace
}  // namespace grainlab

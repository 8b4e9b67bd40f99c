// The wide contact path (disc pairs in batches, several per instruction) does the scalar
// loop's operations in the same order, lane by lane, with no fused multiply-add: it must give
// the baseline's bits, serially and threaded, with friction or without, with local damping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"
#include "disc_pair_kernel.hpp"
#include "simd_path.hpp"

namespace grainlab {
namespace {

// Every series row as text, and the bits of every final position, velocity, spin and contact.
class Recorder : public RunObserver {
 public:
  void onSample(const Sample& s, const World&) override { rows += formatSeriesRow(s) + "\n"; }
  void onFinish(const RunSummary&, const World& world) override {
    for (const Vec2& x : world.positions()) mix(x.data(), 2);
    for (const Vec2& v : world.velocities()) mix(v.data(), 2);
    for (double w : world.spins()) mix(&w, 1);
    std::vector<ContactRecord> contacts;
    world.contacts(contacts);
    this->contacts = contacts.size();
    for (const ContactRecord& c : contacts) {
      const double values[] = {c.fn, c.ft, c.overlap, c.point.x(), c.point.y()};
      mix(values, 5);
    }
  }
  std::string rows;
  std::uint64_t hash = 1469598103934665603ull;
  size_t contacts = 0;

 private:
  void mix(const double* v, int n) {
    for (int k = 0; k < n; ++k) {
      std::uint64_t bits;
      std::memcpy(&bits, v + k, sizeof bits);
      hash = (hash ^ bits) * 1099511628211ull;
    }
  }
};

// A shuffled disc pile pressed 8% closer than its lattice under 50 g: in contact, sliding and
// rebuilding its neighbour list through the run (as in the determinism tests).
Scene pressedPile() {
  Scene scene = pileScene(16, 16, false);
  std::mt19937_64 rng(7);
  std::shuffle(scene.particles.begin(), scene.particles.end(), rng);
  for (ParticleSpec& p : scene.particles) p.position *= 0.92;
  scene.gravity *= 50;
  scene.stages[0].duration = 0.01;  // s
  return scene;
}

Recorder runOn(SimdPath path, const Scene& scene) {
  overrideSimdPath(path);
  Recorder r;
  const RunStatus status = runScene(scene, r).status;
  overrideSimdPath(std::nullopt);
  EXPECT_EQ(status, RunStatus::Completed);
  return r;
}

class WidePath : public ::testing::Test {
 protected:
  void SetUp() override {
    overrideSimdPath(SimdPath::Wide);
    const bool built = simdPath() == SimdPath::Wide;
    overrideSimdPath(std::nullopt);
    if (!built) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  }
};

TEST_F(WidePath, GivesTheBaselinesBitsWithAnyThreadCount) {
  Scene scene = pressedPile();
  const Recorder baseline = runOn(SimdPath::Baseline, scene);
  ASSERT_GT(baseline.contacts, 100u);  // the pile is in contact at the end
  for (int threads : {1, 2, 3}) {
    scene.solver.threads = threads;
    const Recorder wide = runOn(SimdPath::Wide, scene);
    EXPECT_EQ(baseline.hash, wide.hash) << threads << " threads (on " << discPairKernelTarget() << ")";
    EXPECT_EQ(baseline.rows, wide.rows) << threads << " threads";
  }
}

TEST_F(WidePath, GivesTheBaselinesBitsWithoutFrictionAndWithLocalDamping) {
  for (const bool frictionless : {true, false}) {
    Scene scene = pressedPile();
    if (frictionless) scene.material.friction = 0;
    else scene.material.localDamping = 0.3;
    const Recorder baseline = runOn(SimdPath::Baseline, scene);
    const Recorder wide = runOn(SimdPath::Wide, scene);
    const std::string what = frictionless ? "frictionless" : "local damping";
    EXPECT_EQ(baseline.hash, wide.hash) << what;
    EXPECT_EQ(baseline.rows, wide.rows) << what;
  }
}

}  // namespace
}  // namespace grainlab

// The same scene and seed give bit-identical results.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

// Collects every series row as text, and the final positions' bits.
class Recorder : public RunObserver {
 public:
  void onSample(const Sample& s, const World&) override { rows += formatSeriesRow(s) + "\n"; }
  void onFinish(const RunSummary&, const World& world) override {
    for (const Vec2& x : world.positions()) {
      std::uint64_t bits[2];
      std::memcpy(bits, x.data(), sizeof bits);
      hash = (hash ^ bits[0]) * 1099511628211ull;
      hash = (hash ^ bits[1]) * 1099511628211ull;
    }
  }
  std::string rows;
  std::uint64_t hash = 1469598103934665603ull;
};

TEST(Determinism, QuickPresetRepeatsBitForBit) {
  Scene scene = parseScene(presetScene("elongated-bedding-30-quick"));
  scene.stages.resize(2);  // compaction and consolidation suffice to exercise everything
  Recorder a, b;
  ASSERT_EQ(runScene(scene, a).status, RunStatus::Completed);
  ASSERT_EQ(runScene(scene, b).status, RunStatus::Completed);
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_EQ(a.rows, b.rows);
  EXPECT_GT(a.rows.size(), 1000u);
}

TEST(Determinism, ThreadCountDoesNotChangeABit) {
  for (const char* preset : {"circular-quick", "elongated-random-quick"}) {
    Scene scene = parseScene(presetScene(preset));
    scene.stages.resize(1);  // compaction: the preset's own membrane and servo, loose still
    scene.stages[0].maxTime = 0.05;
    Recorder serial, parallel;
    ASSERT_EQ(runScene(scene, serial).status, RunStatus::Completed);
    scene.solver.threads = 2;
    ASSERT_EQ(runScene(scene, parallel).status, RunStatus::Completed);
    EXPECT_EQ(serial.hash, parallel.hash) << preset;
    EXPECT_EQ(serial.rows, parallel.rows) << preset;
  }
}

// A dense pile whose particle indices are shuffled, so that neighbours' indices are far apart:
// with several threads most particles then straddle slices of the pair list, and their shares
// computed by other threads wait and are added after the loop. (The presets above start loose:
// their first stage has few contacts.) Adding the waiting shares in reverse, or letting the
// thread of a particle's last pair add its shares at once, each fail this test (checked).
TEST(Determinism, ThreadCountDoesNotChangeABitInAShuffledPile) {
  for (const char* kind : {"discs", "polygons", "discs with rolling resistance"}) {
    const bool polygons = std::string(kind) == "polygons";
    Scene scene = pileScene(16, 16, polygons);
    if (std::string(kind) == "discs with rolling resistance") {  // the couple goes the same way
      scene.material.rollingFriction = 0.1;
      scene.material.rollingDamping = 0.3;
    }
    std::mt19937_64 rng(7);
    std::shuffle(scene.particles.begin(), scene.particles.end(), rng);
    // Pressed 8% closer than the lattice, neighbours overlap from the start and push apart
    // while 50 g packs them down: the pile stays in contact through the run (at its end, 233
    // contacts among the 256 discs, 103 among the hexagons).
    for (ParticleSpec& p : scene.particles) p.position *= 0.92;
    scene.gravity *= 50;
    scene.stages[0].duration = 0.01;  // s
    Recorder serial;
    ASSERT_EQ(runScene(scene, serial).status, RunStatus::Completed);
    for (int threads : {2, 3}) {
      Recorder parallel;
      scene.solver.threads = threads;
      ASSERT_EQ(runScene(scene, parallel).status, RunStatus::Completed);
      const std::string what = std::string(kind) + ", " + std::to_string(threads) + " threads";
      EXPECT_EQ(serial.hash, parallel.hash) << what;
      EXPECT_EQ(serial.rows, parallel.rows) << what;
    }
  }
}

TEST(Determinism, DifferentSeedGivesDifferentSpecimen) {
  Scene scene = parseScene(presetScene("circular-quick"));
  StageSpec free;
  free.name = "free";
  free.duration = 1e-4;
  scene.stages = {free};
  Recorder a, b;
  runScene(scene, a);
  scene.seed = 2;
  runScene(scene, b);
  EXPECT_NE(a.hash, b.hash);
}

}  // namespace
}  // namespace grainlab

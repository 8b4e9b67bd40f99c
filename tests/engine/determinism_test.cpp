// The same scene and seed give bit-identical results.
#include <gtest/gtest.h>

#include <cstring>

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
  ASSERT_EQ(runScene(scene, a).status, "completed");
  ASSERT_EQ(runScene(scene, b).status, "completed");
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_EQ(a.rows, b.rows);
  EXPECT_GT(a.rows.size(), 1000u);
}

TEST(Determinism, ThreadCountDoesNotChangeABit) {
  for (const char* preset : {"circular-quick", "elongated-random-quick"}) {
    Scene scene = parseScene(presetScene(preset));
    scene.stages.resize(1);  // compaction: thousands of steps with contacts forming
    scene.stages[0].maxTime = 0.05;
    Recorder serial, parallel;
    ASSERT_EQ(runScene(scene, serial).status, "completed");
    scene.solver.threads = 2;
    ASSERT_EQ(runScene(scene, parallel).status, "completed");
    EXPECT_EQ(serial.hash, parallel.hash) << preset;
    EXPECT_EQ(serial.rows, parallel.rows) << preset;
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

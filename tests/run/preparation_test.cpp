// The paper's preparation (section 4): a frictionless compaction that stops when the
// particles are close with no force between them, then consolidation to 300 kPa with
// μ = 0.5 until the volume stops changing. Run through consolidation only (no shearing):
// 1-2 s (circular-quick) and 10-25 s (elongated-bedding-30-quick) on one core, loaded.
#include <gtest/gtest.h>

#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

size_t column(const std::string& name) { return seriesColumnIndex(name); }

class PreparationProbe : public RunObserver {
 public:
  void onSample(const Sample& s, const World&) override {
    if (s.stage == "compaction") compactionEnd = s.values;  // the last one is the stage's end
  }
  std::vector<double> compactionEnd;
};

struct Prepared {
  RunSummary summary;
  std::vector<double> compactionEnd;
};

Prepared prepare(const std::string& preset) {
  nlohmann::json scene = presetScene(preset);
  scene["stages"].erase(2);  // shearing
  PreparationProbe probe;
  Prepared out{runScene(parseScene(scene), probe), {}};
  out.compactionEnd = probe.compactionEnd;
  return out;
}

// The presets' compaction end: the void ratio inside the ring at which it stops
// (docs/biaxial-test.md, "Preparation").
constexpr double kCompactionVoidRatio = 0.40;
constexpr double kConsolidation = 300e3;  // Pa

void checkCompactionEnd(const Prepared& run) {
  ASSERT_EQ(run.summary.status, RunStatus::Completed) << run.summary.error;
  EXPECT_TRUE(run.summary.notes.empty()) << run.summary.notes.front();
  ASSERT_FALSE(run.compactionEnd.empty());
  // Stopped by the void ratio, not by the pressure backstop. Between two stress
  // measurements (20 steps) the ring closes in by 2·ε̇·20·dt ≈ 2e-4 of the area at 2 s⁻¹.
  const double e = run.compactionEnd[column("void_ratio")];
  EXPECT_LE(e, kCompactionVoidRatio + 1e-9);
  EXPECT_GT(e, kCompactionVoidRatio - 2e-3);
  // "No inter-force": the mean stress, and with it the mean contact force (f ∝ p for a given
  // packing), is below 1% of the consolidation's: overlaps under 1e-5 of the particle size.
  EXPECT_LT(run.compactionEnd[column("p")], 0.01 * kConsolidation);
  // Loose enough that the frictional consolidation builds the packing: it compacts further.
  EXPECT_LT(run.summary.voidRatioAfterConsolidation, e - 0.05);
}

// The 60 mm quick specimens are not the paper's; their void ratios after consolidation are
// held to their own seed scatter, mean ± 3 standard deviations over 8 seeds
// (docs/biaxial-test.md). The old preparation, compaction to 3 kPa, falls outside both.
TEST(Preparation, CircularQuickCompactsCloseWithAlmostNoForce) {
  const Prepared run = prepare("circular-quick");
  checkCompactionEnd(run);
  // 8 seeds: 0.2728 ± 0.0040 (0.268-0.278); the 3 kPa end gave 0.259.
  EXPECT_GT(run.summary.voidRatioAfterConsolidation, 0.261);
  EXPECT_LT(run.summary.voidRatioAfterConsolidation, 0.285);
}

TEST(Preparation, ElongatedBeddingQuickCompactsCloseWithAlmostNoForce) {
  const Prepared run = prepare("elongated-bedding-30-quick");
  checkCompactionEnd(run);
  // 8 seeds: 0.2757 ± 0.0124 (0.263-0.296), around the paper's 0.264-0.272 for its
  // elongated specimens; the 3 kPa end gave 0.227.
  EXPECT_GT(run.summary.voidRatioAfterConsolidation, 0.238);
  EXPECT_LT(run.summary.voidRatioAfterConsolidation, 0.313);
}

TEST(Preparation, CompactionVoidRatioMustBePositive) {
  nlohmann::json scene = presetScene("circular-quick");
  scene["stages"][0]["void_ratio"] = 0;
  try {
    parseScene(scene);
    FAIL() << "accepted void_ratio 0";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.field(), "stages[0].void_ratio");
  }
}

}  // namespace
}  // namespace grainlab

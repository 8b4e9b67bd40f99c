// PreparedShearing (grainlab bench --scene ring-cell times what it prepares) must hand over
// exactly the state a run of the same scene begins its shearing from: the same positions and
// angles to the bit, and the same void ratio. A run samples the end of each stage; the
// shearing starts from the consolidation's last sample (its own first row comes one sample
// spacing later: a stage's start sample is skipped when it falls on the step just sampled).
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "grainlab/errors.hpp"
#include "grainlab/prepared_shearing.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"

namespace grainlab {
namespace {

// The consolidation's last sample; the run is cancelled once the shearing has begun.
class ShearingStart : public RunObserver {
 public:
  void onSample(const Sample& s, const World& w) override {
    if (s.stage == "shearing") {
      sheared = true;
      return;
    }
    if (s.stage != "consolidation") return;
    positions.assign(w.positions().begin(), w.positions().end());
    angles.assign(w.angles().begin(), w.angles().end());
    voidRatio = s.values[seriesColumnIndex("void_ratio")];
    step = w.stepCount();
  }
  bool cancelRequested() override { return sheared; }
  bool sheared = false;
  std::vector<Vec2> positions;
  std::vector<double> angles;
  double voidRatio = 0;
  std::int64_t step = 0;
};

void checkSameStart(const std::string& preset) {
  const Scene scene = parseScene(presetScene(preset));
  ShearingStart run;
  runScene(scene, run);
  ASSERT_TRUE(run.sheared) << preset << ": the run reached no shearing";
  PreparedShearing prepared(scene);
  const World& w = prepared.world();
  EXPECT_EQ(w.stepCount(), run.step) << preset;
  ASSERT_EQ(static_cast<size_t>(w.size()), run.positions.size());
  EXPECT_EQ(0, std::memcmp(w.positions().data(), run.positions.data(), run.positions.size() * sizeof(Vec2))) << preset;
  EXPECT_EQ(0, std::memcmp(w.angles().data(), run.angles.data(), run.angles.size() * sizeof(double))) << preset;
  EXPECT_EQ(prepared.voidRatio(), run.voidRatio) << preset;
  EXPECT_EQ(prepared.shearing().name(), "shearing");
}

TEST(PreparedShearing, InTheRingIsTheStateARunShears) { checkSameStart("circular-quick"); }
TEST(PreparedShearing, InTheCellIsTheStateARunShears) { checkSameStart("periodic-biaxial-circular-quick"); }

TEST(PreparedShearing, RefusesASceneWithoutShearingByField) {
  nlohmann::json scene = presetScene("circular-quick");
  scene["stages"].erase(2);  // shearing
  try {
    PreparedShearing prepared(parseScene(scene));
    FAIL() << "a scene without shearing was prepared";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.field(), "stages");
  }
}

}  // namespace
}  // namespace grainlab

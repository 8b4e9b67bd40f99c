// The paper's biaxial test end to end on the quick presets: consolidation to 300 kPa, then
// shearing to 20% axial strain with σ11 held, quasi-static, and no particle leaving.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

size_t column(const std::string& name) { return seriesColumnIndex(name); }

class BiaxialProbe : public RunObserver {
 public:
  void onSample(const Sample& s, const World&) override {
    if (s.stage == "shearing") shearing.push_back(s.values);
  }
  void onFinish(const RunSummary&, const World& world) override {
    // Every specimen particle inside the polygon of the ring's centres (ray casting).
    std::vector<Vec2> ring;
    Vec2 centre = Vec2::Zero();
    for (int k = 0; k < world.size(); ++k) {
      if (world.boundaryFlags()[k]) ring.push_back(world.positions()[k]), centre += world.positions()[k];
    }
    centre /= static_cast<double>(ring.size());
    std::sort(ring.begin(), ring.end(), [&](const Vec2& a, const Vec2& b) {
      return std::atan2(a.y() - centre.y(), a.x() - centre.x()) < std::atan2(b.y() - centre.y(), b.x() - centre.x());
    });
    for (int k = 0; k < world.size(); ++k) {
      if (world.boundaryFlags()[k]) continue;
      const Vec2& p = world.positions()[k];
      bool inside = false;
      for (size_t a = 0, b = ring.size() - 1; a < ring.size(); b = a++) {
        if ((ring[a].y() > p.y()) != (ring[b].y() > p.y()) &&
            p.x() < (ring[b].x() - ring[a].x()) * (p.y() - ring[a].y()) / (ring[b].y() - ring[a].y()) + ring[a].x()) {
          inside = !inside;
        }
      }
      escaped += inside ? 0 : 1;
    }
  }
  std::vector<std::vector<double>> shearing;
  int escaped = 0;
};

void checkBiaxial(const std::string& preset) {
  BiaxialProbe probe;
  const RunSummary summary = runScene(parseScene(presetScene(preset)), probe);
  ASSERT_EQ(summary.status, "completed") << summary.error;
  EXPECT_TRUE(summary.notes.empty()) << summary.notes.front();  // every stage met its criterion
  EXPECT_GT(summary.voidRatioAfterConsolidation, 0.1);
  EXPECT_LT(summary.voidRatioAfterConsolidation, 0.4);
  ASSERT_GT(probe.shearing.size(), 20u);
  EXPECT_NEAR(probe.shearing.back()[column("axial_strain")], 0.2, 0.01);
  EXPECT_EQ(probe.escaped, 0);

  std::vector<double> s11, inertial;
  for (const auto& row : probe.shearing) {
    s11.push_back(row[column("sigma11")]);
    // Compression along 2 against a constant lateral stress: σ22 > σ11 once shearing is
    // under way, and the specimen widens laterally (lateral strain < 0 after the start).
    if (row[column("axial_strain")] > 0.02) {
      EXPECT_GT(row[column("sigma22")], row[column("sigma11")]);
      EXPECT_LT(row[column("lateral_strain")], 0.0);
    }
    EXPECT_GE(row[column("phi_mob_deg")], 0.0);
    inertial.push_back(row[column("inertial_number")]);
  }
  // Quasi-static: the inertial number at or below 1e-3. Its median, not every sample: a
  // small specimen's force network can collapse now and then (p drops, the lateral servo
  // races), and such a sample is not what sets the loading regime.
  std::nth_element(inertial.begin(), inertial.begin() + inertial.size() / 2, inertial.end());
  EXPECT_LE(inertial[inertial.size() / 2], 1e-3);
  // The servo holds σ11 at the confining 300 kPa: its median over shearing within 2%.
  std::nth_element(s11.begin(), s11.begin() + s11.size() / 2, s11.end());
  EXPECT_NEAR(s11[s11.size() / 2], 300e3, 0.02 * 300e3);
  // Mobilised friction: an assembly with μ = 0.5 shears at some tens of degrees (freely
  // rolling discs lowest).
  // The median over shearing past 2% strain is the robust figure; a few-hundred-particle
  // specimen's peak can spike well above it when a strong column forms (52° seen at 19%
  // strain on elongated-bedding-30-quick), so the peak only has to stay below 60°.
  std::vector<double> phi;
  for (const auto& row : probe.shearing) {
    if (row[column("axial_strain")] > 0.02) phi.push_back(row[column("phi_mob_deg")]);
  }
  std::nth_element(phi.begin(), phi.begin() + phi.size() / 2, phi.end());
  EXPECT_GT(phi[phi.size() / 2], 10.0);  // discs without rolling resistance: 14° (circular-quick)
  EXPECT_LT(phi[phi.size() / 2], 45.0);
  EXPECT_LT(summary.peakPhiMobDeg, 60.0);
}

TEST(Biaxial, CircularQuickShearsToTwentyPercent) { checkBiaxial("circular-quick"); }
TEST(Biaxial, ElongatedBeddingQuickShearsToTwentyPercent) { checkBiaxial("elongated-bedding-30-quick"); }

}  // namespace
}  // namespace grainlab

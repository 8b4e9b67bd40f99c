// The paper's biaxial test end to end on the quick presets: consolidation to 300 kPa, then
// shearing to 20% axial strain with σ11 held, quasi-static, and no particle leaving.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"

#include "../support/ring_escapees.hpp"

namespace grainlab {
namespace {

size_t column(const std::string& name) { return seriesColumnIndex(name); }

class BiaxialProbe : public RunObserver {
 public:
  void onSample(const Sample& s, const World&) override {
    if (s.stage == "shearing") shearing.push_back(s.values);
  }
  void onFinish(const RunSummary&, const World& world) override {
    escaped = grainlab::testing::particlesOutsideRing(world);
  }
  std::vector<std::vector<double>> shearing;
  int escaped = 0;
};

// `minWithin` is the fraction of shearing samples at which σ11 must be within 2% of 300 kPa.
// Ideally every sample; what stops that is physics, not the servo. A specimen of a few
// hundred particles now and then loses a large part of its force network within about one
// wave crossing (σ22 falls by tens of percent, in the worst case to zero, and kinetic energy
// jumps 100-1000×). σ11 falls with it before any boundary can know: the stress wave has to
// reach the ring, and the ring may then close in only at the quasi-static cap. Over every
// stress measurement (not just samples) σ11 is within 2% 99% of the time for the quick discs
// and 95-96% for the quick elongated specimens (docs/biaxial-test.md): 40 samples then miss
// 0.4 and 1.8 times on average, and fall below 95% (discs) or 85% (elongated) with
// probability under 1%.
void checkBiaxial(const std::string& preset, double minWithin) {
  BiaxialProbe probe;
  const RunSummary summary = runScene(parseScene(presetScene(preset)), probe);
  ASSERT_EQ(summary.status, RunStatus::Completed) << summary.error;
  EXPECT_TRUE(summary.notes.empty()) << summary.notes.front();  // every stage met its criterion
  EXPECT_GT(summary.voidRatioAfterConsolidation, 0.1);
  EXPECT_LT(summary.voidRatioAfterConsolidation, 0.4);
  ASSERT_GT(probe.shearing.size(), 20u);
  EXPECT_NEAR(probe.shearing.back()[column("axial_strain")], 0.2, 0.01);
  EXPECT_EQ(probe.escaped, 0);

  const double target = 300e3;
  std::vector<double> deviation;
  size_t within = 0;
  bool previousOff = false;
  for (const auto& row : probe.shearing) {
    const double s11 = row[column("sigma11")], strain = row[column("axial_strain")];
    const double dev = std::abs(s11 - target) / target;
    deviation.push_back(dev);
    const bool off = dev > 0.02;
    within += off ? 0 : 1;
    // A collapse is over by the next sample: 0.005 strain apart is ~20 wave crossings, in
    // which the ring can close in by ≥ 0.01 strain at its cap, while reloading after the
    // largest collapse measured took ~0.003.
    EXPECT_FALSE(off && previousOff) << "σ11 off by more than 2% at two samples in a row, ε22 = " << strain;
    previousOff = off;
    // Quasi-static: I ≤ 1e-3 wherever σ11 is held (p ≥ σ11 then, and the lateral cap keeps I
    // at 0.8e-3 of it). During a collapse p itself falls, and with it the denominator of I.
    if (!off) {
      EXPECT_LE(row[column("inertial_number")], 1e-3) << "at ε22 = " << strain;
    }
    // Compression along 2 against a constant lateral stress: σ22 > σ11 once shearing is
    // under way, and the specimen widens laterally (lateral strain < 0 after the start).
    if (strain > 0.02 && !off) {
      EXPECT_GT(row[column("sigma22")], s11) << "at ε22 = " << strain;
      EXPECT_LT(row[column("lateral_strain")], 0.0) << "at ε22 = " << strain;
    }
    EXPECT_GE(row[column("phi_mob_deg")], 0.0);
  }
  EXPECT_GE(static_cast<double>(within), minWithin * static_cast<double>(deviation.size()))
      << within << " of " << deviation.size() << " samples within 2% of 300 kPa";
  // Between collapses the integral action leaves no offset: the median within 0.5%.
  std::nth_element(deviation.begin(), deviation.begin() + deviation.size() / 2, deviation.end());
  EXPECT_LE(deviation[deviation.size() / 2], 0.005);
  // Mobilised friction: an assembly with μ = 0.5 shears at some tens of degrees (freely
  // rolling discs lowest). The median over shearing past 2% strain is the robust figure; a
  // few-hundred-particle specimen's peak can spike well above it when a strong column forms
  // (52° seen at 19% strain on elongated-bedding-30-quick), so the peak need only stay below 60°.
  std::vector<double> phi;
  for (const auto& row : probe.shearing) {
    if (row[column("axial_strain")] > 0.02) phi.push_back(row[column("phi_mob_deg")]);
  }
  std::nth_element(phi.begin(), phi.begin() + phi.size() / 2, phi.end());
  EXPECT_GT(phi[phi.size() / 2], 10.0);  // discs without rolling resistance: 14° (circular-quick)
  EXPECT_LT(phi[phi.size() / 2], 45.0);
  EXPECT_LT(summary.peakPhiMobDeg, 60.0);
}

TEST(Biaxial, CircularQuickShearsToTwentyPercent) { checkBiaxial("circular-quick", 0.95); }
TEST(Biaxial, ElongatedBeddingQuickShearsToTwentyPercent) { checkBiaxial("elongated-bedding-30-quick", 0.85); }
TEST(Biaxial, ElongatedRandomQuickShearsToTwentyPercent) { checkBiaxial("elongated-random-quick", 0.85); }

}  // namespace
}  // namespace grainlab

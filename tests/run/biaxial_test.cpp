// The paper's biaxial test end to end on the quick presets: consolidation to 300 kPa, then
// shearing to 20% axial strain with σ11 held, quasi-static, and no particle leaving.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "grainlab/presets.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"

#include "../support/ring_escapees.hpp"

namespace grainlab {
namespace {

size_t column(const std::string& name) { return seriesColumnIndex(name); }

// The mean stress of a disc packing computed here from the geometry alone: every overlap
// δ = r_i + r_j − |x_i − x_j| > 0 carries k_n δ (the scene's linear law; its damping part
// vanishes at rest), each end on a specimen particle with branch length r − δ/2, so
// p = (1/2A) Σ_ends k_n δ (r − δ/2): Eq. (1)'s trace, to which tangential forces add nothing for
// discs (l ∥ n). A stiffness the engine applied wrongly by 20% puts the reported p 20% off this.
double meanStressFromOverlaps(const World& world, double area) {
  const auto x = world.positions();
  const auto r = world.boundingRadii();
  const auto boundary = world.boundaryFlags();
  const double kn = world.material().normalStiffness;
  double sum = 0;
  for (int i = 0; i < world.size(); ++i) {
    for (int j = i + 1; j < world.size(); ++j) {
      if (boundary[i] && boundary[j]) continue;
      const double delta = r[i] + r[j] - (x[j] - x[i]).norm();
      if (delta <= 0) continue;
      if (!boundary[i]) sum += kn * delta * (r[i] - delta / 2);
      if (!boundary[j]) sum += kn * delta * (r[j] - delta / 2);
    }
  }
  return sum / (2 * area);
}

class BiaxialProbe : public RunObserver {
 public:
  explicit BiaxialProbe(bool discs = false) : discs_(discs) {}
  void onSample(const Sample& s, const World& world) override {
    if (s.stage != "shearing") return;
    shearing.push_back(s.values);
    if (!discs_) return;
    const double p = s.values[column("p")];
    worstOverlapStress = std::max(worstOverlapStress, std::abs(meanStressFromOverlaps(world, s.values[column("area")]) / p - 1));
  }
  void onFinish(const RunSummary&, const World& world) override {
    escaped = grainlab::testing::particlesOutsideRing(world);
  }
  std::vector<std::vector<double>> shearing;
  int escaped = 0;
  double worstOverlapStress = 0;  ///< largest |p(overlaps)/p − 1| over the shearing samples (discs)

 private:
  bool discs_;
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
// 95 % prediction intervals (mean ± t·s·√(1 + 1/n)) of one more run, from a reference ensemble
// of the preset's seeds 2-N (tests/support/biaxial_reference_ensemble.py GRAINLAB PRESET dem, at
// f2feb20); the test runs seed 1.
struct Reference {
  double voidRatioLow, voidRatioHigh;  // after consolidation
  double phiLow, phiHigh;              // median φ_mob past 2% axial strain, degrees
};

void checkBiaxial(const std::string& preset, double minWithin, const Reference& reference) {
  BiaxialProbe probe(preset == "circular-quick");
  const RunSummary summary = runScene(parseScene(presetScene(preset)), probe);
  ASSERT_EQ(summary.status, RunStatus::Completed) << summary.error;
  EXPECT_TRUE(summary.notes.empty()) << summary.notes.front();  // every stage met its criterion
  EXPECT_GT(summary.voidRatioAfterConsolidation, reference.voidRatioLow);
  EXPECT_LT(summary.voidRatioAfterConsolidation, reference.voidRatioHigh);
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
  // Mobilised friction: within the reference ensemble's interval. The median over shearing past
  // 2% strain is the robust figure; a
  // few-hundred-particle specimen's peak can spike well above it when a strong column forms
  // (52° seen at 19% strain on elongated-bedding-30-quick), so the peak need only stay below 60°.
  std::vector<double> phi;
  for (const auto& row : probe.shearing) {
    if (row[column("axial_strain")] > 0.02) phi.push_back(row[column("phi_mob_deg")]);
  }
  std::nth_element(phi.begin(), phi.begin() + phi.size() / 2, phi.end());
  EXPECT_GT(phi[phi.size() / 2], reference.phiLow);
  EXPECT_LT(phi[phi.size() / 2], reference.phiHigh);
  EXPECT_LT(summary.peakPhiMobDeg, 60.0);
  if (preset == "circular-quick") {
    // The overlaps carry the springs' share of the contact forces; the dashpots carry the rest.
    // At a contact c_n v_n / (k_n δ) = 2ζ (v_n / δ) / ω, which with v_n ~ ε̇ d and δ ~ p d / k_n
    // is about 2ζ I √(k_n / p) at inertial number I. The loop above holds I ≤ 1e-3 while σ11
    // is held, so the share stays below 2ζ · 1e-3 · √(k_n / p): 1.4e-2 for this preset, where
    // 6.5e-4 (f2feb20) to 3.3e-3 were measured. A stress that missed a term would be off by O(1).
    const Material material = parseScene(presetScene(preset)).material;
    const double zeta = -std::log(material.restitution) / std::hypot(M_PI, std::log(material.restitution));
    const double dashpotShare = 2 * zeta * 1e-3 * std::sqrt(material.normalStiffness / target);
    std::printf("worst |p(overlaps)/p − 1| over the shearing: %.2e (bound %.2e)\n", probe.worstOverlapStress, dashpotShare);
    EXPECT_LT(probe.worstOverlapStress, dashpotShare);
  }
}

// Seeds 2-12: e = 0.2731 ± 0.0043 (sd), median φ_mob 14.94° ± 1.90°.
TEST(Biaxial, CircularQuickShearsToTwentyPercent) { checkBiaxial("circular-quick", 0.95, {0.2631, 0.2832, 10.51, 19.38}); }
// Seeds 2-12 at 82beaae (presets' series byte-identical to f2feb20's): e = 0.2786 ± 0.0129 (sd),
// median φ_mob 31.43° ± 3.67°. Friction halved (μ = 0.25) gives e = 0.2438, outside.
TEST(Biaxial, ElongatedBeddingQuickShearsToTwentyPercent) {
  checkBiaxial("elongated-bedding-30-quick", 0.85, {0.2487, 0.3086, 22.88, 39.97});
}
// Seeds 2-12 at 82beaae: e = 0.2794 ± 0.0109, median φ_mob 30.99° ± 1.89°.
// On the baseline contact path, whose trajectory the collapse bound below was set on. The wide
// path turns polygons incrementally (docs/benchmarks.md), rounding differently, and so follows
// another trajectory of the same physics (8 seeds, no Welch |t| above 1.51): on it this seed
// collapsed at ε22 = 0.15 with σ11 98.6 % then 22.2 % off its target at two samples in a row,
// where the baseline's largest collapse (57 % at ε22 = 0.14) is over by the next sample.
TEST(Biaxial, ElongatedRandomQuickShearsToTwentyPercent) {
  overrideSimdPath(SimdPath::Baseline);
  struct Restore {
    ~Restore() { overrideSimdPath(std::nullopt); }
  } restore;
  checkBiaxial("elongated-random-quick", 0.85, {0.2540, 0.3047, 26.60, 35.39});
}

}  // namespace
}  // namespace grainlab

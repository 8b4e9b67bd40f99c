// The trade-off's measures of a shearing stage as ShearingRecorder keeps it: the start row
// (ε22 = 0) only anchors the interpolation, ω is interpolated the shorter way round, and the
// Pareto front keeps the points no other beats on both cost and error.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "grainlab/studies/tradeoff/metrics.hpp"

namespace grainlab::tradeoff {
namespace {

report::ShearingSeries shearing() {
  report::ShearingSeries s;
  s.setColumn("axial_strain", {0.0, 0.01, 0.03, 0.2});
  s.setColumn("phi_mob_deg", {0, 10, 20, 30});
  s.setColumn("omega_macro_deg", {80, 88, -88, 0});
  s.setColumn("theta_sigma_macro_deg", {0, 90, 90, 90});
  s.setColumn("theta_sigma_micro_deg", {90, 92, 86, 100});
  s.setColumn("inertial_number", {1, 1e-3, 2e-3, 3e-3});
  s.setColumn("kinetic_energy", {5, 1, 2, 3});
  return s;
}

TEST(TradeoffMetrics, MediansLeaveOutTheStartRow) {
  const RunMetrics m = measureRun(shearing(), 31, 0.25);
  EXPECT_DOUBLE_EQ(m.peakPhiMobDeg, 31);
  EXPECT_DOUBLE_EQ(m.voidRatio, 0.25);
  EXPECT_DOUBLE_EQ(m.thetaSigmaGapDeg, 4);  // of 2, 4, 10; the start row's 90 is not counted
  EXPECT_DOUBLE_EQ(m.inertialNumber, 2e-3);
  EXPECT_DOUBLE_EQ(m.kineticEnergy, 2);
}

TEST(TradeoffMetrics, InterpolatesPhiAndOmegaTheShorterWayRound) {
  const RunMetrics m = measureRun(shearing(), 31, 0.25);
  EXPECT_DOUBLE_EQ(m.phiMobAtEndDeg, 30);
  ASSERT_EQ(m.omegaDeg.size(), kOmegaStrains.size());
  EXPECT_NEAR(m.omegaDeg[0], -90, 1e-9);  // 88° to −88° passes through ±90°, not 0°
  EXPECT_NEAR(m.omegaDeg[3], 0, 1e-9);
}

TEST(TradeoffMetrics, AMissingColumnMeasuresNothing) {
  report::ShearingSeries s;
  s.setColumn("axial_strain", {0.0, 0.1, 0.2});
  const RunMetrics m = measureRun(s, 0, -1);
  EXPECT_TRUE(std::isnan(m.phiMobAtEndDeg));
  EXPECT_TRUE(std::isnan(m.thetaSigmaGapDeg));
}

TEST(TradeoffMetrics, ParetoFrontKeepsTheUnbeatenInIncreasingCost) {
  EXPECT_EQ(paretoFront({4, 1, 2, 3, NAN}, {1, 5, 3, 4, 0}), (std::vector<size_t>{1, 2, 0}));
}

}  // namespace
}  // namespace grainlab::tradeoff

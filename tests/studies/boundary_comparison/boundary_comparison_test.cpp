// grainlab boundaries' pieces with closed forms: where a series peaks, its curves on a strain
// grid (linear between samples, directions the shorter way round), an axial mean moved next to
// a reference direction, and each boundary's scene.
#include <gtest/gtest.h>

#include <cmath>

#include "grainlab/errors.hpp"
#include "grainlab/studies/boundary_comparison/boundary.hpp"
#include "grainlab/studies/boundary_comparison/run_profile.hpp"
#include "grainlab/studies/paper/ensemble_stats.hpp"

namespace grainlab::boundaries {
namespace {

report::ShearingSeries series(std::vector<double> strain, std::vector<double> phi, std::vector<double> ac,
                              std::vector<double> omega) {
  report::ShearingSeries s;
  s.setColumn("axial_strain", std::move(strain));
  s.setColumn("phi_mob_deg", std::move(phi));
  s.setColumn("a_c", std::move(ac));
  s.setColumn("omega_macro_deg", std::move(omega));
  return s;
}

TEST(PeakOf, TakesTheSampleOfLargestPhiMobAndItsStrainAndAc) {
  const auto s = series({0, 0.01, 0.02, 0.03, 0.04}, {0, 20, NAN, 31, 25}, {0, 0.1, 0.2, 0.3, 0.4}, {0, 0, 0, 0, 0});
  const PeakPoint p = peakOf(s);
  EXPECT_EQ(p.phiMobDeg, 31);
  EXPECT_EQ(p.axialStrain, 0.03);
  EXPECT_EQ(p.aC, 0.3);
}

TEST(PeakOf, TheFirstOfEqualPeaksAndNaNWithoutValues) {
  const PeakPoint p = peakOf(series({0, 0.01, 0.02}, {5, 30, 30}, {0, 0.1, 0.2}, {0, 0, 0}));
  EXPECT_EQ(p.axialStrain, 0.01);
  const PeakPoint none = peakOf(series({0, 0.01}, {NAN, NAN}, {0, 0}, {0, 0}));
  EXPECT_TRUE(std::isnan(none.phiMobDeg) && std::isnan(none.axialStrain) && std::isnan(none.aC));
}

TEST(StrainGrid, RunsFromZeroToTheEndInclusive) {
  const std::vector<double> g = strainGrid(0.005, 0.2);
  ASSERT_EQ(g.size(), 41u);
  EXPECT_EQ(g.front(), 0.0);
  EXPECT_NEAR(g.back(), 0.2, 1e-15);
  EXPECT_NEAR(g[7], 0.035, 1e-15);
}

TEST(CurveAt, LinearBetweenSamplesAndNaNBeyondTheSeries) {
  // φ_mob = 1000 ε exactly between samples at uneven strains; a_c = 0.1 + 2 ε.
  const auto s = series({0, 0.004, 0.013, 0.021}, {0, 4, 13, 21}, {0.1, 0.108, 0.126, 0.142}, {0, 0, 0, 0});
  const std::vector<double> grid = strainGrid(0.005, 0.025);
  const std::vector<double> phi = curveAt(s, curveColumns()[0], grid), ac = curveAt(s, curveColumns()[1], grid);
  for (size_t k = 0; k + 1 < grid.size(); ++k) {
    EXPECT_NEAR(phi[k], 1000 * grid[k], 1e-9) << grid[k];
    EXPECT_NEAR(ac[k], 0.1 + 2 * grid[k], 1e-12) << grid[k];
  }
  EXPECT_TRUE(std::isnan(phi.back()));  // 0.025 lies past the last sample
}

TEST(CurveAt, OmegaTakesTheShorterWayRoundAndIsWrappedNearZero) {
  // From 170° to 10° is +20° the short way: half way is 0°, a quarter of the way −5°.
  const auto s = series({0, 0.01}, {0, 0}, {0, 0}, {170, 10});
  const CurveColumn omega = curveColumns()[2];
  ASSERT_TRUE(omega.axial);
  const std::vector<double> w = curveAt(s, omega, {0.0025, 0.005, 0.0075});
  EXPECT_NEAR(w[0], -5, 1e-9);
  EXPECT_NEAR(w[1], 0, 1e-9);
  EXPECT_NEAR(w[2], 5, 1e-9);
}

TEST(AxialMeanIntervalNear, ShiftsByWholeTurnsOnly) {
  // Directions 178° and 4°: circular mean 1°, whose image near 90° is 1° itself and near 180° is 181°.
  const report::MeanInterval a = report::axialMeanIntervalNear({178, 4}, 0);
  EXPECT_NEAR(a.mean, 1, 1e-9);
  const report::MeanInterval b = report::axialMeanIntervalNear({178, 4}, 170);
  EXPECT_NEAR(b.mean, 181, 1e-9);
  EXPECT_NEAR(b.high - b.low, a.high - a.low, 1e-9);
  EXPECT_LE(b.low, b.mean);
  EXPECT_GE(b.high, b.mean);
}

TEST(BoundaryScene, PresetsAndTheMatchedCellsFrictionalCompaction) {
  EXPECT_EQ(boundaryPreset(Boundary::Ring, "circular", true), "circular-quick");
  EXPECT_EQ(boundaryPreset(Boundary::Cell, "bedding-30", true), "periodic-biaxial-elongated-bedding-30-quick");
  EXPECT_EQ(boundaryPreset(Boundary::CellMatched, "bedding-30", false), "periodic-biaxial-elongated-bedding-30");
  const nlohmann::json cell = boundaryScene(Boundary::Cell, "circular", true, 3);
  const nlohmann::json matched = boundaryScene(Boundary::CellMatched, "circular", true, 3, 0.03);
  EXPECT_EQ(cell["seed"], 3);
  EXPECT_EQ(cell["stages"][0]["friction"], 0.0);  // the preset compacts without friction
  EXPECT_EQ(matched["stages"][0]["friction"], matched["material"]["friction"]);
  EXPECT_EQ(matched["stages"][2]["target_axial_strain"], 0.03);
  EXPECT_EQ(cell["stages"][2]["target_axial_strain"], 0.2);
  // Apart from those two keys (and the name) the matched cell is the cell.
  nlohmann::json same = matched;
  same["stages"][0]["friction"] = 0.0;
  same["stages"][2]["target_axial_strain"] = 0.2;
  same["name"] = cell["name"];
  EXPECT_EQ(same, cell);
  EXPECT_EQ(parseBoundary("cell-matched"), Boundary::CellMatched);
  EXPECT_THROW(parseBoundary("wall"), SceneError);
}

}  // namespace
}  // namespace grainlab::boundaries

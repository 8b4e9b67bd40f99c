// The loading paths end to end on their quick presets (docs/loading-paths.md): the measured
// strain-rate direction of a rotation follows the prescribed one and its servo holds the mean
// stress; constant volume keeps the area; cyclic loading reverses at its limits; simple shear
// holds its normal stress.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"

#include "../support/ring_escapees.hpp"

namespace grainlab {
namespace {

size_t column(const std::string& name) { return seriesColumnIndex(name); }

// Every sample's values, by stage name; and at the end, how many specimen particles lie
// outside the polygon of the ring's centres (ray casting), which a rotated or sheared ring
// must still hold in.
class Recorder : public RunObserver {
 public:
  void onSample(const Sample& s, const World&) override { rows[s.stage].push_back(s.values); }
  void onFinish(const RunSummary&, const World& world) override {
    escaped = grainlab::testing::particlesOutsideRing(world);
  }
  std::map<std::string, std::vector<std::vector<double>>> rows;
  int escaped = 0;
};

double axialDiff(double a, double b) {
  const double d = std::remainder(a - b, 180.0);
  return d == 90.0 ? -90.0 : d;
}

Recorder run(const nlohmann::json& scene) {
  Recorder r;
  const RunSummary summary = runScene(parseScene(scene), r);
  EXPECT_EQ(summary.status, RunStatus::Completed) << summary.error;
  EXPECT_TRUE(summary.notes.empty()) << summary.notes.front();  // no stage stopped at its time limit
  EXPECT_EQ(r.escaped, 0);
  return r;
}

// A full turn: θ_strain_rate, fitted to the ring's velocities, against θ0 + Ω t; the mean
// stress after the first 1% of deviatoric strain (d·t) against its target. `collapses`: the
// samples allowed off by more than 2%, each only where the kinetic energy is over 50 times
// its median. As in the biaxial test (biaxial_test.cpp), a few hundred elongated particles
// now and then lose much of their force network within a wave crossing, faster than any
// boundary can answer; the quick discs never did here (worst 0.5%).
void checkRotation(const std::string& preset, size_t collapses) {
  const nlohmann::json scene = presetScene(preset);
  const nlohmann::json& spec = scene["stages"][2];
  const Recorder r = run(scene);
  const auto& rows = r.rows.at("rotation");
  const double t0 = r.rows.at("consolidation").back()[column("time")];  // where rotation began
  const double rate = spec["total_rotation_deg"].get<double>() / spec["duration"].get<double>();
  const double d = spec["deviatoric_strain_rate"], target = spec["mean_stress"];
  ASSERT_GT(rows.size(), 150u);
  std::vector<double> energies;
  for (const auto& row : rows) energies.push_back(row[column("kinetic_energy")]);
  std::nth_element(energies.begin(), energies.begin() + energies.size() / 2, energies.end());
  const double medianEnergy = energies[energies.size() / 2];
  double worstDirection = 0, worstP = 0, turned = 0;
  size_t off = 0;
  for (const auto& row : rows) {
    const double t = row[column("time")] - t0;
    turned = rate * t;
    worstDirection = std::max(worstDirection, std::abs(axialDiff(row[column("theta_strain_rate_deg")],
                                                                 spec["initial_direction_deg"].get<double>() + turned)));
    if (d * t < 0.01) continue;
    const double deviation = std::abs(row[column("p")] - target) / target;
    worstP = std::max(worstP, deviation);
    if (deviation > 0.02) {
      ++off;
      EXPECT_GT(row[column("kinetic_energy")], 50 * medianEnergy) << "p off by " << deviation << " at t = " << t;
    }
  }
  EXPECT_NEAR(turned, 360, 2.5);  // the last sample is at the end of a full turn
  EXPECT_LT(worstDirection, 1.0);
  EXPECT_LE(off, collapses);
  std::printf("%s: worst |θ_strain_rate − prescribed| = %.4f°, worst |p − target|/target = %.4f, %zu of %zu "
              "samples off by > 2%%\n", preset.c_str(), worstDirection, worstP, off, rows.size());
}

TEST(LoadingPaths, RotationOfDiscsFollowsTheTurnAtConstantMeanStress) { checkRotation("rotation-circular-quick", 0); }
TEST(LoadingPaths, RotationOfPolygonsFollowsTheTurnAtConstantMeanStress) {
  checkRotation("rotation-elongated-random-quick", 5);
}

// The paper's shearing compresses axis 2 with the lateral boundary widening: the measured
// major strain-rate direction is then vertical (90° in θσ's convention), and
// omega_strain_rate_deg is the paper's ω. Only while the lateral servo closes in faster than
// the axial rate is the major compressive rate horizontal (0°).
TEST(LoadingPaths, BiaxialShearingHasVerticalStrainRate) {
  const Recorder r = run(presetScene("circular-quick"));
  const auto& rows = r.rows.at("shearing");
  size_t vertical = 0;
  for (const auto& row : rows) {
    const double theta = row[column("theta_strain_rate_deg")];
    if (std::abs(theta - 90) < 1e-9) {
      ++vertical;
      EXPECT_NEAR(row[column("omega_strain_rate_deg")], row[column("omega_macro_deg")], 1e-9);
    } else {
      EXPECT_LT(std::abs(axialDiff(theta, 0)), 1e-9);
    }
  }
  EXPECT_GT(vertical, rows.size() * 9 / 10);
  // No direction where the ring does not deform unequally: compaction's rates are equal.
  for (const auto& row : r.rows.at("compaction")) EXPECT_TRUE(std::isnan(row[column("theta_strain_rate_deg")]));
}

// Box2D's kinematic bodies take the same field. Its servo is documented as looser
// (docs/biaxial-test.md): on this preset 90% of the samples after the first 1% of strain had
// p within 2% (median 0.25%), the worst 27% off at a collapse.
TEST(LoadingPaths, RotationRunsInBox2d) {
  nlohmann::json scene = presetScene("rotation-circular-quick");
  scene["solver"] = {{"engine", "box2d"}};
  const Recorder r = run(scene);
  const auto& rows = r.rows.at("rotation");
  const double t0 = r.rows.at("consolidation").back()[column("time")];
  const nlohmann::json& spec = scene["stages"][2];
  const double rate = spec["total_rotation_deg"].get<double>() / spec["duration"].get<double>();
  ASSERT_GT(rows.size(), 150u);
  size_t within = 0, counted = 0;
  for (const auto& row : rows) {
    const double t = row[column("time")] - t0;
    EXPECT_LT(std::abs(axialDiff(row[column("theta_strain_rate_deg")], 90 + rate * t)), 1.0) << "t = " << t;
    if (spec["deviatoric_strain_rate"].get<double>() * t < 0.01) continue;
    ++counted;
    within += std::abs(row[column("p")] - 300e3) < 0.02 * 300e3;
  }
  EXPECT_GT(within, counted * 8 / 10);
}

TEST(LoadingPaths, ConstantVolumeKeepsTheArea) {
  const Recorder r = run(presetScene("constant-volume-circular-quick"));
  const auto& rows = r.rows.at("constant volume");
  const double area0 = r.rows.at("consolidation").back()[column("area")];
  double worst = 0, sigma11Change = 0;
  for (const auto& row : rows) {
    worst = std::max(worst, std::abs(row[column("area")] / area0 - 1));
    sigma11Change = std::max(sigma11Change, std::abs(row[column("sigma11")] - 300e3));
  }
  EXPECT_LT(worst, 1e-3);
  EXPECT_NEAR(rows.back()[column("axial_strain")], 0.2, 0.005);
  // Not the constant-σ11 stage by another name: σ11 is free, and moves by far more than 2%.
  EXPECT_GT(sigma11Change, 0.2 * 300e3);
  std::printf("constant volume: worst |A/A0 − 1| = %.2e\n", worst);
}

// The signs of successive axial-strain increments: where they change, the loading reversed.
std::vector<double> turningStrains(const std::vector<std::vector<double>>& rows) {
  std::vector<double> turns;
  int direction = 0;
  for (size_t k = 1; k < rows.size(); ++k) {
    const double step = rows[k][column("axial_strain")] - rows[k - 1][column("axial_strain")];
    if (step == 0) continue;
    const int now = step > 0 ? 1 : -1;
    if (direction != 0 && now != direction) turns.push_back(rows[k - 1][column("axial_strain")]);
    direction = now;
  }
  return turns;
}

TEST(LoadingPaths, CyclicReversesAtItsStrainLimits) {
  nlohmann::json scene = presetScene("cyclic-circular-quick");
  scene["output"]["sample_strain"] = 0.0005;  // samples close to every turning point
  const Recorder r = run(scene);
  const auto& rows = r.rows.at("cyclic");
  const double a = scene["stages"][2]["strain_amplitude"];
  const int cycles = scene["stages"][2]["cycles"];
  const std::vector<double> turns = turningStrains(rows);
  ASSERT_EQ(turns.size(), static_cast<size_t>(2 * cycles - 1));  // the last limit ends the stage
  for (size_t k = 0; k < turns.size(); ++k) {
    const double limit = k % 2 == 0 ? a : -a;
    EXPECT_NEAR(turns[k], limit, 0.0005) << "turn " << k;
  }
  EXPECT_NEAR(rows.back()[column("axial_strain")], -a, 0.0005);
  // σ11 held, as in biaxial: within 1 % at the median row and within 5 % at 95 % of them. Not
  // at every row: at a reversal this 250-disc specimen can lose σ11 for a few samples while the
  // ring catches up; which reversal, if any, depends on the seed and on rounding (it does on
  // either contact path), and the validity monitor warns when it lasts (lateral_stress_error).
  std::vector<double> off;
  for (const auto& row : rows) off.push_back(std::abs(row[column("sigma11")] / 300e3 - 1));
  std::sort(off.begin(), off.end());
  EXPECT_LT(off[off.size() / 2], 0.01);
  EXPECT_LT(off[off.size() * 95 / 100], 0.05);
}

TEST(LoadingPaths, CyclicReversesAtItsStressRatioLimits) {
  nlohmann::json scene = presetScene("cyclic-circular-quick");
  nlohmann::json& stage = scene["stages"][2];
  stage.erase("strain_amplitude");
  stage["q_over_p_limits"] = {-0.1, 0.2};
  stage["cycles"] = 2;
  scene["output"]["sample_strain"] = 0.0002;
  const Recorder r = run(scene);
  const auto& rows = r.rows.at("cyclic");
  const std::vector<double> turns = turningStrains(rows);
  ASSERT_EQ(turns.size(), 3u);
  // The ratio at each sample nearest a turn: at the limit, to what a sample spacing and the
  // few steps between stress measurements allow.
  double highest = -1, lowest = 1;
  for (const auto& row : rows) {
    const double ratio = (row[column("sigma22")] - row[column("sigma11")]) / (row[column("sigma22")] + row[column("sigma11")]);
    highest = std::max(highest, ratio);
    lowest = std::min(lowest, ratio);
  }
  EXPECT_NEAR(highest, 0.2, 0.03);
  EXPECT_NEAR(lowest, -0.1, 0.03);
}

TEST(LoadingPaths, SimpleShearHoldsItsNormalStress) {
  const Recorder r = run(presetScene("simple-shear-circular-quick"));
  const auto& rows = r.rows.at("simple shear");
  ASSERT_GT(rows.size(), 50u);
  size_t within = 0;
  double sumSin = 0, sumCos = 0;
  for (const auto& row : rows) {
    within += std::abs(row[column("sigma22")] - 300e3) < 0.02 * 300e3;
    const double theta = radians(row[column("theta_strain_rate_deg")]);
    sumSin += std::sin(2 * theta);
    sumCos += std::cos(2 * theta);
  }
  EXPECT_GT(within, rows.size() * 9 / 10);
  // γ̇ > 0 shortens the diagonal at 135°; the normal servo's own rate tilts it sample by sample.
  const double mean = 0.5 * degrees(std::atan2(sumSin, sumCos));
  EXPECT_LT(std::abs(axialDiff(mean, 135)), 5.0);
}

}  // namespace
}  // namespace grainlab

namespace grainlab {
namespace {

// Every path on polygons (DEM) and in Box2D (discs), shortened: it completes, the ring holds
// the specimen in, and the path's own control does what it says: the area kept, the axial
// strain reversed at its limit, the shortening diagonal of simple shear (135°) measured.
struct PathVariant {
  const char* name;
  const char* preset;
  bool polygons;
  bool box2d;
  friend void PrintTo(const PathVariant& v, std::ostream* os) { *os << v.name; }
};

class PathInEveryMode : public ::testing::TestWithParam<PathVariant> {};

TEST_P(PathInEveryMode, CompletesWithItsBoundaryControlHolding) {
  const PathVariant& v = GetParam();
  nlohmann::json scene = presetScene(v.preset);
  if (v.polygons) scene["assembly"] = presetScene("elongated-random-quick")["assembly"];
  if (v.box2d) scene["solver"]["engine"] = "box2d";
  nlohmann::json& path = scene["stages"][2];
  const std::string type = path["type"];
  if (type == "cyclic") path["cycles"] = 1, scene["output"]["sample_strain"] = 0.0005;
  if (type == "simple_shear") path["target_shear_strain"] = 0.05;
  if (type == "biaxial") path["target_axial_strain"] = 0.03;
  Recorder r;
  const RunSummary summary = runScene(parseScene(scene), r);
  ASSERT_EQ(summary.status, RunStatus::Completed) << summary.error;
  EXPECT_EQ(r.escaped, 0);
  const auto& rows = r.rows.at(path["name"].get<std::string>());
  ASSERT_GT(rows.size(), 5u);
  if (type == "biaxial") {  // constant volume: the area is the ring's kinematics, in any mode
    const double area0 = r.rows.at("consolidation").back()[column("area")];
    for (const auto& row : rows) EXPECT_NEAR(row[column("area")] / area0, 1.0, 1e-3);
  } else if (type == "cyclic") {  // one cycle: up to +a, reversed, down to −a
    const double a = path["strain_amplitude"];
    const std::vector<double> turns = turningStrains(rows);
    ASSERT_EQ(turns.size(), 1u);
    EXPECT_NEAR(turns[0], a, 0.0005);
    EXPECT_NEAR(rows.back()[column("axial_strain")], -a, 0.0005);
  } else {  // simple shear: D = [[0, −γ̇/2], [−γ̇/2, ε̇22]] shortens along 135° when ε̇22 = 0
    std::vector<double> theta;
    for (const auto& row : rows) theta.push_back(row[column("theta_strain_rate_deg")]);
    std::nth_element(theta.begin(), theta.begin() + theta.size() / 2, theta.end());
    EXPECT_NEAR(theta[theta.size() / 2], 135.0, 15.0);  // the normal-stress servo tilts it sample by sample
  }
}

INSTANTIATE_TEST_SUITE_P(
    LoadingPaths, PathInEveryMode,
    ::testing::Values(PathVariant{"CyclicPolygons", "cyclic-circular-quick", true, false},
                      PathVariant{"CyclicBox2d", "cyclic-circular-quick", false, true},
                      PathVariant{"SimpleShearPolygons", "simple-shear-circular-quick", true, false},
                      PathVariant{"SimpleShearBox2d", "simple-shear-circular-quick", false, true},
                      PathVariant{"ConstantVolumePolygons", "constant-volume-circular-quick", true, false},
                      PathVariant{"ConstantVolumeBox2d", "constant-volume-circular-quick", false, true}),
    [](const ::testing::TestParamInfo<PathVariant>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace grainlab

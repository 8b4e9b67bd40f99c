// grainlab shapes' pieces with closed forms: the rolling friction interpolated between
// measured means, and each representation's scene (which preset, which key it turns).
#include <gtest/gtest.h>

#include <cmath>

#include "grainlab/errors.hpp"
#include "grainlab/studies/shape_fidelity/representation.hpp"
#include "grainlab/studies/shape_fidelity/rolling_calibration.hpp"

namespace grainlab::shapes {
namespace {

TEST(RollingCalibration, InterpolatesLinearlyInTheBracketingPair) {
  // Means 24° at 0.1 and 32° at 0.3: 30° lies three quarters of the way, μ_r = 0.25.
  const RollingCalibration c = interpolateRollingFriction({{0.3, 32.0}, {0.1, 24.0}, {0.5, 35.0}}, 30.0);
  EXPECT_NEAR(c.rollingFriction, 0.25, 1e-15);
  EXPECT_EQ(c.below, 0.1);
  EXPECT_EQ(c.above, 0.3);
  EXPECT_TRUE(c.note.empty());
}

TEST(RollingCalibration, AMeasuredMeanOnTheTargetIsItsOwnFriction) {
  EXPECT_NEAR(interpolateRollingFriction({{0.1, 24.0}, {0.2, 28.0}, {0.4, 33.0}}, 28.0).rollingFriction, 0.2, 1e-15);
}

TEST(RollingCalibration, TakesTheFirstBracketWhenTheMeansAreNotMonotonic) {
  // 24 → 31 → 29 → 33: 30° is crossed between 0.1 and 0.2 first (at 0.1 + 6/7 · 0.1).
  const RollingCalibration c = interpolateRollingFriction({{0.1, 24}, {0.2, 31}, {0.3, 29}, {0.4, 33}}, 30.0);
  EXPECT_NEAR(c.rollingFriction, 0.1 + 0.1 * 6.0 / 7.0, 1e-15);
}

TEST(RollingCalibration, NoBracketGivesNaNAndSaysWhichWayToMeasure) {
  const RollingCalibration high = interpolateRollingFriction({{0.1, 24}, {0.2, 28}}, 35.0);
  EXPECT_TRUE(std::isnan(high.rollingFriction));
  EXPECT_NE(high.note.find("above 0.2"), std::string::npos) << high.note;
  const RollingCalibration low = interpolateRollingFriction({{0.1, 24}, {0.2, 28}}, 20.0);
  EXPECT_NE(low.note.find("below 0.1"), std::string::npos) << low.note;
  EXPECT_TRUE(std::isnan(interpolateRollingFriction({{0.1, 24}}, 24.0).rollingFriction));
  // A mean that was not measured (all its runs failed) does not count.
  EXPECT_TRUE(std::isnan(interpolateRollingFriction({{0.1, 24}, {0.2, std::nan("")}}, 25.0).rollingFriction));
}

TEST(Representation, NamesRoundTrip) {
  for (const char* name : {"hexagons", "clumps-2", "clumps-5", "rolling-0.137", "discs"})
    EXPECT_EQ(parseRepresentation(name).name(), name);
}

TEST(Representation, BadNamesAreRefusedNamingTheOption) {
  for (const char* name : {"clumps-1", "clumps-9", "clumps-3x", "rolling-0", "rolling--1", "rolling-x", "squares"}) {
    try {
      parseRepresentation(name);
      ADD_FAILURE() << name << " was accepted";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.field(), "--representations") << name;
      EXPECT_NE(e.reason().find(name), std::string::npos) << e.reason();
    }
  }
}

TEST(Representation, ScenesTurnOnlyTheirKey) {
  const nlohmann::json clumps = representationScene(parseRepresentation("clumps-5"), "bedding-30", true, 4);
  EXPECT_EQ(clumps["assembly"]["shape"], "clump");
  EXPECT_EQ(clumps["assembly"]["clump_discs"], 5);
  EXPECT_EQ(clumps["assembly"]["orientation"], "bedding");
  EXPECT_EQ(clumps["assembly"]["bedding_angle_deg"], 30.0);
  // The hexagons' length over smallest width, √3: every clump of 2 discs or more can take it.
  EXPECT_NEAR(clumps["assembly"]["aspect_ratio"].get<double>(), std::sqrt(3.0), 1e-9);
  EXPECT_EQ(clumps["seed"], 4);

  const nlohmann::json rolling = representationScene(parseRepresentation("rolling-0.25"), "bedding-30", false, 1);
  EXPECT_EQ(representationPreset(parseRepresentation("rolling-0.25"), "bedding-30", false), "circular-rolling");
  EXPECT_EQ(rolling["material"]["rolling_friction"], 0.25);
  EXPECT_EQ(rolling["assembly"]["shape"], "disc");

  EXPECT_EQ(representationPreset(parseRepresentation("hexagons"), "random", true), "elongated-random-quick");
  EXPECT_EQ(representationPreset(parseRepresentation("discs"), "random", true), "circular-quick");
  EXPECT_FALSE(parseRepresentation("discs").carriesFabric());
  EXPECT_TRUE(parseRepresentation("clumps-2").carriesFabric());
}

}  // namespace
}  // namespace grainlab::shapes

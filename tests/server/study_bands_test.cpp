// The ensemble bands' arithmetic (study_bands.hpp) against closed forms: runs whose series are
// straight lines, sampled at different strains, have as mean the mean line and as 95 %
// interval t_{0.975}(n − 1) · s / √n of the lines' values, at every grid strain (a linear
// interpolation of a line is the line); directions average on the circle; a run is counted
// only over the strains it reaches.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "study_bands.hpp"

namespace grainlab::server {
namespace {

struct Line {
  double a, b;  // y = a + b x
  double at(double x) const { return a + b * x; }
};

// The line sampled at `count` strains from `from` to `to` (uneven steps: x = from + (to-from)·u²).
BandCurve sampled(Line line, double from, double to, int count, std::size_t group) {
  BandCurve c;
  c.group = group;
  for (int k = 0; k < count; ++k) {
    const double u = double(k) / (count - 1);
    c.x.push_back(from + (to - from) * u * u);
    c.y.push_back(line.at(c.x.back()));
  }
  c.x.back() = to;
  c.y.back() = line.at(to);
  return c;
}

double sampleSd(const std::vector<double>& v) {
  double mean = 0;
  for (double x : v) mean += x / double(v.size());
  double ss = 0;
  for (double x : v) ss += (x - mean) * (x - mean);
  return std::sqrt(ss / double(v.size() - 1));
}

TEST(StudyBands, MeanAndTIntervalOfStraightLinesAreTheClosedForm) {
  const std::vector<Line> three{{1, 0.5}, {2, 1.0}, {4, 1.5}};
  const std::vector<Line> two{{10, -1}, {12, -2}};
  std::vector<BandCurve> curves{sampled(three[0], 0, 10, 37, 0), sampled(three[1], 0, 10, 51, 0),
                                sampled(three[2], 0, 10, 23, 0), sampled(two[0], 0, 10, 41, 1),
                                sampled(two[1], 0, 8, 29, 1)};  // reaches 8 % only
  const auto grid = strainGrid(curves, 201);
  ASSERT_EQ(grid.size(), 201u);
  EXPECT_EQ(grid.front(), 0.0);
  EXPECT_EQ(grid.back(), 10.0);
  EXPECT_NEAR(grid[100], 5.0, 1e-12);
  const auto bands = ensembleBands(curves, 2, grid, false);
  ASSERT_EQ(bands.size(), 2u);

  for (std::size_t i = 0; i < grid.size(); ++i) {
    const double x = grid[i];
    // Group 0: three lines everywhere; t_{0.975}(2) = 4.303, not the normal 1.96.
    std::vector<double> v{three[0].at(x), three[1].at(x), three[2].at(x)};
    const double mean = (7.0 + 3.0 * x) / 3.0;
    const double half = 4.303 * sampleSd(v) / std::sqrt(3.0);
    EXPECT_EQ(bands[0].n[i], 3) << x;
    EXPECT_NEAR(bands[0].mean[i], mean, 1e-12 * (1 + std::abs(mean))) << x;
    EXPECT_NEAR(bands[0].low[i], mean - half, 1e-11) << x;
    EXPECT_NEAR(bands[0].high[i], mean + half, 1e-11) << x;
    // Group 1: both lines up to 8 %, t_{0.975}(1) = 12.706; beyond, one run and no interval.
    if (x <= 8) {
      const double m = (22.0 - 3.0 * x) / 2.0, h = 12.706 * std::abs(two[0].at(x) - two[1].at(x)) / std::sqrt(2.0) / std::sqrt(2.0);
      EXPECT_EQ(bands[1].n[i], 2) << x;
      EXPECT_NEAR(bands[1].mean[i], m, 1e-12 * (1 + std::abs(m))) << x;
      EXPECT_NEAR(bands[1].high[i] - bands[1].low[i], 2 * h, 1e-10) << x;
    } else {
      EXPECT_EQ(bands[1].n[i], 1) << x;
      EXPECT_NEAR(bands[1].mean[i], two[0].at(x), 1e-12 * (1 + std::abs(two[0].at(x)))) << x;
      EXPECT_TRUE(std::isnan(bands[1].low[i]) && std::isnan(bands[1].high[i])) << x;
    }
  }
}

TEST(StudyBands, InterpolatesBetweenSamplesAndNotBeyondThemOrAcrossAGap) {
  const std::vector<double> x{0, 1, 3}, y{2, 4, NAN};
  const auto v = valuesAt(x, y, {-1, 0, 0.25, 1, 2, 3, 4}, false);
  EXPECT_TRUE(std::isnan(v[0]));  // before the first sample
  EXPECT_EQ(v[1], 2);
  EXPECT_DOUBLE_EQ(v[2], 2.5);
  EXPECT_EQ(v[3], 4);
  EXPECT_TRUE(std::isnan(v[4]));  // beside the gap
  EXPECT_TRUE(std::isnan(v[5]));
  EXPECT_TRUE(std::isnan(v[6]));  // past the last sample
}

TEST(StudyBands, DirectionsInterpolateAlongTheShorterArcAndAverageOnTheCircle) {
  // 170° to 10° is 20° through 0° (axial), not 160° back through 90°.
  const auto v = valuesAt({0, 1}, {170, 10}, {0.25, 0.5, 0.75}, true);
  EXPECT_NEAR(v[0], 175, 1e-12);
  EXPECT_NEAR(std::fmod(v[1], 180.0), 0, 1e-12);
  EXPECT_NEAR(v[2], 5, 1e-12);
  // Two runs at 176° and 4°: their axial mean is 0° (or 180°), not 90°.
  std::vector<BandCurve> curves{{0, {0, 1}, {176, 176}}, {0, {0, 1}, {4, 4}}};
  const auto bands = ensembleBands(curves, 1, {0, 0.5, 1}, true);
  for (double m : bands[0].mean) EXPECT_NEAR(std::min(m, 180 - m), 0, 1e-9);
  EXPECT_LE(bands[0].low[1], bands[0].mean[1]);
  EXPECT_GE(bands[0].high[1], bands[0].mean[1]);
}

TEST(StudyBands, ADirectionInFewerThanHalfTheRunsIsNoMean) {
  // Three runs; at x = 1 only one has a direction (the others are below their noise floor).
  std::vector<BandCurve> curves{{0, {0, 1, 2}, {30, 30, 30}}, {0, {0, 1, 2}, {32, NAN, 32}}, {0, {0, 1, 2}, {34, NAN, 34}}};
  const auto bands = ensembleBands(curves, 1, {0, 1, 2}, true);
  EXPECT_NEAR(bands[0].mean[0], 32, 1e-9);
  EXPECT_EQ(bands[0].n[1], 1);
  EXPECT_TRUE(std::isnan(bands[0].mean[1]));
  EXPECT_NEAR(bands[0].mean[2], 32, 1e-9);
}

TEST(StudyBands, ACurveIsItsShearingRowsWithTheChartsScaling) {
  const std::vector<std::string> columns{"step", "time", "stage", "axial_strain", "q", "contacts", "a_c", "theta_c_deg"};
  auto row = [](std::string stage, double strain, double q, double contacts, double ac, double theta) {
    SampleRecord s;
    s.stage = std::move(stage);
    s.values = {0, 0, NAN, strain, q, contacts, ac, theta};
    return s;
  };
  // 800 contacts: noise floor 1.25·√(2/800) = 0.0625, a direction needs a_c ≥ 0.125.
  const std::vector<SampleRecord> samples{row("compaction", 0.0, 1000, 800, 0.5, 10), row("shear", 0.01, 2000, 800, 0.2, 20),
                                          row("shear", 0.02, 3000, 800, 0.1, 30), row("shear", NAN, 4000, 800, 0.3, 40)};
  const auto deviator = bandCurve(samples, columns, {"shear"}, *bandQuantity("deviator"));
  ASSERT_EQ(deviator.x.size(), 2u);  // the compaction row and the one without a strain left out
  EXPECT_DOUBLE_EQ(deviator.x[0], 1.0);  // percent
  EXPECT_DOUBLE_EQ(deviator.y[0], 4.0);  // σ1 − σ3 = 2q, in kPa
  EXPECT_DOUBLE_EQ(deviator.y[1], 6.0);
  const auto theta = bandCurve(samples, columns, {"shear"}, *bandQuantity("theta_c"));
  EXPECT_EQ(theta.y[0], 20);
  EXPECT_TRUE(std::isnan(theta.y[1]));  // a_c = 0.1 < 2 noise floors
  EXPECT_EQ(bandQuantity("no-such"), nullptr);
}

TEST(StudyBands, ShearingStagesAreNamedAsTheDashboardNamesThem) {
  const auto names = shearingStageNames(
      R"({"stages": [{"type": "compaction"}, {"type": "biaxial", "name": "shear"}, {"type": "cyclic"}, {"type": "free"}]})");
  EXPECT_EQ(names, (std::set<std::string>{"shear", "cyclic"}));
  EXPECT_TRUE(shearingStageNames("not json").empty());
}

}  // namespace
}  // namespace grainlab::server

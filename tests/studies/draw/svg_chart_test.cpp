// SVG charts: nice axis ticks, linear scales, gaps and wraps in polylines, and the markup.
#include <cmath>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "grainlab/studies/draw/markup.hpp"
#include "grainlab/studies/draw/svg_chart.hpp"

namespace grainlab::report {
namespace {

int occurrences(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(NiceAxis, StrainRangeGetsTicksOfFivePercentOfAUnit) {
  const AxisTicks t = niceAxis(0.0, 0.2, 5);
  EXPECT_DOUBLE_EQ(t.step, 0.05);
  EXPECT_DOUBLE_EQ(t.lo, 0.0);
  EXPECT_NEAR(t.hi, 0.2, 1e-12);
  ASSERT_EQ(t.ticks.size(), 5u);
  EXPECT_NEAR(t.ticks[3], 0.15, 1e-12);
  EXPECT_EQ(t.decimals(), 2);
}

TEST(NiceAxis, WidensToWholeTicksAndNeverShowsMinusZero) {
  const AxisTicks t = niceAxis(-3.2, 17.9, 5);
  EXPECT_DOUBLE_EQ(t.step, 5.0);
  EXPECT_DOUBLE_EQ(t.lo, -5.0);
  EXPECT_DOUBLE_EQ(t.hi, 20.0);
  EXPECT_EQ(t.decimals(), 0);
  for (double v : t.ticks) EXPECT_FALSE(std::signbit(v) && v == 0.0);
}

TEST(NiceAxis, ReversedDegenerateAndNonFiniteRangesStillGiveAnAxis) {
  const AxisTicks r = niceAxis(180.0, 0.0, 4);
  EXPECT_DOUBLE_EQ(r.lo, 0.0);
  EXPECT_DOUBLE_EQ(r.hi, 200.0);  // 180/4 = 45 rounds up to a step of 50
  const AxisTicks flat = niceAxis(5.0, 5.0);
  EXPECT_LE(flat.lo, 4.5);
  EXPECT_GE(flat.hi, 5.5);
  const AxisTicks none = niceAxis(NAN, INFINITY);
  EXPECT_DOUBLE_EQ(none.lo, 0.0);
  EXPECT_DOUBLE_EQ(none.hi, 1.0);
}

TEST(LinearScale, MapsEndsAndFlipsForSvgY) {
  const LinearScale x{0, 20, 60, 460};
  EXPECT_DOUBLE_EQ(x(0), 60);
  EXPECT_DOUBLE_EQ(x(10), 260);
  const LinearScale y{0, 180, 256, 30};
  EXPECT_DOUBLE_EQ(y(0), 256);
  EXPECT_DOUBLE_EQ(y(180), 30);
  EXPECT_DOUBLE_EQ(y(90), 143);
}

TEST(DrawableRuns, BreakAtMissingValuesAndAtTheAxialWrap) {
  const std::vector<double> x{0, 1, 2, 3, 4, 5, 6};
  const std::vector<double> y{10, 20, NAN, 170, 5, 8, 9};
  const auto plain = drawableRuns(x, y, false);
  ASSERT_EQ(plain.size(), 2u);
  EXPECT_EQ(plain[0], std::make_pair(size_t{0}, size_t{2}));
  EXPECT_EQ(plain[1], std::make_pair(size_t{3}, size_t{7}));
  // 170° → 5° is the same direction turning by 15°, not a fall of 165°.
  const auto axial = drawableRuns(x, y, true);
  ASSERT_EQ(axial.size(), 3u);
  EXPECT_EQ(axial[1], std::make_pair(size_t{3}, size_t{4}));
  EXPECT_EQ(axial[2], std::make_pair(size_t{4}, size_t{7}));
}

TEST(RenderLineChart, PlacesPointsOnTheScalesAndLabelsTheTicks) {
  ChartSpec spec;
  spec.id = "t1";
  spec.title = "a < b & c";
  spec.xLabel = "axial strain ε22 (%)";
  spec.yLabel = "a_c";
  spec.xMin = 0, spec.xMax = 20, spec.yMin = 0, spec.yMax = 1;
  spec.width = 460, spec.height = 300;
  spec.series.push_back({"", {0, 20}, {0, 1}, "#123456", false, false});
  const std::string svg = renderLineChart(spec);
  // No legend: the plot spans x 60..446 and y 256..30 (margins 60, 14, 30, 44).
  EXPECT_NE(svg.find("points=\"60.0,256.0 446.0,30.0\""), std::string::npos) << svg;
  EXPECT_NE(svg.find(">a &lt; b &amp; c<"), std::string::npos);
  EXPECT_NE(svg.find(">0.2<"), std::string::npos);
  EXPECT_NE(svg.find(">15<"), std::string::npos);
  EXPECT_EQ(svg.find("xmlns"), std::string::npos);
  EXPECT_NE(renderLineChart(spec, true).find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
}

TEST(RenderLineChart, GapsLegendAndNoNumbersThatAreNotNumbers) {
  ChartSpec spec;
  spec.id = "t2";
  spec.series.push_back({"θ_c", {0, 1, 2, 3, 4}, {100, 95, NAN, 92, 91}, "", false, false});
  spec.series.push_back({"θ_n", {0, 1, 2}, {NAN, NAN, NAN}, "", true, false});
  spec.yReferences = {90};
  const std::string svg = renderLineChart(spec);
  EXPECT_EQ(occurrences(svg, "<polyline"), 2);  // the gap splits θ_c; θ_n draws nothing
  EXPECT_NE(svg.find(">θ_c<"), std::string::npos);
  EXPECT_NE(svg.find(">θ_n<"), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray=\"2 3\""), std::string::npos);  // the 90° reference
  EXPECT_FALSE(std::regex_search(svg, std::regex("nan|inf", std::regex::icase)));
  EXPECT_EQ(occurrences(svg, "<svg"), 1);
  EXPECT_EQ(occurrences(svg, "</svg>"), 1);
}

TEST(RenderLineChart, BandsBreakAtGapsAndWidenTheAxis) {
  ChartSpec spec;
  spec.id = "t3";
  LineSeries mean{"mean", {0, 1, 2, 3, 4, 5}, {1, 1, 1, 1, 1, 1}, "#000000"};
  mean.low = {0.5, 0.5, NAN, 0.5, 0.5, 0.5};
  mean.high = {1.5, 1.5, NAN, 1.5, 1.5, 9.0};  // the band's top sets the axis, not the line
  LineSeries faint{"", {0, 5}, {0.8, 0.8}, "#000000"};
  faint.faint = true;
  spec.series = {faint, mean};
  const std::string svg = renderLineChart(spec);
  EXPECT_EQ(occurrences(svg, "class=\"band\""), 2);  // split by the missing bounds at x = 2
  EXPECT_EQ(occurrences(svg, "stroke-opacity=\"0.3\""), 1);
  EXPECT_NE(svg.find(">10<"), std::string::npos) << "the y axis reaches the band's 9";
  EXPECT_FALSE(std::regex_search(svg, std::regex("nan|inf", std::regex::icase)));
}

TEST(Markup, Escapes) {
  EXPECT_EQ(escapeMarkup("<a href='x'>&\"</a>"), "&lt;a href=&#39;x&#39;&gt;&amp;&quot;&lt;/a&gt;");
}

}  // namespace
}  // namespace grainlab::report

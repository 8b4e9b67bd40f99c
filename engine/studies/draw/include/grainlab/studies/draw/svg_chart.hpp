#pragma once
// Line charts as inline SVG: nice axis ticks, linear scales, polylines that break at missing
// values (and, for axial directions, at the wrap from 180° to 0°), a legend and reference lines.
// Pure functions of their inputs: the same chart gives the same text.
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace grainlab::report {

/// An axis range widened to whole ticks: lo and hi are multiples of step; ticks run from lo to
/// hi inclusive. step is 1, 2 or 5 times a power of ten.
struct AxisTicks {
  double lo = 0, hi = 1, step = 0.2;
  std::vector<double> ticks;
  /// Digits after the point that label every tick exactly (0 for step ≥ 1).
  int decimals() const;
};

/// About `target` ticks covering [lo, hi] (either order). A degenerate or non-finite range
/// becomes a unit-wide range around the value (or [0, 1]).
AxisTicks niceAxis(double lo, double hi, int target = 5);

/// Maps [d0, d1] (data) linearly onto [r0, r1] (pixels); r1 < r0 flips the axis (SVG y).
struct LinearScale {
  double d0 = 0, d1 = 1, r0 = 0, r1 = 1;
  double operator()(double v) const { return r0 + (v - d0) * (r1 - r0) / (d1 - d0); }
};

/// Colour-blind-safe colours (Okabe-Ito), by index modulo their number.
const std::string& paletteColour(size_t index);

struct LineSeries {
  LineSeries() = default;
  LineSeries(std::string label_, std::vector<double> x_, std::vector<double> y_, std::string colour_ = "",
             bool dashed_ = false, bool markers_ = false)
      : label(std::move(label_)), x(std::move(x_)), y(std::move(y_)), colour(std::move(colour_)), dashed(dashed_),
        markers(markers_) {}
  std::string label;
  std::vector<double> x, y;          ///< same length; a NaN in either leaves a gap
  std::string colour;                ///< CSS colour; empty = palette by position
  bool dashed = false;
  bool markers = false;              ///< a small circle at each point
  /// A shaded band from low to high (same length as x; empty = none), e.g. a 95 % interval;
  /// drawn beneath the lines, broken where a bound or the line is missing.
  std::vector<double> low, high;
  bool faint = false;                ///< thin and pale: one member of an ensemble
};

struct ChartSpec {
  std::string id;                    ///< unique in the document (names the clip path)
  std::string title;
  std::string xLabel, yLabel;
  std::vector<LineSeries> series;
  std::optional<double> xMin, xMax, yMin, yMax;  ///< fixed ends; otherwise from the data
  std::vector<double> yReferences;   ///< dashed horizontal lines (e.g. 90° or 0)
  /// y is an axial direction in [0, 180): a jump of more than 90° between neighbours is the
  /// wrap, not a change, and breaks the line instead of drawing across the chart.
  bool axialY = false;
  int width = 460, height = 300;     ///< px
};

/// The chart as an <svg> element. `standalone` adds the XML namespace (for a .svg file); an
/// SVG inside HTML does without it.
std::string renderLineChart(const ChartSpec& spec, bool standalone = false);

/// Splits a polyline's points into drawable runs: a run ends at a non-finite point and, when
/// `axial`, between neighbours whose y differ by more than 90. Returns index ranges [first, last).
std::vector<std::pair<size_t, size_t>> drawableRuns(const std::vector<double>& x, const std::vector<double>& y,
                                                    bool axial);

}  // namespace grainlab::report

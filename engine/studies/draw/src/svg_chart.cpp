#include "grainlab/studies/draw/svg_chart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "grainlab/studies/draw/markup.hpp"
#include "grainlab/studies/paper/number_text.hpp"

namespace grainlab::report {
namespace {

std::string px(double v) { return fixed(v, 1); }

// Margins around the plot area, px: room for tick labels, axis labels, the title and a legend.
constexpr double kLeft = 60, kRight = 14, kTop = 30, kBottom = 44, kLegendWidth = 118;

}  // namespace

int AxisTicks::decimals() const {
  if (!(step > 0)) return 0;
  return std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
}

AxisTicks niceAxis(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0, hi = 1;
  if (lo > hi) std::swap(lo, hi);
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(lo))) {
    // A flat series still needs an axis: a unit-wide one around its value.
    lo -= 0.5;
    hi += 0.5;
  }
  target = std::max(target, 2);
  const double raw = (hi - lo) / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * magnitude;
    if (raw <= step * (1 + 1e-9)) break;
  }
  AxisTicks t;
  t.step = step;
  // A small tolerance keeps a value that is a whole tick (within rounding) from adding one more.
  t.lo = std::floor(lo / step + 1e-9) * step;
  t.hi = std::ceil(hi / step - 1e-9) * step;
  const int n = static_cast<int>(std::lround((t.hi - t.lo) / step));
  for (int k = 0; k <= n; ++k) {
    double v = t.lo + k * step;
    if (std::abs(v) < step * 1e-9) v = 0;  // no "-0"
    t.ticks.push_back(v);
  }
  return t;
}

const std::string& paletteColour(size_t index) {
  static const std::vector<std::string> colours{"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                                "#E69F00", "#56B4E9", "#000000", "#999999", "#8C510A"};
  return colours[index % colours.size()];
}

std::vector<std::pair<size_t, size_t>> drawableRuns(const std::vector<double>& x, const std::vector<double>& y,
                                                    bool axial) {
  std::vector<std::pair<size_t, size_t>> runs;
  const size_t n = std::min(x.size(), y.size());
  size_t start = 0;
  bool open = false;
  for (size_t k = 0; k < n; ++k) {
    const bool finite = std::isfinite(x[k]) && std::isfinite(y[k]);
    const bool wraps = open && finite && axial && std::abs(y[k] - y[k - 1]) > 90.0;
    if (open && (!finite || wraps)) {
      runs.emplace_back(start, k);
      open = false;
    }
    if (finite && !open) {
      start = k;
      open = true;
    }
  }
  if (open) runs.emplace_back(start, n);
  return runs;
}

std::string renderLineChart(const ChartSpec& spec, bool standalone) {
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  for (const LineSeries& s : spec.series) {
    for (size_t k = 0; k < std::min(s.x.size(), s.y.size()); ++k) {
      if (!std::isfinite(s.x[k]) || !std::isfinite(s.y[k])) continue;
      xlo = std::min(xlo, s.x[k]);
      xhi = std::max(xhi, s.x[k]);
      ylo = std::min(ylo, s.y[k]);
      yhi = std::max(yhi, s.y[k]);
      for (const std::vector<double>* bound : {&s.low, &s.high}) {
        if (k < bound->size() && std::isfinite((*bound)[k])) ylo = std::min(ylo, (*bound)[k]), yhi = std::max(yhi, (*bound)[k]);
      }
    }
  }
  for (double r : spec.yReferences) ylo = std::min(ylo, r), yhi = std::max(yhi, r);
  AxisTicks xt = niceAxis(spec.xMin.value_or(xlo), spec.xMax.value_or(xhi), 6);
  AxisTicks yt = niceAxis(spec.yMin.value_or(ylo), spec.yMax.value_or(yhi), 5);
  // Fixed ends are kept exactly, even when they are not whole ticks.
  if (spec.xMin) xt.lo = *spec.xMin;
  if (spec.xMax) xt.hi = *spec.xMax;
  if (spec.yMin) yt.lo = *spec.yMin;
  if (spec.yMax) yt.hi = *spec.yMax;

  const bool legend = std::any_of(spec.series.begin(), spec.series.end(),
                                   [](const LineSeries& s) { return !s.label.empty(); });
  const double w = spec.width, h = spec.height;
  const double plotLeft = kLeft, plotRight = w - kRight - (legend ? kLegendWidth : 0);
  const double plotTop = kTop, plotBottom = h - kBottom;
  const LinearScale sx{xt.lo, xt.hi, plotLeft, plotRight};
  const LinearScale sy{yt.lo, yt.hi, plotBottom, plotTop};
  const std::string clip = escapeMarkup(spec.id) + "-clip";

  std::string o;
  o += "<svg";
  if (standalone) o += " xmlns=\"http://www.w3.org/2000/svg\"";
  o += " class=\"chart\" id=\"" + escapeMarkup(spec.id) + "\" viewBox=\"0 0 " + px(w) + " " + px(h) + "\" width=\"" +
       px(w) + "\" height=\"" + px(h) + "\" role=\"img\" aria-label=\"" + escapeMarkup(spec.title) +
       "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  o += "<title>" + escapeMarkup(spec.title) + "</title>\n";
  o += "<rect x=\"0\" y=\"0\" width=\"" + px(w) + "\" height=\"" + px(h) + "\" fill=\"#ffffff\"/>\n";
  o += "<defs><clipPath id=\"" + clip + "\"><rect x=\"" + px(plotLeft) + "\" y=\"" + px(plotTop) + "\" width=\"" +
       px(plotRight - plotLeft) + "\" height=\"" + px(plotBottom - plotTop) + "\"/></clipPath></defs>\n";
  o += "<text x=\"" + px(w / 2) + "\" y=\"18\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">" +
       escapeMarkup(spec.title) + "</text>\n";

  // Grid and tick labels.
  for (double v : xt.ticks) {
    if (v < xt.lo - 1e-12 || v > xt.hi + 1e-12) continue;
    const double X = sx(v);
    o += "<line x1=\"" + px(X) + "\" y1=\"" + px(plotTop) + "\" x2=\"" + px(X) + "\" y2=\"" + px(plotBottom) +
         "\" stroke=\"#e4e4e4\"/>\n";
    o += "<text x=\"" + px(X) + "\" y=\"" + px(plotBottom + 14) + "\" text-anchor=\"middle\">" +
         fixed(v, xt.decimals()) + "</text>\n";
  }
  for (double v : yt.ticks) {
    if (v < yt.lo - 1e-12 || v > yt.hi + 1e-12) continue;
    const double Y = sy(v);
    o += "<line x1=\"" + px(plotLeft) + "\" y1=\"" + px(Y) + "\" x2=\"" + px(plotRight) + "\" y2=\"" + px(Y) +
         "\" stroke=\"#e4e4e4\"/>\n";
    o += "<text x=\"" + px(plotLeft - 5) + "\" y=\"" + px(Y + 4) + "\" text-anchor=\"end\">" +
         fixed(v, yt.decimals()) + "</text>\n";
  }
  for (double r : spec.yReferences) {
    if (r < yt.lo || r > yt.hi) continue;
    o += "<line x1=\"" + px(plotLeft) + "\" y1=\"" + px(sy(r)) + "\" x2=\"" + px(plotRight) + "\" y2=\"" + px(sy(r)) +
         "\" stroke=\"#888888\" stroke-dasharray=\"2 3\"/>\n";
  }
  o += "<rect x=\"" + px(plotLeft) + "\" y=\"" + px(plotTop) + "\" width=\"" + px(plotRight - plotLeft) +
       "\" height=\"" + px(plotBottom - plotTop) + "\" fill=\"none\" stroke=\"#444444\"/>\n";

  // Data.
  o += "<g clip-path=\"url(#" + clip + ")\" fill=\"none\" stroke-width=\"1.6\">\n";
  // Bands first, so every line stays visible on top of them.
  for (size_t i = 0; i < spec.series.size(); ++i) {
    const LineSeries& s = spec.series[i];
    if (s.low.size() != s.x.size() || s.high.size() != s.x.size()) continue;
    const std::string colour = s.colour.empty() ? paletteColour(i) : s.colour;
    for (const auto& [first, last] : drawableRuns(s.x, s.y, spec.axialY)) {
      size_t k = first;
      while (k < last) {
        while (k < last && !(std::isfinite(s.low[k]) && std::isfinite(s.high[k]))) ++k;
        size_t end = k;
        while (end < last && std::isfinite(s.low[end]) && std::isfinite(s.high[end])) ++end;
        if (end - k >= 2) {
          std::string points;
          for (size_t j = k; j < end; ++j) points += px(sx(s.x[j])) + "," + px(sy(s.high[j])) + " ";
          for (size_t j = end; j-- > k;) points += px(sx(s.x[j])) + "," + px(sy(s.low[j])) + (j > k ? " " : "");
          o += "<polygon class=\"band\" points=\"" + points + "\" fill=\"" + colour +
               "\" fill-opacity=\"0.18\" stroke=\"none\"/>\n";
        }
        k = end;
      }
    }
  }
  for (size_t i = 0; i < spec.series.size(); ++i) {
    const LineSeries& s = spec.series[i];
    const std::string colour = s.colour.empty() ? paletteColour(i) : s.colour;
    const std::string dash = s.dashed ? " stroke-dasharray=\"5 3\"" : "";
    for (const auto& [first, last] : drawableRuns(s.x, s.y, spec.axialY)) {
      std::string points;
      for (size_t k = first; k < last; ++k) {
        if (k > first) points += ' ';
        points += px(sx(s.x[k])) + "," + px(sy(s.y[k]));
      }
      if (last - first == 1) {
        o += "<circle cx=\"" + px(sx(s.x[first])) + "\" cy=\"" + px(sy(s.y[first])) + "\" r=\"1.6\" fill=\"" + colour +
             "\" stroke=\"none\"/>\n";
      } else {
        o += "<polyline points=\"" + points + "\" stroke=\"" + colour + "\"" + dash +
             (s.faint ? " stroke-opacity=\"0.3\" stroke-width=\"0.7\"" : "") + "/>\n";
      }
    }
    if (s.markers) {
      for (size_t k = 0; k < std::min(s.x.size(), s.y.size()); ++k) {
        if (!std::isfinite(s.x[k]) || !std::isfinite(s.y[k])) continue;
        o += "<circle cx=\"" + px(sx(s.x[k])) + "\" cy=\"" + px(sy(s.y[k])) + "\" r=\"2\" fill=\"" + colour +
             "\" stroke=\"none\"/>\n";
      }
    }
  }
  o += "</g>\n";

  // Axis labels.
  o += "<text x=\"" + px((plotLeft + plotRight) / 2) + "\" y=\"" + px(h - 8) + "\" text-anchor=\"middle\">" +
       escapeMarkup(spec.xLabel) + "</text>\n";
  o += "<text transform=\"translate(14," + px((plotTop + plotBottom) / 2) + ") rotate(-90)\" text-anchor=\"middle\">" +
       escapeMarkup(spec.yLabel) + "</text>\n";

  if (legend) {
    double y = plotTop + 8;
    const double x = plotRight + 10;
    for (size_t i = 0; i < spec.series.size(); ++i) {
      const LineSeries& s = spec.series[i];
      if (s.label.empty()) continue;
      const std::string colour = s.colour.empty() ? paletteColour(i) : s.colour;
      o += "<line x1=\"" + px(x) + "\" y1=\"" + px(y) + "\" x2=\"" + px(x + 20) + "\" y2=\"" + px(y) + "\" stroke=\"" +
           colour + "\" stroke-width=\"2\"" + (s.dashed ? " stroke-dasharray=\"5 3\"" : "") + "/>\n";
      o += "<text x=\"" + px(x + 25) + "\" y=\"" + px(y + 4) + "\">" + escapeMarkup(s.label) + "</text>\n";
      y += 16;
    }
  }
  o += "</svg>\n";
  return o;
}

}  // namespace grainlab::report

#include "grainlab/studies/draw/pareto_plot.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "grainlab/studies/draw/markup.hpp"
#include "grainlab/studies/paper/number_text.hpp"
#include "grainlab/studies/draw/svg_chart.hpp"

namespace grainlab::tradeoff {
namespace {

using report::escapeMarkup;
using report::fixed;

constexpr int kWidth = 500, kHeight = 360;                      // px per panel
constexpr int kLeft = 62, kRight = 18, kTop = 34, kBottom = 78;  // px of margin

// Colour per axis in a fixed order, so the two panels agree.
size_t axisIndex(const std::string& axis) {
  static const std::vector<std::string> order{"reference", "noise", "baseline", "timestep_safety", "inertial_number",
                                              "vertices", "sample_strain", "engine", "box2d"};
  // grainlab shapes' representations never share a panel with the axes: the colours after the reference's.
  static const std::vector<std::string> shapes{"clumps", "rolling discs", "discs"};
  if (const auto s = std::find(shapes.begin(), shapes.end(), axis); s != shapes.end())
    return 1 + static_cast<size_t>(s - shapes.begin());
  const auto it = std::find(order.begin(), order.end(), axis);
  return static_cast<size_t>(it - order.begin());
}

// Log-scale ticks: 1, 2, 5 × 10^k within [lo, hi] when they span at most two decades, else
// the decades alone.
std::vector<double> logTicks(double lo, double hi) {
  std::vector<double> ticks;
  const bool fine = std::log10(hi / lo) <= 2.0;
  for (int e = static_cast<int>(std::floor(std::log10(lo))); e <= static_cast<int>(std::ceil(std::log10(hi))); ++e) {
    for (double m : fine ? std::vector<double>{1, 2, 5} : std::vector<double>{1}) {
      const double t = m * std::pow(10.0, e);
      if (t >= lo * (1 - 1e-12) && t <= hi * (1 + 1e-12)) ticks.push_back(t);
    }
  }
  return ticks;
}

void renderPanel(std::ostringstream& svg, const ParetoPanel& panel, int x0, const std::string& xLabel,
                 const std::string& yLabel) {
  std::vector<const ParetoPoint*> drawn;
  for (const ParetoPoint& p : panel.points) {
    if (p.seconds > 0 && std::isfinite(p.seconds) && std::isfinite(p.error)) drawn.push_back(&p);
  }
  double tLo = 1, tHi = 10, eHi = 1;
  if (!drawn.empty()) {
    tLo = tHi = drawn.front()->seconds;
    eHi = 0;
    for (const ParetoPoint* p : drawn) {
      tLo = std::min(tLo, p->seconds);
      tHi = std::max(tHi, p->seconds);
      eHi = std::max(eHi, p->error);
      if (std::isfinite(p->errorHigh)) eHi = std::max(eHi, p->errorHigh);
    }
  }
  // Half a decade of room at either end keeps markers and labels off the frame.
  tLo /= std::sqrt(3.0);
  tHi *= std::sqrt(3.0);
  if (std::isfinite(panel.noiseFloor)) eHi = std::max(eHi, panel.noiseFloor);
  const report::AxisTicks yAxis = report::niceAxis(0, eHi > 0 ? eHi : 1);
  const double left = x0 + kLeft, right = x0 + kWidth - kRight, top = kTop, bottom = kHeight - kBottom;
  const report::LinearScale sx{std::log10(tLo), std::log10(tHi), left, right};
  const report::LinearScale sy{yAxis.lo, yAxis.hi, bottom, top};

  svg << "<g font-family=\"sans-serif\" font-size=\"11\">\n";
  svg << "<text x=\"" << (left + right) / 2 << "\" y=\"18\" text-anchor=\"middle\" font-size=\"13\">"
      << escapeMarkup(panel.title) << "</text>\n";
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << right - left << "\" height=\"" << bottom - top
      << "\" fill=\"none\" stroke=\"#888\"/>\n";
  for (double t : logTicks(tLo, tHi)) {
    const double x = sx(std::log10(t));
    svg << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << bottom
        << "\" stroke=\"#eee\"/><text x=\"" << x << "\" y=\"" << bottom + 14 << "\" text-anchor=\"middle\">"
        << report::general(t, 3) << "</text>\n";
  }
  for (double v : yAxis.ticks) {
    const double y = sy(v);
    svg << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << right << "\" y2=\"" << y
        << "\" stroke=\"#eee\"/><text x=\"" << left - 5 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">"
        << fixed(v, yAxis.decimals()) << "</text>\n";
  }
  svg << "<text x=\"" << (left + right) / 2 << "\" y=\"" << bottom + 32 << "\" text-anchor=\"middle\">"
      << escapeMarkup(xLabel) << "</text>\n";
  svg << "<text transform=\"translate(" << x0 + 16 << "," << (top + bottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << escapeMarkup(yLabel) << "</text>\n";

  if (std::isfinite(panel.noiseFloor)) {
    const double y = sy(panel.noiseFloor);
    svg << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << right << "\" y2=\"" << y
        << "\" stroke=\"#999\" stroke-dasharray=\"2 4\"/><text x=\"" << right - 4 << "\" y=\"" << y - 4
        << "\" text-anchor=\"end\" font-size=\"9\" fill=\"#777\">noise floor</text>\n";
  }
  // The front as a staircase: from each front point, right at its error to the next one's cost.
  std::vector<const ParetoPoint*> front;
  for (const ParetoPoint* p : drawn) {
    if (p->onFront) front.push_back(p);
  }
  std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->seconds < b->seconds; });
  if (front.size() > 1) {
    svg << "<polyline fill=\"none\" stroke=\"#444\" stroke-dasharray=\"4 3\" points=\"";
    for (size_t k = 0; k < front.size(); ++k) {
      const double x = sx(std::log10(front[k]->seconds)), y = sy(front[k]->error);
      if (k > 0) svg << x << "," << sy(front[k - 1]->error) << " ";
      svg << x << "," << y << " ";
    }
    svg << "\"/>\n";
  }
  for (const ParetoPoint* p : drawn) {  // intervals first, under the markers
    if (!std::isfinite(p->errorLow) || !std::isfinite(p->errorHigh)) continue;
    const double x = sx(std::log10(p->seconds));
    svg << "<line x1=\"" << x << "\" y1=\"" << sy(std::max(p->errorLow, yAxis.lo)) << "\" x2=\"" << x << "\" y2=\""
        << sy(p->errorHigh) << "\" stroke=\"" << report::paletteColour(axisIndex(p->axis)) << "\" stroke-width=\"1.5\"/>\n";
  }
  for (const ParetoPoint* p : drawn) {
    const double x = sx(std::log10(p->seconds)), y = sy(p->error);
    const std::string& colour = report::paletteColour(axisIndex(p->axis));
    svg << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"" << (p->onFront ? 5 : 4) << "\" fill=\"" << colour
        << "\" stroke=\"" << (p->onFront ? "#000" : "none") << "\"><title>" << escapeMarkup(p->axis + " " + p->label)
        << "</title></circle>\n";
    svg << "<text x=\"" << x + 6 << "\" y=\"" << y - 5 << "\" font-size=\"9\" fill=\"#333\">" << escapeMarkup(p->label)
        << "</text>\n";
  }
  // Legend: the axes present in this panel.
  std::vector<std::string> axes;
  for (const ParetoPoint* p : drawn) {
    if (std::find(axes.begin(), axes.end(), p->axis) == axes.end()) axes.push_back(p->axis);
  }
  std::sort(axes.begin(), axes.end(), [](const auto& a, const auto& b) { return axisIndex(a) < axisIndex(b); });
  double lx = left, ly = bottom + 50;
  for (const std::string& axis : axes) {
    const double w = 16 + 6.2 * static_cast<double>(axis.size());  // px, roughly the text's width
    if (lx + w > right && lx > left) {  // wrap to a second line
      lx = left;
      ly += 15;
    }
    svg << "<circle cx=\"" << lx + 4 << "\" cy=\"" << ly - 4 << "\" r=\"4\" fill=\""
        << report::paletteColour(axisIndex(axis)) << "\"/><text x=\"" << lx + 11 << "\" y=\"" << ly << "\">"
        << escapeMarkup(axis) << "</text>\n";
    lx += w;
  }
  svg << "</g>\n";
}

}  // namespace

std::string renderParetoSvg(const std::vector<ParetoPanel>& panels, const std::string& xLabel,
                            const std::string& yLabel) {
  const int width = kWidth * static_cast<int>(std::max<size_t>(1, panels.size()));
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << kHeight
      << "\" viewBox=\"0 0 " << width << " " << kHeight << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (size_t k = 0; k < panels.size(); ++k) renderPanel(svg, panels[k], static_cast<int>(k) * kWidth, xLabel, yLabel);
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace grainlab::tradeoff

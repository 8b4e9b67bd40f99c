#include "grainlab/studies/draw/rose_chart.hpp"

#include <algorithm>
#include <cmath>

#include "grainlab/math.hpp"
#include "grainlab/studies/draw/markup.hpp"
#include "grainlab/studies/paper/number_text.hpp"

namespace grainlab::report {
namespace {

std::string px(double v) { return fixed(v, 1); }

constexpr double kCell = 170;     // px per rose, square
constexpr double kHeader = 44;    // px above the first row: title and captions
constexpr double kRowLabel = 96;  // px left of the first column: the quantity's name

const std::vector<RoseQuantity>& quantities() {
  static const std::vector<RoseQuantity> q{RoseQuantity::Normals, RoseQuantity::NormalForce,
                                           RoseQuantity::TangentialForce};
  return q;
}

const std::string& colourOf(RoseQuantity q) {
  static const std::string colours[] = {"#0072B2", "#D55E00", "#009E73"};
  return colours[static_cast<int>(q)];
}

// SVG point of polar (r px, θ degrees) around (cx, cy): θ counter-clockwise from the 1-axis,
// and SVG's y points down.
std::string polar(double cx, double cy, double r, double thetaDeg) {
  const double t = radians(thetaDeg);
  return px(cx + r * std::cos(t)) + "," + px(cy - r * std::sin(t));
}

std::string rose(const analysis::PolarHistograms& h, RoseQuantity q, double cx, double cy, double radius) {
  const std::vector<double> values = roseBinValues(h, q);
  double top = 0;
  for (double v : values) {
    if (std::isfinite(v)) top = std::max(top, std::abs(v));
  }
  for (int d = 0; d < 180; ++d) top = std::max(top, std::abs(roseFitValue(h, q, d)));
  std::string o;
  o += "<circle cx=\"" + px(cx) + "\" cy=\"" + px(cy) + "\" r=\"" + px(radius) +
       "\" fill=\"none\" stroke=\"#dddddd\"/>\n";
  o += "<circle cx=\"" + px(cx) + "\" cy=\"" + px(cy) + "\" r=\"" + px(radius / 2) +
       "\" fill=\"none\" stroke=\"#eeeeee\"/>\n";
  o += "<line x1=\"" + px(cx - radius) + "\" y1=\"" + px(cy) + "\" x2=\"" + px(cx + radius) + "\" y2=\"" + px(cy) +
       "\" stroke=\"#cccccc\"/>\n";
  o += "<line x1=\"" + px(cx) + "\" y1=\"" + px(cy - radius) + "\" x2=\"" + px(cx) + "\" y2=\"" + px(cy + radius) +
       "\" stroke=\"#cccccc\"/>\n";
  if (!(top > 0)) return o + "<text x=\"" + px(cx) + "\" y=\"" + px(cy) + "\" text-anchor=\"middle\">no data</text>\n";
  const double scale = radius / top;
  const std::string& colour = colourOf(q);
  const double width = h.binWidthDeg();
  for (int half = 0; half < 2; ++half) {
    for (int b = 0; b < h.bins; ++b) {
      const double v = values[static_cast<size_t>(b)];
      if (!std::isfinite(v) || v == 0) continue;
      const double r = std::abs(v) * scale;
      const double a0 = b * width + half * 180.0, a1 = a0 + width;
      const std::string fill = v < 0 ? "none" : colour;
      o += "<path d=\"M" + px(cx) + "," + px(cy) + " L" + polar(cx, cy, r, a0) + " A" + px(r) + "," + px(r) +
           " 0 0 0 " + polar(cx, cy, r, a1) + " Z\" fill=\"" + fill + "\" fill-opacity=\"0.35\" stroke=\"" + colour +
           "\" stroke-width=\"0.6\"" + (v < 0 ? " stroke-dasharray=\"2 1\"" : "") + "/>\n";
    }
  }
  std::string points;
  for (int d = 0; d <= 360; d += 2) {
    {
    if (d) points += ' ';
    points += polar(cx, cy, std::abs(roseFitValue(h, q, d)) * scale, d);
  }
  }
  o += "<polyline points=\"" + points + "\" fill=\"none\" stroke=\"#222222\" stroke-width=\"1.3\"/>\n";
  // The outer ring's value, so roses of one row can be compared.
  const std::string ring = q == RoseQuantity::Normals ? general(top, 3) : general(top / 1e3, 3) + " kN/m";
  o += "<text x=\"" + px(cx + radius + 10) + "\" y=\"" + px(cy - radius + 2) +
       "\" text-anchor=\"end\" font-size=\"9\" fill=\"#666666\">" + ring + "</text>\n";
  return o;
}

}  // namespace

std::vector<double> roseBinValues(const analysis::PolarHistograms& h, RoseQuantity q) {
  std::vector<double> values(static_cast<size_t>(std::max(h.bins, 0)), std::nan(""));
  for (size_t b = 0; b < values.size() && b < h.count.size(); ++b) {
    if (h.count[b] == 0) continue;
    switch (q) {
      case RoseQuantity::Normals:
        values[b] = h.ends > 0 ? static_cast<double>(h.count[b]) * h.bins / static_cast<double>(h.ends) : std::nan("");
        break;
      case RoseQuantity::NormalForce: values[b] = b < h.fn.size() ? h.fn[b] : std::nan(""); break;
      case RoseQuantity::TangentialForce: values[b] = b < h.ft.size() ? h.ft[b] : std::nan(""); break;
    }
  }
  return values;
}

double roseFitValue(const analysis::PolarHistograms& h, RoseQuantity q, double thetaDeg) {
  switch (q) {
    case RoseQuantity::Normals: return h.density.value(thetaDeg);
    case RoseQuantity::NormalForce: return h.fnFit.value(thetaDeg);
    case RoseQuantity::TangentialForce: return h.ftFit.value(thetaDeg);
  }
  return std::nan("");
}

std::string roseName(RoseQuantity q) {
  switch (q) {
    case RoseQuantity::Normals: return "contact normals";
    case RoseQuantity::NormalForce: return "mean f_n";
    case RoseQuantity::TangentialForce: return "mean f_t";
  }
  return "";
}

std::string renderRoseGrid(const std::string& id, const std::string& title,
                           const std::vector<const analysis::PolarHistograms*>& snapshots,
                           const std::vector<std::string>& captions, bool standalone) {
  const double w = kRowLabel + kCell * static_cast<double>(snapshots.size()) + 8;
  const double h = kHeader + kCell * static_cast<double>(quantities().size()) + 6;
  std::string o = "<svg";
  if (standalone) o += " xmlns=\"http://www.w3.org/2000/svg\"";
  o += " class=\"rose\" id=\"" + escapeMarkup(id) + "\" viewBox=\"0 0 " + px(w) + " " + px(h) + "\" width=\"" + px(w) +
       "\" height=\"" + px(h) + "\" role=\"img\" aria-label=\"" + escapeMarkup(title) +
       "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  o += "<title>" + escapeMarkup(title) + "</title>\n";
  o += "<rect x=\"0\" y=\"0\" width=\"" + px(w) + "\" height=\"" + px(h) + "\" fill=\"#ffffff\"/>\n";
  o += "<text x=\"" + px(w / 2) + "\" y=\"16\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">" +
       escapeMarkup(title) + "</text>\n";
  for (size_t c = 0; c < snapshots.size(); ++c) {
    const double cx = kRowLabel + kCell * (static_cast<double>(c) + 0.5);
    const std::string caption = c < captions.size() ? captions[c] : "";
    o += "<text x=\"" + px(cx) + "\" y=\"36\" text-anchor=\"middle\">" + escapeMarkup(caption) + "</text>\n";
  }
  for (size_t r = 0; r < quantities().size(); ++r) {
    const RoseQuantity q = quantities()[r];
    const double cy = kHeader + kCell * (static_cast<double>(r) + 0.5);
    o += "<text x=\"6\" y=\"" + px(cy + 4) + "\" fill=\"" + colourOf(q) + "\">" + escapeMarkup(roseName(q)) + "</text>\n";
    for (size_t c = 0; c < snapshots.size(); ++c) {
      const double cx = kRowLabel + kCell * (static_cast<double>(c) + 0.5);
      if (!snapshots[c]) {
        o += "<text x=\"" + px(cx) + "\" y=\"" + px(cy) + "\" text-anchor=\"middle\" fill=\"#888888\">not sampled</text>\n";
        continue;
      }
      o += rose(*snapshots[c], q, cx, cy, kCell / 2 - 12);
    }
  }
  o += "</svg>\n";
  return o;
}

}  // namespace grainlab::report

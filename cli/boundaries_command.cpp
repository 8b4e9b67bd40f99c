#include "boundaries_command.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "grainlab/errors.hpp"
#include "grainlab/studies/boundary_comparison/boundary_study.hpp"
#include "grainlab/studies/draw/svg_chart.hpp"
#include "option_list.hpp"

namespace grainlab {
namespace {

std::string axisLabel(const std::string& quantity) {
  if (quantity == "phi_mob_deg") return "φ_mob (°)";
  if (quantity == "a_c") return "a_c";
  return "ω (°)";
}

// One panel per quantity (rows) and assembly (columns): each boundary's ensemble mean with
// its 95 % interval shaded.
std::string curvesSvg(const boundaries::BoundaryStudy& study) {
  std::vector<std::string> assemblies, quantities;
  for (const auto& c : study.curves) {
    if (std::find(assemblies.begin(), assemblies.end(), c.assembly) == assemblies.end()) assemblies.push_back(c.assembly);
    if (std::find(quantities.begin(), quantities.end(), c.quantity) == quantities.end()) quantities.push_back(c.quantity);
  }
  const int w = 460, h = 300;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w * assemblies.size() << "\" height=\""
      << h * quantities.size() << "\">\n";
  for (size_t row = 0; row < quantities.size(); ++row)
    for (size_t col = 0; col < assemblies.size(); ++col) {
      report::ChartSpec spec;
      spec.id = "c" + std::to_string(row) + "_" + std::to_string(col);
      spec.title = assemblies[col] + ": " + axisLabel(quantities[row]) + ", mean and 95% interval";
      spec.xLabel = "axial strain ε22";
      spec.yLabel = axisLabel(quantities[row]);
      spec.width = w;
      spec.height = h;
      if (quantities[row] == "omega_macro_deg") {
        // Near zero strain the stress is isotropic and ω undefined: its intervals span ±90°.
        spec.yReferences = {0.0};
        spec.yMin = -45;
        spec.yMax = 45;
      }
      size_t colour = 0;
      for (const auto& c : study.curves) {
        if (c.assembly != assemblies[col] || c.quantity != quantities[row]) continue;
        report::LineSeries s(c.boundary, c.strain, {}, report::paletteColour(colour++));
        for (const report::MeanInterval& m : c.stats) {
          s.y.push_back(m.mean);
          s.low.push_back(m.low);
          s.high.push_back(m.high);
        }
        spec.series.push_back(std::move(s));
      }
      svg << "<g transform=\"translate(" << col * w << "," << row * h << ")\">\n"
          << report::renderLineChart(spec) << "</g>\n";
    }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace

int boundariesCommand(const std::vector<std::string>& args) {
  boundaries::BoundaryStudyOptions opt;
  try {
    for (size_t k = 0; k < args.size(); ++k) {
      const bool value = k + 1 < args.size();
      if (args[k] == "--out" && value) opt.outDir = args[++k];
      else if (args[k] == "--full") opt.quick = false;
      else if (args[k] == "--seeds" && value) opt.seeds = std::stoi(args[++k]);
      else if (args[k] == "--jobs" && value) opt.jobs = static_cast<unsigned>(std::stoul(args[++k]));
      else if (args[k] == "--assemblies" && value) opt.assemblies = splitList(args[++k]);
      else if (args[k] == "--axial-strain" && value) opt.axialStrain = std::stod(args[++k]);
      else if (args[k] == "--boundaries" && value) {
        for (const std::string& name : splitList(args[++k])) opt.boundaries.push_back(boundaries::parseBoundary(name));
      } else {
        std::cerr << "grainlab boundaries: unexpected argument " << args[k] << "\n";
        return 2;
      }
    }
    const boundaries::BoundaryStudy study = boundaries::runBoundaryStudy(opt, &std::cerr);
    const std::filesystem::path dir = opt.outDir;
    std::ofstream(dir / "curves.svg") << curvesSvg(study);
    std::cerr << "boundaries: " << study.runs << " runs, " << study.failedRuns << " failed; wrote "
              << (dir / "boundaries.csv").string() << ", runs.csv, curves.csv and curves.svg\n";
    return study.failedRuns == 0 ? 0 : 1;
  } catch (const SceneError& e) {
    std::cerr << "grainlab boundaries: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument&) {
    std::cerr << "grainlab boundaries: --seeds and --jobs take whole numbers, --axial-strain a number\n";
    return 2;
  }
}

}  // namespace grainlab

#include "shapes_command.hpp"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "grainlab/errors.hpp"
#include "grainlab/studies/draw/pareto_plot.hpp"
#include "grainlab/studies/shape_fidelity/shape_study.hpp"
#include "option_list.hpp"

namespace grainlab {
namespace {

// The default comparison (docs/shape-fidelity.md): clumps of 2, 3 and 5 discs; discs at the
// rolling frictions the calibration measured, and at the μ_r it interpolated on the quick
// specimens (0.64); plain discs.
std::vector<shapes::Representation> defaultRepresentations() {
  std::vector<shapes::Representation> reps;
  for (const char* name : {"clumps-2", "clumps-3", "clumps-5", "rolling-0.1", "rolling-0.2", "rolling-0.4", "rolling-0.6",
                           "rolling-0.8", "rolling-0.64", "discs"})
    reps.push_back(shapes::parseRepresentation(name));
  return reps;
}

}  // namespace

int shapesCommand(const std::vector<std::string>& args) {
  shapes::ShapeStudyOptions opt;
  try {
    for (size_t k = 0; k < args.size(); ++k) {
      const bool value = k + 1 < args.size();
      if (args[k] == "--out" && value) opt.outDir = args[++k];
      else if (args[k] == "--full") opt.quick = false;
      else if (args[k] == "--seeds" && value) opt.seeds = std::stoi(args[++k]);
      else if (args[k] == "--jobs" && value) opt.jobs = static_cast<unsigned>(std::stoul(args[++k]));
      else if (args[k] == "--assemblies" && value) opt.assemblies = splitList(args[++k]);
      else if (args[k] == "--representations" && value) {
        for (const std::string& name : splitList(args[++k])) opt.representations.push_back(shapes::parseRepresentation(name));
      } else {
        std::cerr << "grainlab shapes: unexpected argument " << args[k] << "\n";
        return 2;
      }
    }
    if (opt.representations.empty()) opt.representations = defaultRepresentations();
    const shapes::ShapeStudy study = shapes::runShapeStudy(opt, &std::cerr);
    const std::filesystem::path dir = opt.outDir;
    std::ofstream(dir / "shapes.svg") << tradeoff::renderParetoSvg(
        study.panels, "CPU s per run, preparation included (log scale)",
        "|bias| of peak φ_mob (°), 95% interval");
    if (std::isfinite(study.calibration.rollingFriction))
      std::cout << "rolling friction matching the hexagons' mean peak phi_mob (random): " << std::setprecision(3)
                << study.calibration.rollingFriction << " (between " << study.calibration.below << " and "
                << study.calibration.above << ")\n";
    else if (!study.calibration.note.empty())
      std::cout << "rolling friction calibration: " << study.calibration.note << "\n";
    std::cerr << "shapes: " << study.runs << " runs (" << study.runsSkipped << " were done), " << study.failedRuns
              << " failed; wrote " << (dir / "shapes.csv").string() << ", runs.csv, calibration.csv and shapes.svg\n";
    return study.failedRuns == 0 ? 0 : 1;
  } catch (const SceneError& e) {
    std::cerr << "grainlab shapes: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument&) {
    std::cerr << "grainlab shapes: --seeds and --jobs take whole numbers\n";
    return 2;
  }
}

}  // namespace grainlab

#include "grainlab/lammps/cell_deformation.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "grainlab/lammps/export.hpp"

namespace grainlab::lammps {
namespace {

std::string shortNum(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

}  // namespace

std::vector<CellRun> cellRuns(const Scene& scene, const StartingSpecimen& s) {
  const Eigen::Matrix2d& h = *s.cell;
  // LAMMPS's triclinic box has its first edge along x; grainlab's cells start square and its
  // strain-controlled paths keep h21 = 0, so a turned cell is refused rather than rotated.
  if (h(1, 0) != 0)
    throw ExportRefused("the periodic cell's first edge is not along x (h21 = " + shortNum(h(1, 0)) +
                        " m): LAMMPS's triclinic box is upper-triangular");
  // The velocity gradient the specimen was kept with (its last stage's, a servo's) is not
  // carried: grainlab starts each stage with the cell at rest and then sets the stage's own L
  // (RunContext::beginStage), so the exported run starts from the stage's streaming field.
  std::vector<CellRun> runs;
  const double dt = s.timestep;
  for (std::size_t k = s.firstStage; k < scene.stages.size(); ++k) {
    const StageSpec& stage = scene.stages[k];
    const std::string at = "stages[" + std::to_string(k) + "] (\"" + stage.name + "\")";
    if (stage.friction) throw ExportRefused(at + ".friction: LAMMPS keeps one pair_style");
    CellRun run;
    if (stage.type == StageSpec::Type::Free) {
      run.steps = std::lround(stage.duration / dt);
    } else if (stage.type == StageSpec::Type::Biaxial && stage.lateral == StageSpec::Lateral::ConstantVolume) {
      // grainlab's cell: D22 = rate, D11 = −D22 (compression positive), h ← (I + L dt) h each
      // step, until 1 − F22/F22(start) reaches the target: the first n with (1 − r dt)^n ≤ 1 − ε.
      run.rate11 = stage.strainRate;
      run.rate22 = -stage.strainRate;
      run.steps = static_cast<long>(
          std::ceil(std::log(1 - stage.targetAxialStrain) / std::log(1 - stage.strainRate * dt) - 1e-9));
    } else {
      throw ExportRefused(at + ".type \"" + std::string(toString(stage.type)) +
                          (stage.type == StageSpec::Type::Biaxial ? "\" with lateral \"constant_stress\"" : "\"") +
                          ": held by a stress servo; in a cell only free and constant-volume biaxial stages "
                          "(strain-controlled) map to fix deform");
    }
    if (!runs.empty() && (run.rate11 != runs.back().rate11 || run.rate22 != runs.back().rate22))
      throw ExportRefused(at + ": its strain rate differs from the stage before; LAMMPS's streaming velocities "
                               "are set once, so export one stage (with --from) at a time");
    runs.push_back(run);
  }
  return runs;
}

}  // namespace grainlab::lammps

#pragma once
// A scene's own periodic cell as LAMMPS's triclinic box, and the scene's remaining cell stages
// as fix deform (docs/periodic-cell.md, "Against LAMMPS"). LAMMPS's box is upper-triangular
// (edge 1 along x), and fix deform prescribes the box, so only strain-controlled stages with a
// diagonal velocity gradient map: constant-volume biaxial (L = diag(D, −D)) and free (L = 0).
#include <vector>

#include <Eigen/Core>

#include "grainlab/scene.hpp"
#include "grainlab/starting_specimen.hpp"

namespace grainlab::lammps {

struct CellRun {
  long steps = 0;
  double rate11 = 0, rate22 = 0;  ///< L11, L22, 1/s (true strain rates: LAMMPS's trate)
};

/// The cell's stages from specimen.firstStage on, each as LAMMPS steps under one L. Throws
/// ExportRefused naming the field for a cell that is not upper-triangular, a stage held by a
/// stress servo, a stage's own friction, or stages with different L (LAMMPS's streaming
/// velocities are set once, in the data file).
std::vector<CellRun> cellRuns(const Scene& scene, const StartingSpecimen& specimen);

}  // namespace grainlab::lammps

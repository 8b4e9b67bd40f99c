#pragma once
// A specimen and its run written for LAMMPS (docs/lammps.md): DIR/specimen.data (atom_style
// sphere, dimension 2), DIR/in.grainlab (the input script: gran/hooke/history with the mapped
// material, walls or a periodic cell, the timestep, fix deform, the dumps grainlab imports)
// and DIR/export.json (what was exported, with the mapped coefficients).
#include <array>
#include <optional>
#include <stdexcept>
#include <string>

#include "grainlab/scene.hpp"
#include "grainlab/starting_specimen.hpp"

namespace grainlab::lammps {

/// Something the scene needs that LAMMPS cannot do faithfully; what() is one line naming it.
/// Nothing has been written when it is thrown.
class ExportRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ExportOptions {
  /// The rectangle of the scene's four walls becomes a periodic cell (the walls are dropped).
  bool periodic = false;
  /// fix deform's rates in 1/s: x and y stretch (erate, extension positive) and xy shear
  /// (tilt erate: γ̇ of the xy tilt over ly0). Periodic cells only.
  std::optional<std::array<double, 3>> deform;
  /// LAMMPS steps to run; unset: the scene's remaining (free) stages, duration / timestep.
  std::optional<long> steps;
  /// Steps between dumps; unset: about 100 frames over the run.
  std::optional<long> dumpEvery;
  /// Export a scene with Cundall's local damping without it (LAMMPS has no equivalent).
  bool withoutLocalDamping = false;
  /// For the files' headers: where the specimen came from ("scene.json", "--preset NAME", ...).
  std::string origin;
};

struct ExportSummary {
  int particles = 0;
  long steps = 0;
  long dumpEvery = 0;
  double timestep = 0;  ///< s
  bool periodic = false;
};

/// A scene's own periodic cell is written as a triclinic box with its free and constant-volume
/// biaxial stages as fix deform (cell_deformation.hpp); the friction is the scene's, whatever a
/// preparation stage left in the specimen. Throws ExportRefused (nothing written) for polygons,
/// a membrane ring or any boundary or fixed particle, a servo-driven stage, local damping,
/// inclined walls, --periodic without a wall rectangle or with a cell, fix deform without a
/// periodic cell, or nothing to run. Throws
/// std::runtime_error if a file cannot be written.
ExportSummary exportLammps(const Scene& scene, const StartingSpecimen& specimen, const ExportOptions& options,
                           const std::string& directory);

}  // namespace grainlab::lammps

#pragma once
// Specimen generation: the paper's assemblies of discs, elongated convex polygons or clumps of
// discs in a line, placed
// at random without overlap inside a circle and enclosed by a ring of boundary particles.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "grainlab/particle.hpp"

namespace grainlab {

struct SpecimenRecipe {
  enum class Shape { Disc, Elongated, Clump };
  enum class Orientation { Random, Bedding };

  Shape shape = Shape::Disc;
  double discRadius = 0.002;                 ///< m, discs
  /// Elongated polygons and clumps: long-axis lengths L (m) and their fractions by count.
  std::vector<double> longAxes{0.0045, 0.0050, 0.0070};
  std::vector<double> countFractions;        ///< empty: chosen to meet the paper's grading
  /// Polygons: long / short axis of the circumscribing ellipse. Clumps: long axis / width
  /// (the member discs' diameter), below clump_discs so that neighbours overlap.
  double aspectRatio = 1.5;
  int vertices = 6;                          ///< 3..8
  int clumpDiscs = 3;                        ///< 2..8 equal discs along the long axis (clumps)
  Orientation orientation = Orientation::Random;
  double beddingAngle = 0;                   ///< rad, long axes at this angle (Bedding)
  double specimenDiameter = 0.160;           ///< m, the consolidated specimen's target size
  double targetVoidRatio = 0.27;             ///< sets the particle count for that diameter
  std::optional<int> particleCount;          ///< overrides the count derived above
  double boundaryRadius = 0;                 ///< m, ring particle radius; 0 = automatic
};

struct Specimen {
  /// Specimen particles first, then the boundary ring (Motion::Kinematic, boundary = true).
  std::vector<ParticleSpec> particles;
  int specimenCount = 0;                     ///< particles that are not boundary
  double initialRingRadius = 0;              ///< m, radius of the ring of boundary centres
};

/// Deterministic for a given recipe and seed.
Specimen generateSpecimen(const SpecimenRecipe& recipe, std::uint64_t seed);

/// A specimen for a periodic cell: no ring; the particles of the same recipe (grading,
/// shapes, orientations: random or bedding) placed at random without overlap, images
/// included, in a square cell at the circle's placement area fraction (0.45 discs, 0.40
/// others, looser if they do not fit).
struct CellSpecimen {
  std::vector<ParticleSpec> particles;
  Eigen::Matrix2d edges = Eigen::Matrix2d::Zero();  ///< m, the cell's edge vectors (columns)
  double solidArea = 0;                             ///< m², the particles' areas summed
};
/// Deterministic for a given recipe and seed. Throws SceneError as generateSpecimen does.
CellSpecimen generateCellSpecimen(const SpecimenRecipe& recipe, std::uint64_t seed);
/// The particles generateSpecimen(recipe, any seed) makes, without placing them: the
/// specimen's exactly, and the ring's for the first placement circle (a packing that must
/// be placed in a looser circle gets a few more ring discs). For limits checked before a
/// run is built (the server's --max-particles). Throws SceneError as generateSpecimen does.
int plannedParticleCount(const SpecimenRecipe& recipe);

/// Parses the scene's "assembly" object; errors name the field under `path` (e.g.
/// "assembly.vertices") through SceneError. Unknown keys are errors.
SpecimenRecipe parseSpecimenRecipe(const nlohmann::json& assembly, const std::string& path);
nlohmann::json specimenRecipeToJson(const SpecimenRecipe& recipe);

}  // namespace grainlab

#pragma once
// A scene: everything one run needs, parsed and validated from the JSON of
// shared docs/contracts.md. Parsing never half-succeeds: it returns a whole Scene or throws
// SceneError naming the field.
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/material.hpp"
#include "grainlab/particle.hpp"
#include "grainlab/specimen.hpp"
#include "grainlab/wall.hpp"

namespace grainlab {

struct StageSpec {
  enum class Type { Free, Compaction, Isotropic, Biaxial };
  Type type = Type::Free;
  std::string name;               ///< as reported in series.csv's `stage` column
  double duration = 0;            ///< s (free): how long to run
  double pressure = 0;            ///< Pa: target p (compaction, isotropic); σ11 held (biaxial)
  double strainRate = 0;          ///< 1/s: boundary strain-rate scale (compaction, isotropic
                                  ///< cap) or axial compression rate ε̇22 (biaxial)
  double targetAxialStrain = 0.2; ///< biaxial: stop at this ε22
  std::optional<double> friction; ///< overrides material.friction during the stage
  /// compaction: also stop once the void ratio inside the ring is this low (the particles are
  /// close; the pressure end then only catches a packing that jams looser)
  std::optional<double> voidRatio;
  /// s: the stage ends here even if its criterion is unmet (the parser sets finite defaults)
  double maxTime = std::numeric_limits<double>::infinity();
};

struct BoundarySpec {
  enum class Type { None, Membrane };
  Type type = Type::None;
};

/// The solver: grainlab's DEM ("solver.engine": "dem") or Box2D's rigid-body solver ("box2d",
/// engine/src/rigid_body_solver.hpp).
struct SolverSpec {
  enum class Engine { Dem, Box2d };
  Engine engine = Engine::Dem;
  double timestep = 0;            ///< s; 0 = timestepSafety × critical timestep (box2d: × its own scale)
  double timestepSafety = 0.2;
  int threads = 1;                ///< force computation threads (dem); results do not depend on it
  int velocityIterations = 8;     ///< box2d: b2World::Step's velocity iterations
  int positionIterations = 3;     ///< box2d: b2World::Step's position iterations
};

struct OutputSpec {
  double sampleInterval = 0;      ///< s between samples outside biaxial stages; 0 = automatic
  double sampleStrain = 0.001;    ///< axial strain between samples in biaxial stages
  bool fabric = true;             ///< anisotropy parameters and stress directions
  bool histograms = true;         ///< polar histograms at each sample (for the dashboard)
  int histogramBins = 18;
  bool vtk = false;               ///< ParaView frames in DIR/vtk (grainlab/vtk_writer.hpp)
  int vtkEvery = 1;               ///< a VTK frame at every vtkEvery-th sample (and at the end)
  /// s of wall time between checkpoints (grainlab/checkpoint.hpp), for runs that keep them
  /// (`grainlab run` and the server do). Writing one takes milliseconds for a few thousand
  /// particles.
  double checkpointEverySeconds = 60;
};

struct Scene {
  std::string name = "scene";
  std::uint64_t seed = 1;
  Material material;
  std::vector<ParticleSpec> particles;          ///< explicit particles
  std::optional<SpecimenRecipe> assembly;       ///< generated particles (added after explicit ones)
  std::vector<Wall> walls;
  Vec2 gravity = Vec2::Zero();
  BoundarySpec boundary;
  std::vector<StageSpec> stages;
  SolverSpec solver;
  OutputSpec output;
};

/// Throws SceneError(field, reason) for anything malformed, out of range or unknown.
Scene parseScene(const nlohmann::json& json);
/// Reads and parses a file; a JSON syntax error is a SceneError on field "(json)".
Scene loadSceneFile(const std::string& path);
/// The JSON of a scene file, unparsed; SceneError as loadSceneFile for a file that is not JSON.
nlohmann::json loadSceneJson(const std::string& path);

}  // namespace grainlab

#pragma once
// A scene: everything one run needs, parsed and validated from the JSON of
// shared docs/contracts.md. Parsing never half-succeeds: it returns a whole Scene or throws
// SceneError naming the field.
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/material.hpp"
#include "grainlab/particle.hpp"
#include "grainlab/specimen.hpp"
#include "grainlab/wall.hpp"

namespace grainlab {

struct StageSpec {
  enum class Type { Free, Compaction, Isotropic, Biaxial, Rotation, Cyclic, SimpleShear };
  /// What the lateral boundary of a biaxial or cyclic stage holds: σ11, or the area.
  enum class Lateral { ConstantStress, ConstantVolume };
  Type type = Type::Free;
  std::string name;               ///< as reported in series.csv's `stage` column
  double duration = 0;            ///< s (free, rotation): how long to run
  double pressure = 0;            ///< Pa: target p (compaction, isotropic, rotation's
                                  ///< mean_stress); σ11 held (biaxial, cyclic); σ22 held
                                  ///< (simple_shear's normal_stress)
  double strainRate = 0;          ///< 1/s: boundary strain-rate scale (compaction, isotropic
                                  ///< cap) or axial compression rate ε̇22 (biaxial)
  double targetAxialStrain = 0.2; ///< biaxial: stop at this ε22
  Lateral lateral = Lateral::ConstantStress;  ///< biaxial, cyclic
  /// rotation: ε̇1 − ε̇3 of the deviatoric strain rate, 1/s (its principal values are ±½ of it)
  double deviatoricStrainRate = 0;
  double rotationRateDeg = 0;     ///< rotation: °/s, counter-clockwise positive
  /// rotation: the one of rotation_rate_deg_per_s, total_rotation_deg and duration that the
  /// parser derived from the other two (not a field the scene gave)
  std::string rotationDerivedField;
  double initialDirectionDeg = 90;///< rotation: θ_ε̇ at the start (90° = vertical compression);
                                  ///< in a periodic cell the major principal stress direction θσ
  /// rotation in a periodic cell: the deviatoric stress q = ½(σ1 − σ2) held while the stress
  /// axes turn, Pa (the cell's rotation is stress-controlled; 0 for the ring's)
  double deviatoricStress = 0;
  std::optional<double> strainAmplitude;  ///< cyclic: reverse at axial strain ±amplitude
  std::optional<std::pair<double, double>> qOverPLimits;  ///< cyclic: or at these (σ22−σ11)/(σ22+σ11)
  int cycles = 1;                 ///< cyclic: a cycle is up to the upper limit and down to the lower
  double shearRate = 0;           ///< simple_shear: γ̇, 1/s
  double targetShearStrain = 0.2; ///< simple_shear: stop at this γ
  std::optional<double> friction; ///< overrides material.friction during the stage
  /// compaction: also stop once the void ratio inside the ring is this low (the particles are
  /// close; the pressure end then only catches a packing that jams looser)
  std::optional<double> voidRatio;
  /// s: the stage ends here even if its criterion is unmet (the parser sets finite defaults)
  double maxTime = std::numeric_limits<double>::infinity();
};

/// Stages that shear the specimen (the paper's biaxial stage and the loading paths): strains
/// are measured from their start, and they are the bulk of a run's work.
inline bool isShearing(StageSpec::Type t) {
  return t == StageSpec::Type::Biaxial || t == StageSpec::Type::Rotation || t == StageSpec::Type::Cyclic ||
         t == StageSpec::Type::SimpleShear;
}

/// A stage's share of a run's work, for progress: a shearing stage counts four others.
inline double stageWork(StageSpec::Type t) { return isShearing(t) ? 4.0 : 1.0; }

/// A stage type's name in scene JSON ("free", "compaction", "isotropic", "biaxial",
/// "rotation", "cyclic", "simple_shear"): one table for the parser, the studies and the docs.
std::string_view toString(StageSpec::Type type);
/// The stage type a name gives; nothing for any other string.
std::optional<StageSpec::Type> parseStageType(std::string_view name);
/// Every stage type, in the order of the enum.
std::span<const StageSpec::Type> stageTypes();

struct BoundarySpec {
  /// None; the paper's ring of boundary particles; or a periodic cell (docs/periodic-cell.md).
  enum class Type { None, Membrane, Periodic };
  Type type = Type::None;
  /// periodic: the rectangular cell's width and height, m, for explicit particles; with an
  /// assembly the cell is sized by the specimen's placement (generateCellSpecimen).
  std::optional<Vec2> cellSize;
  /// periodic: the largest strain rate a stress servo of the cell may command in biaxial and
  /// simple_shear stages, 1/s: at 3 /s a 4 mm disc at 300 kPa has an inertial number of 1e-3
  /// (docs/periodic-cell.md), and the servo keeps up with dilation at shearing rates of 1 /s.
  double rateCap = 3;
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
  /// output.stage_checkpoints: keep the run's state at the end of each stage, so a later run
  /// can start from it (grainlab/prepared_specimen.hpp). Unset: on for dem, off for box2d
  /// (box2d must rebuild its b2World at a stage's end to save it, which changes what follows).
  std::optional<bool> stageCheckpoints;
};

/// "start_from": the prepared specimen a run starts from instead of running its own first
/// stages (grainlab/prepared_specimen.hpp). Either `run` (a run's directory) with `stage`
/// (empty: the stage before the scene's first shearing stage), or `checkpoint` (a file), or
/// `run_id` with `stage`: a run stored by `grainlab serve`, which only the server resolves (it
/// then sets `checkpoint` to that run's stage checkpoint in its own storage).
struct StartFrom {
  std::string run;
  std::string stage;
  std::string checkpoint;
  std::int64_t runId = 0;  ///< 0: none
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
  std::optional<StartFrom> startFrom;
};

/// Throws SceneError(field, reason) for anything malformed, out of range or unknown.
Scene parseScene(const nlohmann::json& json);
/// Reads and parses a file; a JSON syntax error is a SceneError on field "(json)".
Scene loadSceneFile(const std::string& path);
/// The JSON of a scene file, unparsed; SceneError as loadSceneFile for a file that is not JSON.
nlohmann::json loadSceneJson(const std::string& path);

}  // namespace grainlab

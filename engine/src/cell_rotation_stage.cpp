// The scene's `rotation` stage in a periodic cell: the principal stress axes turn at constant
// p and q, stress-controlled (docs/periodic-cell.md, "Rotation of the stress axes"). The three
// servos of a CellStage hold σ11, σ22 = p ± q cos 2θ and ½(σ12 + σ21) = q sin 2θ; the strain
// rate that follows is measured.
//
// Two phases, as rotation tests are run in the literature: the stress is first brought from
// wherever the stage before left it (isotropic, usually) to (p, q) at θ0 and held until steady;
// only then do the axes turn, at θ̇ for the stage's duration. Turning from an isotropic state
// would turn axes that do not exist yet.
#include <algorithm>
#include <cmath>
#include <limits>

#include "grainlab/math.hpp"
#include "grainlab/stages.hpp"
#include "grainlab/state_archive.hpp"
#include "periodic_stages.hpp"

namespace grainlab {
namespace {

// Steady: every held component within this fraction of p of its target at this many successive
// servo measurements (four per response time: five response times), as the isotropic stage.
constexpr double kSteadyTolerance = 0.005;
constexpr int kSteadyMeasurements = 20;

class CellRotationStage : public Stage {
 public:
  CellRotationStage(const StageSpec& spec, const OutputSpec& output, World& world, const CellLoading& loading)
      : spec_(spec), world_(world), cell_(spec.name, loading, world, spec.maxTime, output.sampleInterval),
        startTime_(world.time()),
        spacing_(output.sampleInterval > 0 ? output.sampleInterval : spec.duration / 180) {
    cell_.turnAxesFrom(kNotYet);
  }

  const std::string& name() const override { return spec_.name; }
  void beforeStep() override {
    cell_.beforeStep();
    if (turning() || steps_ % cell_.measureEvery() != 0) return;
    steady_ = heldAtTarget() ? steady_ + 1 : 0;
    if (steady_ >= kSteadyMeasurements) {
      turnStart_ = world_.time();
      cell_.turnAxesFrom(turnStart_);
    }
  }
  void afterStep() override { ++steps_; }
  bool finished() const override { return turned() >= spec_.duration || elapsed() >= spec_.maxTime; }
  double progress() const override { return std::clamp(turned() / spec_.duration, 0.0, 1.0); }
  double work() const override { return stageWork(spec_.type); }
  double sampleCoordinate() const override { return elapsed(); }
  double sampleSpacing() const override { return spacing_; }
  std::string endNote() const override {
    if (turned() >= spec_.duration) return {};
    if (!turning())
      return "reached its max_time of " + std::to_string(spec_.maxTime) +
             " s before the stress held p and q (is q/p above what the specimen can carry?)";
    return "reached its max_time of " + std::to_string(spec_.maxTime) + " s before the axes turned the whole rotation";
  }
  void persist(StateArchive& a) override {
    a.section("cell rotation stage");
    a(startTime_);
    a(turnStart_);
    a(steps_);
    a(steady_);
    cell_.persist(a);
    cell_.turnAxesFrom(turnStart_);  // CellStage does not keep it
  }

 private:
  static constexpr double kNotYet = std::numeric_limits<double>::infinity();

  double elapsed() const { return world_.time() - startTime_; }
  bool turning() const { return turnStart_ != kNotYet; }
  double turned() const { return turning() ? world_.time() - turnStart_ : 0.0; }
  // The stress at the last servo measurement against the targets at θ0, each within a fraction
  // of p (the scale of every component).
  bool heldAtTarget() const {
    const StressTensor& s = cell_.stress();
    const double p = spec_.pressure, q = spec_.deviatoricStress;
    const double theta = spec_.initialDirectionDeg * kPi / 180;
    const double tolerance = kSteadyTolerance * p;
    return std::abs(s.s11 - (p + q * std::cos(2 * theta))) <= tolerance &&
           std::abs(s.s22 - (p - q * std::cos(2 * theta))) <= tolerance &&
           std::abs(0.5 * (s.s12 + s.s21) - q * std::sin(2 * theta)) <= tolerance;
  }

  StageSpec spec_;
  World& world_;
  CellStage cell_;
  double startTime_, spacing_;
  double turnStart_ = kNotYet;
  std::int64_t steps_ = 0;
  std::int64_t steady_ = 0;
};

}  // namespace

std::unique_ptr<Stage> makeCellRotationStage(const StageSpec& spec, const OutputSpec& output, World& world,
                                             double rateCap) {
  CellLoading loading;
  loading.rateCap = rateCap;
  loading.crossings = 0.1;  // as the cell's other scene stages (cell_scene_stages.cpp)
  loading.rotation = {spec.pressure, spec.deviatoricStress, spec.initialDirectionDeg * kPi / 180,
                      spec.rotationRateDeg * kPi / 180};
  return std::make_unique<CellRotationStage>(spec, output, world, loading);
}

}  // namespace grainlab

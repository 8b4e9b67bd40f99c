// The scene's stage types in a periodic cell: each a CellStage (periodic_stages.hpp) with the
// components the path prescribes or holds, and the stage's own end criterion, as the ring's
// stages of the same type end (docs/periodic-cell.md, "Scenes").
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "free_stage.hpp"
#include "grainlab/stages.hpp"
#include "grainlab/state_archive.hpp"
#include "periodic_stages.hpp"

namespace grainlab {
namespace {

// Isotropic compression ends when σ11 and σ22 have both been within this fraction of p at
// this many successive servo measurements (four per response time: five response times).
constexpr double kIsotropicTolerance = 0.005;
constexpr int kSteadyMeasurements = 20;

class CellSceneStage : public Stage {
 public:
  enum class End { Steady, AxialStrain, ShearStrain };

  CellSceneStage(const StageSpec& spec, const OutputSpec& output, World& world, const CellLoading& loading, End end)
      : spec_(spec), world_(world), cell_(spec.name, loading, world, spec.maxTime, output.sampleInterval), end_(end),
        startTime_(world.time()), startF22_(world.periodicCell()->deformation()(1, 1)),
        spacing_(end == End::Steady ? (output.sampleInterval > 0 ? output.sampleInterval : 0.005) : output.sampleStrain) {}

  const std::string& name() const override { return spec_.name; }
  void beforeStep() override {
    cell_.beforeStep();
    if (steps_ % cell_.measureEvery() == 0 && end_ == End::Steady) {
      const StressTensor& s = cell_.stress();
      const double p = spec_.pressure;
      const bool near = std::abs(s.s11 - p) <= kIsotropicTolerance * p && std::abs(s.s22 - p) <= kIsotropicTolerance * p;
      steady_ = near ? steady_ + 1 : 0;
    }
  }
  void afterStep() override {
    cell_.afterStep();
    ++steps_;
  }
  bool finished() const override { return reached() || elapsed() >= spec_.maxTime; }
  double progress() const override {
    const double byTime = std::clamp(elapsed() / spec_.maxTime, 0.0, 1.0);
    if (end_ == End::AxialStrain) return std::clamp(axialStrain() / spec_.targetAxialStrain, 0.0, 1.0);
    if (end_ == End::ShearStrain) return std::clamp(shearStrain() / spec_.targetShearStrain, 0.0, 1.0);
    return reached() ? 1.0 : byTime;
  }
  double work() const override { return stageWork(spec_.type); }
  double sampleCoordinate() const override {
    return end_ == End::AxialStrain ? axialStrain() : end_ == End::ShearStrain ? shearStrain() : elapsed();
  }
  double sampleSpacing() const override { return spacing_; }
  std::string endNote() const override {
    return reached() ? std::string() : "reached its max_time of " + std::to_string(spec_.maxTime) + " s before its criterion";
  }
  void persist(StateArchive& a) override {
    a.section("cell scene stage");
    a(startTime_);
    a(startF22_);
    a(steps_);
    a(steady_);
    cell_.persist(a);
  }

 private:
  double elapsed() const { return world_.time() - startTime_; }
  // The cell's compression along axis 2 since the stage began (the ring's 1 − stretch2 / ref).
  double axialStrain() const { return 1 - world_.periodicCell()->deformation()(1, 1) / startF22_; }
  // γ of simple shear, the prescribed rate times the time (the cell's shear follows it exactly).
  double shearStrain() const { return spec_.shearRate * elapsed(); }
  bool reached() const {
    switch (end_) {
      case End::Steady: return steady_ >= kSteadyMeasurements;
      case End::AxialStrain: return axialStrain() >= spec_.targetAxialStrain;
      case End::ShearStrain: return shearStrain() >= spec_.targetShearStrain;
    }
    return false;
  }

  StageSpec spec_;
  World& world_;
  CellStage cell_;
  End end_;
  double startTime_, startF22_, spacing_;
  std::int64_t steps_ = 0;
  std::int64_t steady_ = 0;
};

}  // namespace

std::unique_ptr<Stage> makeCellStage(const StageSpec& spec, const OutputSpec& output, World& world, double rateCap) {
  using T = StageSpec::Type;
  using End = CellSceneStage::End;
  CellLoading loading;
  loading.rateCap = rateCap;
  // A tenth of an elastic-wave crossing: the response with which the engine's servo tests
  // hold σ within 0.5 % while the cell is sheared at 1 /s (docs/periodic-cell.md).
  loading.crossings = 0.1;
  switch (spec.type) {
    case T::Free: return std::make_unique<FreeStage>(spec, output, world);
    case T::Isotropic:
      loading.rateCap = spec.strainRate;  // as the ring's isotropic stage: its strain_rate caps the servos
      loading.d11 = loading.d22 = CellComponent::holding(spec.pressure);
      loading.d12 = CellComponent::prescribed(0);
      return std::make_unique<CellSceneStage>(spec, output, world, loading, End::Steady);
    case T::Biaxial:
      // The paper's path: axis 2 compressed at the rate, σ11 held (or the area held).
      loading.d22 = CellComponent::prescribed(spec.strainRate);
      loading.d11 = spec.lateral == StageSpec::Lateral::ConstantStress ? CellComponent::holding(spec.pressure)
                                                                       : CellComponent::prescribed(-spec.strainRate);
      loading.d12 = CellComponent::prescribed(0);
      return std::make_unique<CellSceneStage>(spec, output, world, loading, End::AxialStrain);
    case T::SimpleShear:
      // v₁ = γ̇ x₂: D12 = −γ̇/2 (compression positive), w = γ̇/2; σ22 held.
      loading.d11 = CellComponent::prescribed(0);
      loading.d22 = CellComponent::holding(spec.pressure);
      loading.d12 = CellComponent::prescribed(-0.5 * spec.shearRate);
      loading.spin = 0.5 * spec.shearRate;
      return std::make_unique<CellSceneStage>(spec, output, world, loading, End::ShearStrain);
    case T::Rotation: return makeCellRotationStage(spec, output, world, rateCap);
    default: break;
  }
  throw std::invalid_argument("a periodic cell cannot run a " + std::string(toString(spec.type)) + " stage");
}

}  // namespace grainlab

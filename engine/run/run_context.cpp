#include "run_context.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "grainlab/errors.hpp"
#include "grainlab/membrane.hpp"
#include "grainlab/specimen.hpp"
#include "grainlab/stages.hpp"

namespace grainlab {

RunContext::RunContext(const Scene& scene) : scene_(scene), monitor_(scene) {
  WorldSettings settings;
  settings.threads = scene.solver.threads;
  if (scene.solver.engine == SolverSpec::Engine::Box2d) {
    settings.engine = WorldSettings::Engine::Box2d;
    settings.velocityIterations = scene.solver.velocityIterations;
    settings.positionIterations = scene.solver.positionIterations;
  }
  world_ = std::make_unique<World>(scene.material, settings);
  for (const ParticleSpec& p : scene.particles) world_->addParticle(p);
  if (scene.boundary.type == BoundarySpec::Type::Periodic) {
    buildCell(scene);
  } else if (scene.assembly) {
    const Specimen specimen = generateSpecimen(*scene.assembly, scene.seed);
    const bool membrane = scene.boundary.type == BoundarySpec::Type::Membrane;
    for (const ParticleSpec& p : specimen.particles) {
      if (p.boundary && !membrane) continue;  // no ring asked for
      world_->addParticle(p);
    }
  }
  for (const Wall& w : scene.walls) world_->addWall(w);
  world_->setGravity(scene.gravity);
  world_->setTimestepSafety(scene.solver.timestepSafety);
  if (scene.solver.timestep > 0) world_->setTimestep(scene.solver.timestep);
  try {
    world_->initialize();  // contacts exist before the first sample checks them
  } catch (const SimulationError& e) {
    // Over the critical timestep: the field is the timestep the scene gives.
    if (scene.solver.timestep > 0) throw SceneError("solver.timestep", e.what());
    throw;
  }
  if (scene.boundary.type == BoundarySpec::Type::Membrane) {
    membrane_ = std::make_unique<Membrane>(*world_);
    sampled_ = sampleMembrane(*membrane_);
  }
  if (world_->periodicCell()) sampled_ = sampleCell(*world_);
  sampler_ = std::make_unique<Sampler>(scene.output, *world_, sampled_.get());
}

RunContext::~RunContext() = default;

void RunContext::buildCell(const Scene& scene) {
  Eigen::Matrix2d h = Eigen::Matrix2d::Zero();
  std::vector<ParticleSpec> particles;
  if (scene.assembly) {
    CellSpecimen specimen = generateCellSpecimen(*scene.assembly, scene.seed);
    h = specimen.edges;
    particles = std::move(specimen.particles);
  } else {
    h(0, 0) = scene.boundary.cellSize->x();
    h(1, 1) = scene.boundary.cellSize->y();
  }
  try {
    world_->setPeriodicCell(h);
  } catch (const std::invalid_argument& e) {
    throw SceneError(scene.assembly ? "boundary.type" : "boundary.size", e.what());
  }
  for (const ParticleSpec& p : particles) world_->addParticle(p);
}

double RunContext::voidRatioNow() const {
  if (!sampled_) return std::numeric_limits<double>::quiet_NaN();
  return (sampled_->area() - sampled_->solidArea()) / sampled_->solidArea();
}

double RunContext::totalWork() const {
  double work = 0;
  for (const StageSpec& s : scene_.stages) work += stageWork(s.type);
  return work;
}

Stage& RunContext::beginStage(size_t index) {
  stageIndex_ = index;
  const StageSpec& spec = scene_.stages[index];
  world_->setFriction(spec.friction.value_or(scene_.material.friction));
  // Each stage starts from a cell at rest. Stopping it here rather than in endStage keeps the
  // ended stage's L in its kept specimen, so a run started from that specimen samples the
  // same state as the run that kept it (its strain-rate columns included).
  if (world_->periodicCell()) world_->setCellVelocityGradient(Eigen::Matrix2d::Zero());
  if (spec.type == StageSpec::Type::Isotropic || isShearing(spec.type)) {
    sampler_->resetStrainReference();
  }
  stage_ = newStage(spec);
  stageStartSample_ = true;
  nextSample_ = stage_->sampleCoordinate() + stage_->sampleSpacing();
  return *stage_;
}

std::unique_ptr<Stage> RunContext::newStage(const StageSpec& spec) {
  if (world_->periodicCell()) return makeCellStage(spec, scene_.output, *world_, scene_.boundary.rateCap);
  return makeStage(spec, scene_.output, *world_, membrane_.get());
}

void RunContext::endStage() {
  if (scene_.stages[stageIndex_].type == StageSpec::Type::Isotropic) {
    voidRatioAfterConsolidation_ = sampler_->lastVoidRatio();
  }
  if (membrane_) membrane_->setStrainRates(0, 0);
}

void RunContext::persist(StateArchive& a) {
  a.section("run context");
  std::uint64_t stage = stageIndex_;
  a(stage);
  a.require(stage < scene_.stages.size(), "stage " + std::to_string(stage) + " is past the scene's stages");
  a(nextSample_);
  a(lastSampleStep_);
  a(voidRatioAfterConsolidation_);
  a(sampleSeconds_);
  world_->persist(a);
  if (membrane_) membrane_->persist(a);
  sampler_->persist(a);
  monitor_.persist(a);
  if (a.loading()) {
    // As beginStage, without what it resets: friction, strain references and the next
    // sample come from the checkpoint.
    stageIndex_ = static_cast<size_t>(stage);
    stage_ = newStage(scene_.stages[stageIndex_]);
  }
  a.section("stage");
  stage_->persist(a);
}

bool RunContext::sampleDue() const { return stage_->sampleCoordinate() >= nextSample_; }

void RunContext::sample(RunObserver& observer) {
  if (world_->stepCount() == lastSampleStep_) return;  // a stage's end may coincide with a sample
  lastSampleStep_ = world_->stepCount();
  world_->checkHealth();  // a diverged state never reaches the results
  const double rate = sampled_ ? sampled_->rateMagnitude() : 0.0;
  lastSampleRate_ = rate;
  const auto t0 = std::chrono::steady_clock::now();
  const Sample s = sampler_->measure(static_cast<int>(stageIndex_), scene_.stages[stageIndex_], rate);
  sampleSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  monitor_.observe(s, *world_, stageIndex_, stageStartSample_);
  stageStartSample_ = false;
  observer.onSample(s, *world_);
  // The next multiple of the spacing past where the stage is: computed, not stepped to, so
  // a spacing too small to change a large coordinate cannot loop forever.
  const double spacing = stage_->sampleSpacing(), at = stage_->sampleCoordinate();
  nextSample_ = std::max(nextSample_, (std::floor(at / spacing) + 1) * spacing);
  if (!(nextSample_ > at)) nextSample_ = std::nextafter(at, std::numeric_limits<double>::infinity());
}

}  // namespace grainlab

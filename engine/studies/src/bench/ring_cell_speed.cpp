#include "grainlab/studies/bench/ring_cell_speed.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "grainlab/errors.hpp"
#include "grainlab/membrane.hpp"
#include "grainlab/periodic_cell.hpp"
#include "grainlab/specimen.hpp"
#include "grainlab/stages.hpp"
#include "grainlab/thread_cpu_clock.hpp"

namespace grainlab::bench {
namespace {

// A scene's specimen built and prepared as a run of it builds and prepares it (run_context.cpp:
// the world, the ring, each stage's friction, the cell at rest when a stage begins), without
// the sampling; then its shearing stage, begun.
struct ShearingSpecimen {
  std::unique_ptr<World> world;
  std::unique_ptr<Membrane> membrane;  // the ring's; none in a cell
  std::unique_ptr<Stage> shearing;     // refers to the two above: declared after them
  std::vector<double> specimenRadii;  // sorted: the ring's and the cell's must be the same
  int specimenParticles = 0;
  double voidRatio = 0;
};

std::unique_ptr<Stage> beginStage(const Scene& scene, const StageSpec& spec, World& world, Membrane* membrane) {
  world.setFriction(spec.friction.value_or(scene.material.friction));
  if (world.periodicCell()) {
    world.setCellVelocityGradient(Eigen::Matrix2d::Zero());
    return makeCellStage(spec, scene.output, world, scene.boundary.rateCap);
  }
  return makeStage(spec, scene.output, world, membrane);
}

void checkFits(const Scene& scene, BoundarySpec::Type boundary, const std::string& side) {
  if (!scene.assembly || scene.assembly->shape != SpecimenRecipe::Shape::Disc)
    throw SceneError(side + ".assembly", "the ring-cell bench compares disc assemblies");
  if (scene.boundary.type != boundary)
    throw SceneError(side + ".boundary.type", boundary == BoundarySpec::Type::Periodic ? "must be periodic" : "must be membrane");
  if (scene.stages.empty() || !isShearing(scene.stages.back().type))
    throw SceneError(side + ".stages", "must end in a shearing stage");
}

ShearingSpecimen prepare(const Scene& scene, int threads, std::ostream* progress) {
  ShearingSpecimen s;
  WorldSettings settings;
  settings.threads = threads;
  s.world = std::make_unique<World>(scene.material, settings);
  World& world = *s.world;
  const bool periodic = scene.boundary.type == BoundarySpec::Type::Periodic;
  double solid = 0;
  if (periodic) {
    const CellSpecimen specimen = generateCellSpecimen(*scene.assembly, scene.seed);
    world.setPeriodicCell(specimen.edges);
    for (const ParticleSpec& p : specimen.particles) {
      world.addParticle(p);
      s.specimenRadii.push_back(p.radius);
    }
    solid = specimen.solidArea;
  } else {
    for (const ParticleSpec& p : generateSpecimen(*scene.assembly, scene.seed).particles) {
      world.addParticle(p);
      if (!p.boundary) s.specimenRadii.push_back(p.radius);
    }
  }
  std::sort(s.specimenRadii.begin(), s.specimenRadii.end());
  s.specimenParticles = static_cast<int>(s.specimenRadii.size());
  world.setTimestepSafety(scene.solver.timestepSafety);
  if (scene.solver.timestep > 0) world.setTimestep(scene.solver.timestep);
  world.initialize();
  if (!periodic) s.membrane = std::make_unique<Membrane>(world);
  size_t k = 0;
  for (; !isShearing(scene.stages[k].type); ++k) {
    if (progress) *progress << "bench: " << scene.name << ": " << scene.stages[k].name << "\n";
    const std::unique_ptr<Stage> stage = beginStage(scene, scene.stages[k], world, s.membrane.get());
    for (std::int64_t n = 1; !stage->finished(); ++n) {
      stage->beforeStep();
      world.step();
      stage->afterStep();
      if (n % 1000 == 0) world.checkHealth();
    }
    if (s.membrane) s.membrane->setStrainRates(0, 0);
  }
  world.checkHealth();
  s.voidRatio = periodic ? (world.periodicCell()->area() - solid) / solid : s.membrane->voidRatio();
  s.shearing = beginStage(scene, scene.stages[k], world, s.membrane.get());
  return s;
}

// One timed repeat of `steps` steps of the shearing stage (its servo and boundary included).
void timeRepeat(ShearingSpecimen& s, int steps, int threads, PileSpeed& into) {
  World& world = *s.world;
  Stage& stage = *s.shearing;
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = threadCpuSeconds();
  for (int n = 0; n < steps; ++n) {
    stage.beforeStep();
    world.step();
    stage.afterStep();
  }
  const double cpu = threadCpuSeconds() - cpu0;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (stage.finished()) throw SimulationError("the shearing stage of the bench's specimen ended inside the timing: fewer steps");
  into.rates.push_back(world.size() * static_cast<double>(steps) / wall);
  if (threads == 1) into.cpuRates.push_back(world.size() * static_cast<double>(steps) / cpu);
}

ShearingSpeed describe(const Scene& scene, const ShearingSpecimen& s) {
  std::vector<ContactRecord> contacts;
  s.world->contacts(contacts);
  ShearingSpeed r;
  r.speed = PileSpeed{scene.name, s.world->size(), 2.0 * contacts.size() / s.world->size(), {}, s.world->timestep()};
  r.specimenParticles = s.specimenParticles;
  r.voidRatio = s.voidRatio;
  return r;
}

}  // namespace

RingCellSpeeds measureCellAgainstRing(const Scene& ring, const Scene& cell, int steps, int repeats, int threads,
                                      std::ostream* progress) {
  checkFits(ring, BoundarySpec::Type::Membrane, "ring");
  checkFits(cell, BoundarySpec::Type::Periodic, "cell");
  ShearingSpecimen r = prepare(ring, threads, progress), c = prepare(cell, threads, progress);
  if (r.specimenRadii != c.specimenRadii)
    throw SceneError("cell.assembly", "the cell's particles (" + std::to_string(c.specimenParticles) +
                                          ") are not the ring specimen's (" + std::to_string(r.specimenParticles) +
                                          "): give both the same recipe and seed");
  RingCellSpeeds out{describe(ring, r), describe(cell, c)};
  const double ring0 = r.shearing->sampleCoordinate(), cell0 = c.shearing->sampleCoordinate();
  if (progress) *progress << "bench: timing " << ring.name << " and " << cell.name << " in turn, shearing\n";
  for (int rep = 0; rep < repeats; ++rep) {
    timeRepeat(r, steps, threads, out.ring.speed);
    timeRepeat(c, steps, threads, out.cell.speed);
  }
  r.world->checkHealth();
  c.world->checkHealth();
  out.ring.axialStrainTimed = r.shearing->sampleCoordinate() - ring0;
  out.cell.axialStrainTimed = c.shearing->sampleCoordinate() - cell0;
  return out;
}

}  // namespace grainlab::bench

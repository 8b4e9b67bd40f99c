#include "grainlab/studies/bench/ring_cell_speed.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "grainlab/errors.hpp"
#include "grainlab/prepared_shearing.hpp"
#include "grainlab/stages.hpp"
#include "grainlab/thread_cpu_clock.hpp"

namespace grainlab::bench {
namespace {

// One side: its specimen prepared as a run prepares it, and the radii of its own particles.
struct ShearingSpecimen {
  std::unique_ptr<PreparedShearing> prepared;
  std::vector<double> specimenRadii;  // sorted: the ring's and the cell's must be the same
};

void checkFits(const Scene& scene, BoundarySpec::Type boundary, const std::string& side) {
  if (!scene.assembly || scene.assembly->shape != SpecimenRecipe::Shape::Disc)
    throw SceneError(side + ".assembly", "the ring-cell bench compares disc assemblies");
  if (scene.boundary.type != boundary)
    throw SceneError(side + ".boundary.type", boundary == BoundarySpec::Type::Periodic ? "must be periodic" : "must be membrane");
  if (scene.stages.empty() || !isShearing(scene.stages.back().type))
    throw SceneError(side + ".stages", "must end in a shearing stage");
}

ShearingSpecimen prepare(Scene scene, int threads, std::ostream* progress) {
  scene.solver.threads = threads;
  ShearingSpecimen s;
  s.prepared = std::make_unique<PreparedShearing>(std::move(scene), progress);
  const World& world = s.prepared->world();
  for (int k = 0; k < world.size(); ++k) {
    if (!world.boundaryFlags()[static_cast<size_t>(k)]) s.specimenRadii.push_back(world.boundingRadii()[static_cast<size_t>(k)]);
  }
  std::sort(s.specimenRadii.begin(), s.specimenRadii.end());
  return s;
}

// One timed repeat of `steps` steps of the shearing stage (its servo and boundary included).
void timeRepeat(ShearingSpecimen& s, int steps, int threads, PileSpeed& into) {
  World& world = s.prepared->world();
  Stage& stage = s.prepared->shearing();
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
  const World& world = s.prepared->world();
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  ShearingSpeed r;
  r.speed = PileSpeed{scene.name, world.size(), 2.0 * contacts.size() / world.size(), {}, world.timestep(), {}};
  r.specimenParticles = static_cast<int>(s.specimenRadii.size());
  r.voidRatio = s.prepared->voidRatio();
  return r;
}

}  // namespace

RingCellSpeeds measureCellAgainstRing(const Scene& ring, const Scene& cell, int steps, int repeats, int threads,
                                      std::ostream* progress) {
  checkFits(ring, BoundarySpec::Type::Membrane, "ring");
  checkFits(cell, BoundarySpec::Type::Periodic, "cell");
  ShearingSpecimen r = prepare(ring, threads, progress), c = prepare(cell, threads, progress);
  if (r.specimenRadii != c.specimenRadii)
    throw SceneError("cell.assembly", "the cell's particles (" + std::to_string(c.specimenRadii.size()) +
                                          ") are not the ring specimen's (" + std::to_string(r.specimenRadii.size()) +
                                          "): give both the same recipe and seed");
  RingCellSpeeds out{describe(ring, r), describe(cell, c)};
  const double ring0 = r.prepared->shearing().sampleCoordinate(), cell0 = c.prepared->shearing().sampleCoordinate();
  if (progress) *progress << "bench: timing " << ring.name << " and " << cell.name << " in turn, shearing\n";
  for (int rep = 0; rep < repeats; ++rep) {
    timeRepeat(r, steps, threads, out.ring.speed);
    timeRepeat(c, steps, threads, out.cell.speed);
  }
  r.prepared->world().checkHealth();
  c.prepared->world().checkHealth();
  out.ring.axialStrainTimed = r.prepared->shearing().sampleCoordinate() - ring0;
  out.cell.axialStrainTimed = c.prepared->shearing().sampleCoordinate() - cell0;
  return out;
}

}  // namespace grainlab::bench

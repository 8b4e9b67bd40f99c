#include "grainlab/starting_specimen.hpp"

#include "grainlab/periodic_cell.hpp"
#include "prepared_specimen.hpp"
#include "run_context.hpp"

namespace grainlab {

StartingSpecimen startingSpecimen(const Scene& scene) {
  // The run's own construction and loading, so the specimen is exactly the one it would step.
  RunContext context(scene);
  StartingSpecimen s;
  if (scene.startFrom) {
    PreparedHistory history;
    s.firstStage = loadPreparedSpecimen(scene, context, history);
  }
  const World& world = context.world();
  const auto copy = [](auto span) { return std::vector(span.begin(), span.end()); };
  s.shapes = copy(world.shapes());
  s.radii = copy(world.boundingRadii());
  s.masses = copy(world.masses());
  s.inertias = copy(world.inertias());
  s.positions = copy(world.positions());
  s.velocities = copy(world.velocities());
  s.spins = copy(world.spins());
  s.motions = copy(world.motions());
  s.boundary = copy(world.boundaryFlags());
  s.walls = copy(world.walls());
  if (const PeriodicCell* cell = world.periodicCell()) {
    s.cell = cell->edges();
    s.cellVelocityGradient = cell->velocityGradient();
  }
  s.material = world.material();
  s.timestep = world.timestep();
  s.time = world.time();
  return s;
}

}  // namespace grainlab

#pragma once
// What moves the particles: the narrow interface between the World and its two engines,
// grainlab's own DEM (DemSolver: springs, dashpots and leapfrog) and Box2D's rigid-body solver
// (RigidBodySolver). A solver reads and writes the World's ParticleStore and keeps whatever
// else it needs (neighbour lists, contact history, a b2World) to itself. The World owns the
// store, the material, the clock and the checks, and knows nothing of either engine.
#include <cstdint>
#include <span>
#include <vector>

#include "grainlab/contact.hpp"
#include "grainlab/stress.hpp"

namespace grainlab {

class StateArchive;

class Solver {
 public:
  virtual ~Solver() = default;

  /// Builds what the solver needs from the store's particles and walls as they are now, and
  /// the forces on them. Called again if particles or walls are added afterwards.
  virtual void initialize(double dt) = 0;
  /// Advances the store by dt: positions, angles, velocities and spins, then the forces and
  /// torques the next step starts from. `step` numbers this step, counting from 1.
  virtual void step(double dt, std::int64_t step) = 0;
  /// The material's friction has changed (it does between the paper's stages).
  virtual void frictionChanged(double mu) = 0;
  /// From the next step on, work on `threads` threads (the caller's included). A solver whose
  /// results do not depend on the count may take it at any step; one that runs serially
  /// ignores it.
  virtual void setThreads(int /*threads*/) {}

  /// Its default timestep is this multiple of timestep_safety × the critical timestep.
  virtual double timestepScale() const = 0;
  /// Whether the timestep must stay below the critical one (explicit integration of springs).
  virtual bool boundedByCriticalTimestep() const = 0;
  /// The stability bound of the packing as it stands (World::packingTimestep).
  virtual double packingTimestep(int* particle, int* contacts) const = 0;
  /// The normal stiffness a contact shows to slow loading, N/m (World::contactStiffness).
  virtual double contactStiffness(double dt) const = 0;
  /// Whether velocities lag the positions by half a step (leapfrog) or are theirs.
  virtual bool velocitiesLagHalfStep() const = 0;

  /// The touching contacts as of the last force computation, in a stable order.
  virtual void contacts(std::vector<ContactRecord>& out) const = 0;
  /// The contact stress of those contacts (grainlab::contactStress over contacts()); a solver
  /// may sum it without building the records, to the same bits.
  virtual StressTensor contactStress(std::span<const Vec2> centroids, std::span<const unsigned char> inside,
                                     double area, const PeriodicCell* cell) const {
    std::vector<ContactRecord> records;
    contacts(records);
    return grainlab::contactStress(records, centroids, inside, area, cell);
  }
  /// Energy stored in the contacts, J per metre.
  virtual double elasticEnergy() const = 0;
  /// Throws SimulationError naming the pair if two bodies overlap by more than half the
  /// smaller's bounding radius (`step`, `dt` and `criticalDt` are for the message).
  virtual void checkOverlaps(std::int64_t step, double dt, double criticalDt) const = 0;

  /// Whether its state can be saved after `steps` steps.
  virtual bool resumable(std::int64_t steps) const = 0;
  /// Brings its state to a form persist() can save exactly, now (World::makeResumable).
  virtual void makeResumable() {}
  /// Saves or loads its own state (World::persist); `dt` is the timestep of the steps to come.
  virtual void persist(StateArchive& a, double dt) = 0;
};

}  // namespace grainlab

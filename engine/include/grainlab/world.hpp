#pragma once
// The world a scene runs in: the particles (a ParticleStore, the one owner of their state),
// the solver that moves them (grainlab's DEM, or Box2D's rigid-body solver: engine/src/
// solver.hpp), the clock, and the checks and energies read from them. Analysis reads it
// through const views only.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "grainlab/contact.hpp"
#include "grainlab/material.hpp"
#include "grainlab/math.hpp"
#include "grainlab/particle.hpp"
#include "grainlab/particle_store.hpp"
#include "grainlab/profile.hpp"
#include "grainlab/shape.hpp"
#include "grainlab/stress.hpp"
#include "grainlab/wall.hpp"

namespace grainlab {

class StateArchive;
class Solver;

struct WorldSettings {
  /// Verlet skin as a fraction of the mean bounding radius: pairs within this gap are kept
  /// in the neighbour list, which is rebuilt when a particle has moved half of it. Between
  /// walls it changes no result, only the speed: the list keeps its pairs in (i, j) order, and
  /// a pair it leaves out is too far apart to touch and keeps no state. Thinner, it lists
  /// fewer pairs for more rebuilds (docs/benchmarks.md, "A thinner Verlet skin"). In a
  /// periodic cell a rebuild also wraps the positions into the cell, which rounds them, so
  /// there the rebuilds' schedule is part of the result and the skin stays 0.3
  /// (ContactSolver::initialize).
  double skinFraction = 0.15;
  /// Threads for the force computation (the caller's included). Results are bit-identical
  /// for any count: the parallel path adds each particle's forces in the serial order.
  int threads = 1;
  /// Dem: grainlab's own contact laws and integrator (DemSolver, engine/src/dem_solver.hpp).
  /// Box2d: Box2D's rigid-body solver moves the particles (RigidBodySolver, engine/src/
  /// rigid_body_solver.hpp) and the particle store mirrors its bodies after every step.
  enum class Engine { Dem, Box2d };
  Engine engine = Engine::Dem;
  int velocityIterations = 8, positionIterations = 3;  ///< box2d only
};

class World {
 public:
  explicit World(const Material& material, WorldSettings settings = {});
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Adds a particle; returns its index (indices are dense and stable, in creation order).
  /// Throws std::invalid_argument for a malformed shape.
  int addParticle(const ParticleSpec& spec);
  int addWall(const Wall& wall);

  void setGravity(const Vec2& g) { particles_.gravity = g; }
  /// Friction may change between stages (the paper compacts with μ = 0).
  void setFriction(double mu);
  const Material& material() const { return material_; }

  /// Timestep in s. Until set, it is timestepSafety × criticalTimestep() (box2d: × the
  /// rigid-body timestep scale, RigidBodySolver::kTimestepScale).
  void setTimestep(double dt) { timestep_ = dt; }
  double timestep() const;
  void setTimestepSafety(double safety) { timestepSafety_ = safety; }
  /// 2·√(m*/k) for the stiffest, lightest contact: m* = m/2 for the lightest particle and
  /// k the stiffest spring seen through the particle's rotational inertia at its bounding
  /// radius R: k_t·(1 + m R²/I), and for polygons also k_n·(1 + m R²/I) (their normal forces
  /// need not pass through the centre). Explicit integration is unstable above it.
  double criticalTimestep() const;

  /// The stability bound of the packing as it now stands, which can be well below the
  /// single-contact criticalTimestep(): a particle held by Z contacts vibrates up to √Z times
  /// faster than against one (a Gershgorin bound), and viscous damping of ratio ζ lowers
  /// leapfrog's limit by the factor √(1+ζ²) − ζ. Infinite with no contacts, and for box2d
  /// (rigid contacts have no spring). `particle` and
  /// `contacts` (optional) receive the particle that sets it and its contact count.
  double packingTimestep(int* particle = nullptr, int* contacts = nullptr) const;
  WorldSettings::Engine engine() const { return settings_.engine; }
  /// Threads for the force computation, as settings.threads: may change between any two steps,
  /// with the same results (box2d runs serially whatever the count). Throws
  /// std::invalid_argument below 1.
  void setThreads(int threads);
  int threads() const { return settings_.threads; }
  /// The normal stiffness a contact shows to slow loading, N/m: k_n for dem; for box2d the
  /// rigid solver's apparent stiffness (RigidBodySolver::contactStiffness). Servo gains
  /// are derived from it.
  double contactStiffness() const;

  /// Makes the world a periodic cell with edge vectors the columns of h, m (one corner at the
  /// origin; particles placed anywhere are wrapped into it). Particles then meet the images
  /// of the others across its edges, and their velocities are fluctuations about the cell's
  /// affine field (docs/periodic-cell.md). Throws std::invalid_argument for a degenerate cell,
  /// or with the box2d engine, which has no periodic cell.
  void setPeriodicCell(const Eigen::Matrix2d& h);
  /// The periodic cell, or null for a world without one.
  const PeriodicCell* periodicCell() const { return particles_.cell ? &*particles_.cell : nullptr; }
  /// The velocity gradient L the periodic cell (and the affine part of every particle's
  /// motion) follows from the next step, 1/s. Requires a periodic cell.
  void setCellVelocityGradient(const Eigen::Matrix2d& L);

  /// Prescribed motion of a kinematic particle (ignored for others).
  void setKinematicVelocity(int i, const Vec2& v, double spin = 0);

  /// Builds the collision geometry, the neighbour list and the first forces once every
  /// particle and wall is in (step() calls it if needed). Throws SimulationError if the
  /// timestep exceeds the critical one: explicit integration would be unstable.
  void initialize();
  /// Advances one timestep: the solver's step (dem: kick, drift, neighbour update, forces).
  void step();
  /// Checkpoints: everything the next step depends on (state, contact history, kept polygon
  /// features, the box2d engine's bodies and warm-start impulses), saved into `a`, or loaded
  /// from it into a world built from the same scene and initialized. After a load, step()
  /// continues bit for bit as the saved world would have. Loading checks that the particles
  /// are the same (CheckpointError otherwise).
  void persist(StateArchive& a);
  /// Whether the state can be saved now: always for dem; for box2d only at the steps where
  /// its b2World is rebuilt from its own state (RigidBodySolver::kRebuildEvery), since a
  /// b2World's internals (its broad-phase tree, its contact order) cannot be saved.
  bool resumable() const;
  /// Makes the state savable exactly at this step: nothing for dem; box2d rebuilds its
  /// b2World from its own state, as it does every kRebuildEvery steps (so the steps that
  /// follow differ from those of a run that did not call it; a run loaded from the state
  /// saved now continues exactly as this one does).
  void makeResumable();

  /// Throws SimulationError if any state is non-finite or an overlap has run away (beyond
  /// half of the smaller particle's size), naming the particle and the likely cause.
  void checkHealth() const;

  // ---- const views (for analysis and output; never a way to change the physics) ----
  int size() const { return particles_.size(); }
  std::int64_t stepCount() const { return steps_; }
  double time() const { return time_; }
  std::span<const Vec2> positions() const { return particles_.position; }
  std::span<const double> angles() const { return particles_.angle; }
  std::span<const Vec2> velocities() const { return particles_.velocity; }
  std::span<const double> spins() const { return particles_.spin; }
  std::span<const Vec2> forces() const { return particles_.force; }   ///< contact + body forces of the last step
  std::span<const double> torques() const { return particles_.torque; }
  std::span<const double> masses() const { return particles_.mass; }
  std::span<const double> inertias() const { return particles_.inertia; }
  std::span<const double> boundingRadii() const { return particles_.boundingRadius; }
  std::span<const ShapeKind> shapes() const { return particles_.shape; }
  std::span<const Motion> motions() const { return particles_.motion; }
  std::span<const unsigned char> boundaryFlags() const { return particles_.boundary; }
  std::span<const Wall> walls() const { return particles_.walls; }
  /// The body-frame polygon of particle i (which must be a polygon).
  const Polygon& polygon(int i) const { return particles_.polygonOf(i); }
  /// Solid area of particle i, m².
  double area(int i) const { return particles_.area(i); }
  bool hasPolygons() const { return !particles_.polygons.empty(); }
  /// The body-frame clump of particle i (which must be a clump): its discs about its centroid.
  const Clump& clump(int i) const { return particles_.clumpOf(i); }
  bool hasClumps() const { return !particles_.clumps.empty(); }
  /// World-frame member discs of clump particle i.
  void worldMembers(int i, std::vector<ClumpMember>& out) const;
  /// World-frame vertices of polygon particle i.
  void worldVertices(int i, std::vector<Vec2>& out) const;

  /// The touching contacts as of the last force computation, in a stable order.
  void contacts(std::vector<ContactRecord>& out) const;
  /// grainlab::contactStress of those contacts at the particles' positions (in a periodic cell,
  /// with its minimum-image branch vectors), to the same bits, without building the records.
  StressTensor contactStress(std::span<const unsigned char> inside, double area) const;
  /// Σ ½ m v² + ½ I ω² over dynamic particles, J per metre.
  double kineticEnergy() const;
  /// Energy stored in the contact springs, J per metre (0 for box2d: rigid contacts).
  double elasticEnergy() const;

  const Profile& profile() const { return profile_; }

 private:
  // Names the particle if the state is not finite (after a solver found a position it could
  // not place in its grid), then lets the original error go on.
  template <class Action>
  void namingDivergence(Action&& action);

  Material material_;  // the solvers read it; friction changes between stages
  WorldSettings settings_;
  double timestep_ = 0;
  double timestepSafety_ = 0.2;
  std::int64_t steps_ = 0;
  double time_ = 0;
  bool prepared_ = false;
  double criticalTimestep_ = 0;  // s, cached by initialize()
  Profile profile_;
  ParticleStore particles_;
  std::unique_ptr<Solver> solver_;  // built with the World; refers to the three above
};

}  // namespace grainlab

#pragma once
// The DEM world: particle state in contiguous arrays, a Verlet neighbour list, contact forces
// from a pluggable contact law, and explicit leapfrog integration in double precision.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "grainlab/contact.hpp"
#include "grainlab/material.hpp"
#include "grainlab/math.hpp"
#include "grainlab/particle.hpp"
#include "grainlab/profile.hpp"
#include "grainlab/shape.hpp"
#include "grainlab/wall.hpp"

namespace grainlab {

class NeighborList;
class StateArchive;
class PolygonCollider;
class RigidBodySolver;
class WorkerPool;
struct PairState;
struct ContactGeometry;
struct DiscContact;
struct TouchingDiscs;
struct TouchingShapes;
struct CachedContact;

struct WorldSettings {
  /// Verlet skin as a fraction of the mean bounding radius: pairs within this gap are kept
  /// in the neighbour list, which is rebuilt when a particle has moved half of it.
  double skinFraction = 0.3;
  /// Threads for the force computation (the caller's included). Results are bit-identical
  /// for any count: the parallel path adds each particle's forces in the serial order.
  int threads = 1;
  /// Dem: grainlab's own contact laws and integrator. Box2d: Box2D's rigid-body solver moves
  /// the particles (RigidBodySolver, engine/src/rigid_body_solver.hpp) and the World's arrays
  /// mirror its bodies after every step; the DEM members below are then unused.
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

  void setGravity(const Vec2& g) { gravity_ = g; }
  /// Friction may change between stages (the paper compacts with μ = 0).
  void setFriction(double mu);
  const Material& material() const { return material_; }

  /// Timestep in s. Until set, it is timestepSafety × criticalTimestep() (box2d: × the
  /// rigid-body timestep scale, RigidBodySolver::timestepScale).
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
  /// leapfrog's limit by the factor √(1+ζ²) − ζ. Infinite with no contacts. `particle` and
  /// `contacts` (optional) receive the particle that sets it and its contact count.
  double packingTimestep(int* particle = nullptr, int* contacts = nullptr) const;
  WorldSettings::Engine engine() const { return settings_.engine; }
  /// The normal stiffness a contact shows to slow loading, N/m: k_n for dem; for box2d the
  /// rigid solver's apparent stiffness (RigidBodySolver::apparentStiffness). Servo gains
  /// are derived from it.
  double contactStiffness() const;

  /// Prescribed motion of a kinematic particle (ignored for others).
  void setKinematicVelocity(int i, const Vec2& v, double spin = 0);

  /// Builds the collision geometry, the neighbour list and the first forces once every
  /// particle and wall is in (step() calls it if needed). Throws SimulationError if the
  /// timestep exceeds the critical one: explicit integration would be unstable.
  void initialize();
  /// Advances one timestep: kick, drift, neighbour update, forces.
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

  /// Throws SimulationError if any state is non-finite or an overlap has run away (beyond
  /// half of the smaller particle's size), naming the particle and the likely cause.
  void checkHealth() const;

  // ---- const views (for analysis and output; never a way to change the physics) ----
  int size() const { return static_cast<int>(position_.size()); }
  std::int64_t stepCount() const { return steps_; }
  double time() const { return time_; }
  std::span<const Vec2> positions() const { return position_; }
  std::span<const double> angles() const { return angle_; }
  std::span<const Vec2> velocities() const { return velocity_; }
  std::span<const double> spins() const { return spin_; }
  std::span<const Vec2> forces() const { return force_; }   ///< contact + body forces of the last step
  std::span<const double> torques() const { return torque_; }
  std::span<const double> masses() const { return mass_; }
  std::span<const double> inertias() const { return inertia_; }
  std::span<const double> boundingRadii() const { return boundingRadius_; }
  std::span<const ShapeKind> shapes() const { return shape_; }
  std::span<const Motion> motions() const { return motion_; }
  std::span<const unsigned char> boundaryFlags() const { return boundary_; }
  std::span<const Wall> walls() const { return walls_; }
  /// The body-frame polygon of particle i (which must be a polygon).
  const Polygon& polygon(int i) const { return polygons_[static_cast<size_t>(shapeIndex_[i])]; }
  /// Solid area of particle i, m².
  double area(int i) const;
  bool hasPolygons() const { return !polygons_.empty(); }
  /// World-frame vertices of polygon particle i.
  void worldVertices(int i, std::vector<Vec2>& out) const;

  /// The touching contacts as of the last force computation, in a stable order.
  void contacts(std::vector<ContactRecord>& out) const;
  /// Σ ½ m v² + ½ I ω² over dynamic particles, J per metre.
  double kineticEnergy() const;
  /// Energy stored in the contact springs, J per metre (0 for box2d: rigid contacts).
  double elasticEnergy() const;

  const Profile& profile() const { return profile_; }

 private:
  friend class RigidBodySolver;  // mirrors the arrays below into its b2World and back
  // Particle k's stiffest contact spring as seen through its rotational inertia (N/m).
  double stiffestSpring(int k, bool tangential) const;
  void forEachParticleRange(const std::function<void(int, int)>& body);
  void computeForces();
  void advance(double dt, int begin, int end);
  Vec2 bodyForce(int k) const { return motion_[k] == Motion::Dynamic ? Vec2(mass_[k] * gravity_) : Vec2::Zero(); }
  void assignDamping();
  // A particle's force before its contacts: its weight.
  void resetForce(int k) {
    force_[k] = bodyForce(k);
    torque_[k] = 0;
  }
  void assignDeferredSlots();
  ContactGeometry pairGeometry(const PairState& pair, CachedContact* cache) const;
  void carryPolygonCache();
  void applyLocalDamping(int k);
  template <class Law, bool kDiscsOnly>
  void pairForces(const Law& law);
  template <bool kDiscsOnly, class Force, class Apart>
  void forEachTouching(int begin, int end, Force&& force, Apart&& apart);
  template <class Law>
  void contactForce(PairState& pair, const ContactGeometry& g, const Law& law, double dt, Vec2& force,
                    double& torqueI, double& torqueJ) const;
  template <class Law>
  void contactForce(PairState& pair, const DiscContact& c, const Law& law, double dt, Vec2& force,
                    double& torqueI, double& torqueJ) const;

  Material material_;
  WorldSettings settings_;
  Vec2 gravity_ = Vec2::Zero();
  double timestep_ = 0;
  double timestepSafety_ = 0.2;
  std::int64_t steps_ = 0;
  double time_ = 0;
  bool prepared_ = false;
  double skin_ = 0;  // m
  double criticalTimestep_ = 0;  // s, cached by initialize()

  // Hot state, one entry per particle.
  std::vector<Vec2> position_, velocity_, force_;
  std::vector<double> angle_, spin_, torque_;
  std::vector<double> cos_, sin_;        // of angle_, refreshed each step for polygons only
  std::vector<double> invMass_, invInertia_;
  // Cold data.
  std::vector<double> mass_, inertia_, boundingRadius_;
  std::vector<ShapeKind> shape_;
  std::vector<Motion> motion_;
  std::vector<unsigned char> boundary_;
  std::vector<int> shapeIndex_;          // index into polygons_ or -1 for discs
  std::vector<Polygon> polygons_;
  std::vector<Wall> walls_;

  std::unique_ptr<NeighborList> neighbors_;
  // Set by the step's integration pass when some particle moved far enough to need a new
  // neighbour list; each thread checks its own particles, so none reads the others' lines.
  std::atomic<bool> neighborsOutdated_{true};
  std::unique_ptr<PolygonCollider> polygonCollider_;
  std::unique_ptr<WorkerPool> pool_;     // null when serial
  // Parallel force loop: a pair's share of force on a particle is added at once by the thread
  // that owns the particle (the one computing its first pair); a share computed by another
  // thread waits in a slot and is added after the loop, in pair order.
  struct DeferredForce {
    Vec2 force = Vec2::Zero();            // to add to the particle's force
    double torque = 0;                    // to add to its torque
    bool touching = false;                // false: the pair was apart, nothing to add
  };
  std::vector<int> deferredSlot_;        // per pair end (2 × pair + 1 for j): slot, or -1 if added at once
  std::vector<DeferredForce> deferred_;  // slots, grouped by particle, in pair order
  std::vector<int> deferredStart_;       // particle k's slots: [deferredStart_[k], deferredStart_[k+1])
  // Scratch for the two-pass force loop: each pair's room for its contact (one of the two,
  // by whether the scene has polygons).
  std::vector<TouchingDiscs> touchingDiscs_;
  std::vector<TouchingShapes> touchingShapes_;
  std::vector<CachedContact> polygonCache_;  // per pair, when there are polygons
  std::unique_ptr<RigidBodySolver> rigid_;  // box2d engine only
  Profile profile_;
};

}  // namespace grainlab

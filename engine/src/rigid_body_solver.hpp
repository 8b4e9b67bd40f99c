#pragma once
// The box2d engine ("solver": {"engine": "box2d"}): Box2D's rigid-body solver (b2World,
// sequential impulses with velocity and position iterations) moves the particles instead of
// grainlab's springs and leapfrog. The ParticleStore stays the one state the rest of the
// program reads: this class mirrors it into a b2World once, steps it, and copies positions,
// angles, velocities and spins back after every step, with the contact forces (from the
// solver's impulses) into the store's forces and torques.
//
// What it maps, and how:
//  - Bodies: dynamic particles are dynamic bodies, kinematic ones kinematic bodies (their
//    velocities, set by World::setKinematicVelocity, are forwarded every step; their
//    positions are integrated in double here, as the DEM does), fixed ones static.
//    Walls are static boxes behind their surface. No sleeping, no continuous collision.
//  - Units: Box2D is single precision and tuned for bodies of 0.1-10 units. Lengths are
//    scaled so the mean particle radius is one unit, masses so the mean mass is one unit,
//    and coordinates are taken about the initial centre of the particles. Time stays in
//    seconds. Impulses are converted back exactly: F = λ / (M L dt).
//  - Shape: each polygon is shrunk inward by Box2D's compiled-in skin b2_polygonRadius
//    (0.01 units) before Set(), so the skinned (rounded) shape Box2D collides is the true
//    polygon, except within the skin at the corners (a 120° corner is rounded off by
//    0.16 skin = 0.0016 units). Walls' boxes are set back by the skin likewise. Discs have
//    no skin. Set() may reorder vertices: nothing here relies on their order.
//  - Mass: each body gets the store's mass and inertia (b2Body::SetMassData), not Box2D's
//    from the shrunk shape.
//  - Material: friction μ on every fixture (Box2D mixes √(μ₁μ₂) = μ); setFriction updates
//    the fixtures and every existing contact. Restitution e on every fixture, applied by
//    Box2D above its restitution threshold, left at its default of one length unit per second
//    (one mean particle radius per second); slower impacts are perfectly inelastic.
//  - Checkpoints: a b2World's internals (its broad-phase tree, the order of its contacts,
//    which decides the solver's order) cannot be saved, so every kRebuildEvery steps the
//    b2World is rebuilt from its own float state and warm-start impulses, in a fixed order
//    (rebuild()). A run resumed from a checkpoint taken at such a step rebuilds the same
//    b2World, and continues bit for bit.
//  - Not mapped: the contact stiffnesses (contacts are rigid: no elastic energy, overlaps are
//    only Box2D's slop and solver error) and Cundall's local damping (no counterpart in a
//    rigid-body solver; Box2D's own damping is viscous and would slow steady motion too).
#include <cstdint>
#include <memory>
#include <vector>

#include "grainlab/contact.hpp"
#include "grainlab/material.hpp"
#include "grainlab/math.hpp"
#include "grainlab/particle_store.hpp"
#include "grainlab/profile.hpp"
#include "grainlab/state_archive.hpp"
#include "solver.hpp"

class b2World;
class b2Body;
class b2Fixture;

namespace grainlab {

class RigidBodySolver final : public Solver {
 public:
  /// The default box2d timestep is this multiple of the DEM's (timestep_safety × the critical
  /// timestep of the scene's springs). See docs/speed-accuracy.md for why.
  static constexpr double kTimestepScale = 10.0;
  /// Steps between rebuilds of the b2World from its own state (and so between the steps at
  /// which a box2d run can be checkpointed). A rebuild costs about what a few steps do.
  static constexpr int kRebuildEvery = 1000;

  RigidBodySolver(ParticleStore& particles, const Material& material, int velocityIterations,
                  int positionIterations, Profile& profile);
  ~RigidBodySolver() override;
  RigidBodySolver(const RigidBodySolver&) = delete;
  RigidBodySolver& operator=(const RigidBodySolver&) = delete;

  /// Builds the b2World from the store's current particles and walls.
  void initialize(double dt) override;
  /// One b2World::Step of dt, then the store's state, forces and torques from it; every
  /// kRebuildEvery steps, rebuild().
  void step(double dt, std::int64_t step) override;
  /// Updates the fixtures and every existing contact.
  void frictionChanged(double mu) override;

  double timestepScale() const override { return kTimestepScale; }
  /// Rigid contacts have no spring: no explicit-integration bound.
  bool boundedByCriticalTimestep() const override { return false; }
  double packingTimestep(int* particle, int* contacts) const override;
  /// The stiffness a contact appears to have under slow loading, N/m: (4 n_v / 3) m̄ / dt²
  /// for n_v velocity iterations and the mean particle mass m̄. A rigid contact has none, but
  /// the iteration-limited solver lets a packing take up a boundary strain within Box2D's
  /// slop, and its stress then grows with that strain as if the contacts were springs of
  /// this stiffness. Measured on circular-quick after consolidation (p against volumetric
  /// strain, dp/dε_v = 2.5-3.2 m̄/dt² at 8 iterations, 6.4-6.8 at 20, for dt from 2.4e-5 to
  /// 1.5e-4 s; the packing's modulus is k/2 as for the DEM's springs).
  double contactStiffness(double dt) const override;
  /// Box2D's velocities are its positions' (it integrates them first).
  bool velocitiesLagHalfStep() const override { return false; }

  /// The touching contacts of the last step, sorted by (i, j) as the DEM path's.
  void contacts(std::vector<ContactRecord>& out) const override;
  /// Rigid contacts store no energy.
  double elasticEnergy() const override { return 0; }
  /// Throws SimulationError if two bodies overlap by more than half the smaller's radius:
  /// the solver could not keep them apart.
  void checkOverlaps(std::int64_t step, double dt, double criticalDt) const override;

  /// Only at the steps where the b2World was rebuilt from its own state.
  bool resumable(std::int64_t steps) const override { return steps % kRebuildEvery == 0; }
  /// Rebuilds now, out of turn, so the state can be saved at any step.
  void makeResumable() override { rebuild(); }
  /// Saves its state, or loads it and rebuilds (call at a rebuild step).
  void persist(StateArchive& a, double dt) override;

  double lengthScale() const { return lengthScale_; }  ///< Box2D units per metre

 private:
  // Tears the b2World down and builds it again from its bodies' float state and its
  // contacts' warm-start impulses, bodies in particle order: afterwards the b2World depends
  // only on that state, not on its history.
  void rebuild();
  // A body's state as Box2D holds it, in Box2D units and single precision.
  struct BodyState {
    float x, y, angle, vx, vy, spin;
  };
  // A contact's warm start: its fixtures (particle index, or −1 − wall) and per manifold
  // point the feature id and the impulses.
  struct ContactState {
    int a, b;
    int points;
    unsigned ids[2];
    float normalImpulse[2], tangentImpulse[2];
  };
  void build(const std::vector<BodyState>& bodies, const std::vector<ContactState>& contacts);
  void capture(std::vector<BodyState>& bodies, std::vector<ContactState>& contacts) const;
  void restoreWarmStart(const std::vector<ContactState>& contacts);
  void addParticle(int k, const BodyState& state);
  void addWall(int w, double halfWidth);
  void gatherContacts(double dt);

  ParticleStore& particles_;
  const Material& material_;  // the World's: its friction changes between stages
  const int velocityIterations_, positionIterations_;
  Profile& profile_;
  double dt_ = 0;           // s, of the last step, or of the next after a load
  double lengthScale_ = 1;  // Box2D units per m
  double massScale_ = 1;    // Box2D units per kg (per metre of thickness)
  Vec2 origin_ = Vec2::Zero();
  double halfWidth_ = 0;    // of the walls' boxes, Box2D units
  std::unique_ptr<b2World> b2_;
  std::vector<b2Body*> bodies_;     // one per particle, in index order
  std::vector<b2Fixture*> fixtures_;  // particles' then walls'
  std::vector<ContactRecord> contacts_;  // in Box2D's contact-list order
};

}  // namespace grainlab

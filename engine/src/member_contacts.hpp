#pragma once
// The DEM's contacts in a scene with clumps: bodies apart from shapes. Every body's discs are
// members (a lone disc is its own one member, a clump has several); the broad phase (the
// Verlet neighbour list) and the narrow phase (touchDiscs, touchDiscWall) see members, a pair
// of members of the same body is dropped, and each member's force and torque go to its body,
// the torque with the lever from the body's centroid (a member's normal force does not pass
// through the body's centre, so the disc fast path's torque-free normal force does not apply).
// One thread: the sums are in pair order, so the result is the same whatever the thread count.
// On the wide path (grainlab/simd_path.hpp) the member-member pairs go through the disc kernel
// in batches (member_pair_batch.hpp), then the member-wall pairs: each body's sums are again
// in one fixed order.
#include <cstdint>
#include <vector>

#include "contact_geometry.hpp"
#include "grainlab/contact.hpp"
#include "grainlab/material.hpp"
#include "grainlab/particle_store.hpp"
#include "grainlab/profile.hpp"
#include "member_pair_batch.hpp"
#include "neighbor_list.hpp"

namespace grainlab {

class StateArchive;

class MemberContactSolver {
 public:
  MemberContactSolver(ParticleStore& particles, const Material& material, double skinFraction, Profile& profile);

  /// The member table from the store's bodies as they are now; the next computeForces()
  /// builds a new neighbour list. Throws SimulationError for a scene that also has polygons.
  void initialize();
  /// Places the members where their bodies now are, rebuilds the neighbour list if a member
  /// has moved half the skin, and adds every touching member pair's force and torques for a
  /// step of dt to the bodies' forces, then Cundall's local damping.
  void computeForces(double dt);
  void clearTangentialHistory();

  /// One record per touching member pair, between the members' bodies (i < j), in pair order.
  void contacts(std::vector<ContactRecord>& out) const;
  /// Each body's number of touching member contacts.
  void countContacts(std::vector<int>& count) const;
  double elasticEnergy() const;
  void checkOverlaps(std::int64_t step, double dt, double criticalDt) const;
  void persist(StateArchive& a);

  int memberCount() const { return static_cast<int>(owner_.size()); }

 private:
  void placeMembers();
  void assignDamping();
  template <class Law>
  void pairForces(const Law& law, double dt);
  template <class Law>
  void widePairForces(const Law& law, double dt);
  template <class Law>
  void pairForce(PairState& p, const DiscContact& c, const Law& law, double dt);
  DiscContact touch(const PairState& p) const;
  void writeBackWideState() const;

  ParticleStore& particles_;
  const Material& material_;
  const double skinFraction_;
  Profile& profile_;
  double skin_ = 0;  // m

  // Per member, in body order (a body's members are consecutive).
  std::vector<int> owner_;        // its body
  std::vector<Vec2> offset_;      // body frame, from the body's centroid (zero for a lone disc)
  std::vector<double> radius_;
  std::vector<Motion> motion_;    // its body's
  std::vector<Vec2> lever_;       // world frame, from the body's centroid: offset_ turned
  std::vector<Vec2> position_;    // world frame: the body's position + lever_
  NeighborList neighbors_;
  // The wide path's layout of the member pairs, rebuilt when the list is. After a wide step
  // the pairs' state is in the batch (ahead of the list) until writeBackWideState().
  MemberPairBatch batch_;
  bool batchStale_ = true;
  mutable bool wideStateAhead_ = false;
};

}  // namespace grainlab

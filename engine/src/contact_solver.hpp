#pragma once
// The DEM's contacts: which pairs may touch (the Verlet neighbour list: the broad phase),
// where they touch (discs in closed form, polygons through their kept features: the narrow
// phase), the force law (linear spring-dashpot, Cundall-Strack friction) with each pair's
// history, and the assembly of every pair's force onto its particles, threaded or not with
// bit-identical results.
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "contact_geometry.hpp"
#include "contact_law.hpp"
#include "rolling_resistance.hpp"
#include "disc_pair_batch.hpp"
#include "disc_pair_kernel.hpp"
#include "grainlab/contact.hpp"
#include "grainlab/material.hpp"
#include "grainlab/particle_store.hpp"
#include "grainlab/profile.hpp"
#include "grainlab/stress.hpp"
#include "neighbor_list.hpp"
#include "polygon_collider.hpp"
#include "polygon_face_batch.hpp"
#include "polygon_pair_slots.hpp"

namespace grainlab {

class StateArchive;
class WorkerPool;

class ContactSolver {
 public:
  /// `pool` (null when serial) runs the force loop; `profile` receives its timings.
  ContactSolver(ParticleStore& particles, const Material& material, double skinFraction, WorkerPool* pool,
                Profile& profile);
  ~ContactSolver();

  /// Takes in the store's particles and walls as they are now (polygon features, the skin);
  /// the next computeForces() builds a new neighbour list.
  void initialize();
  /// Periodic cell: the cell has just advanced; the images' drift since the last build narrows
  /// the skin left to the particles' own moves.
  void cellAdvanced();
  /// True if some particle in [begin, end) has moved far enough that the neighbour list must
  /// be rebuilt. Reads only that range, so each thread checks the particles it just moved.
  bool movedOutOfSkin(int begin, int end) const;
  /// Adds every touching pair's force and torques for a step of dt to the store's forces
  /// (which hold the body forces), then Cundall's local damping. `moved`: movedOutOfSkin()
  /// was true for some range since the last call.
  void computeForces(double dt, bool moved);
  /// Frictional springs built under another friction are stale: every pair's is dropped.
  void clearTangentialHistory();
  /// From the next step on, the force loop runs on `pool` (null: serially). The forces keep
  /// their bits: only the plans that follow the thread count are made again.
  void setPool(WorkerPool* pool);

  void contacts(std::vector<ContactRecord>& out) const;
  /// grainlab::contactStress over contacts(), with the same terms in the same order (the same
  /// bits), summed straight from the pairs' state: no records, no write-back of the wide
  /// path's state (contact_solver_stress.cpp).
  StressTensor contactStress(std::span<const Vec2> centroids, std::span<const unsigned char> inside, double area,
                             const PeriodicCell* cell) const;
  /// Each particle's number of touching contacts, as of the last force computation.
  void countContacts(std::vector<int>& count) const;
  double elasticEnergy() const;
  void checkOverlaps(std::int64_t step, double dt, double criticalDt) const;
  void persist(StateArchive& a);

 private:
  // `shift`: in a periodic cell, where j's image is (x_j + shift); null otherwise.
  ContactGeometry pairGeometry(const PairState& pair, CachedContact* cache, const Vec2* shift = nullptr,
                               SlackGuards guards = SlackGuards::EveryDecision) const;
  // Periodic cell (contact_solver_periodic.cpp): pair k's image shift of j, m, and the affine
  // velocity of that image relative to i, L (x_j + shift − x_i).
  Vec2 imageShift(size_t k) const { return particles_.cell->shift(neighbors_.shifts()[k]); }
  Vec2 affineRelativeVelocity(const PairState& p, size_t k) const;
  // The wide kernel's view of the cell this step: the slots' image shifts, h and L.
  void setWideCell(DiscPairKernelInput& in) const;
  // Rebuilds the list in the cell when due: remaps a far-tilted cell, wraps the positions into
  // it, bins them. Returns true if it rebuilt.
  bool updatePeriodicNeighbors(bool moved);
  void assignDamping();
  void assignDeferredSlots();
  void assignRollingPairs();
  void carryPolygonCache();
  void writeBackWideState() const;
  template <class Law, bool kDiscsOnly, bool kPeriodic = false>
  void pairForces(const Law& law, double dt);
  // The wide path for a discs-only scene: disc-disc pairs in batches (discPairForces), then
  // the disc-wall pairs; each thread adds its own particles' shares at once, and the shares
  // that waited (where slices meet) are added after, in pair order (disc_pair_batch.hpp).
  template <class Law>
  void widePairForces(const Law& law, double dt);
  template <bool kDiscsOnly, bool kPeriodic, class Force, class Apart>
  void forEachTouching(int begin, int end, Force&& force, Apart&& apart);
  // The wide path with polygons: a pair's first pass (its answer, and what a slot needs), the
  // kept slots outside a periodic cell (polygon_pair_slots.hpp), and a cell's batch.
  struct WidePolygonPair {
    int i = 0, j = 0, si = 0, sj = 0;
    Pose pi, pj;
    double reach = 0;
  };
  enum class WideAnswer { Face, Apart, Other };
  template <bool kPeriodic>
  WideAnswer decideWidePair(int k, WidePolygonPair& found);
  template <class Force, class Apart>
  void forEachTouchingKept(int begin, int end, Force&& force, Apart&& apart);
  template <class Force, class Apart>
  void forEachTouchingInCell(int begin, int end, Force&& force, Apart&& apart);
  template <bool kPeriodic, class Law>
  void contactForce(PairState& pair, const ContactGeometry& g, const Law& law, double dt, Vec2& force,
                    double& torqueI, double& torqueJ) const;
  template <bool kPeriodic, class Law>
  void contactForce(PairState& pair, const DiscContact& c, const Law& law, double dt, Vec2& force,
                    double& torqueI, double& torqueJ) const;
  // A face-against-edge pair whose law the batch applied: its answer as it is.
  template <bool kPeriodic, class Law>
  void contactForce(PairState&, const PolygonFaceForce& b, const Law&, double, Vec2& force, double& torqueI,
                    double& torqueJ) const {
    force = b.force;
    torqueI = b.torqueI;
    torqueJ = b.torqueJ;
  }

  ParticleStore& particles_;
  const Material& material_;
  const double skinFraction_;
  WorkerPool* pool_;
  Profile& profile_;
  double skin_ = 0;  // m

  NeighborList neighbors_;
  Eigen::Matrix2d cellAtBuild_ = Eigen::Matrix2d::Zero();  // periodic: the edges at the last build
  std::unique_ptr<PolygonCollider> polygonCollider_;
  std::vector<CachedContact> polygonCache_;  // per pair, when there are polygons
  std::vector<RollingResistance::Pair> rollingPairs_;  // per pair, with rolling resistance
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
  bool deferredSlotsStale_ = true;       // the pair list changed since the slots were assigned
  // Scratch for the two-pass force loop: each pair's room for its contact (one of the two,
  // by whether the scene has polygons).
  std::vector<TouchingDiscs> touchingDiscs_;
  std::vector<TouchingShapes> touchingShapes_;
  // The wide path's layout of the pairs, rebuilt when the list is. After a wide step the
  // disc pairs' state is the batch's until writeBackWideState() hands it to the list.
  DiscPairBatch discBatch_;
  bool discBatchStale_ = true;
  mutable bool wideStateAhead_ = false;
  // The wide path in a scene with polygons: face-against-edge pairs measured in batches.
  PolygonFaceBatch polygonBatch_;
  PolygonPairSlots pairSlots_;  // outside a periodic cell: which pairs keep their slots
  // The batch holds every touching pair's contact as the last force pass measured it, at the
  // particles' positions now (computeForces is a step's last move; a load or a new layout
  // clears it): the servos' stress reads them instead of measuring again.
  bool batchContactsCurrent_ = false;
  bool widePolygons_ = false;
  PolygonFaceLaw polygonLaw_;  // this step's law, for the batch
};

}  // namespace grainlab

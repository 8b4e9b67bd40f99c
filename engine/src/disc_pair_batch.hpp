#pragma once
// A discs-only scene's pairs laid out for the wide path: the disc-disc pairs in
// structure-of-arrays slots (what discPairForces() reads and writes) and the disc-wall pairs
// apart. Each particle adds its shares of force and torque in one order whatever the number
// of threads: its disc-disc pairs in pair order, then its walls. The work (blocks of slots,
// then groups of wall pairs) is split between threads in contiguous slices, as
// WorkerPool::parallelFor splits it. A particle belongs to the slice that computes its first
// share, and that slice adds each of its shares at once; a share computed in a later slice
// waits in a record of the particle's, and the particle adds its records, in order, after
// the loop (addDeferred). With one thread nothing waits; in a pile whose particle indices
// follow space, only the particles where the slices meet have records. (Records for every
// end, summed in a pass over all particles, cost the threaded step what the kernel saved.)
// The disc-disc pairs' state (spring, fn, ft, overlap, and with rolling resistance the relative
// rotation) lives in the slots from one step to the next; writeBack() hands it to the
// neighbour list's pairs when they are read.
#include <cstdint>
#include <vector>

#include "disc_pair_kernel.hpp"
#include "grainlab/math.hpp"
#include "neighbor_list.hpp"
#include "rolling_resistance.hpp"

namespace grainlab {

class DiscPairBatch {
 public:
  /// Lays out the list's pairs as they are now (after a rebuild or a restore), with their state;
  /// with `rolling` (each pair's rolling constants, in pair order), their rolling lanes too;
  /// in a periodic cell, each slot's image shift n (the list's shifts()).
  /// `threads`: how many slices the work is split into (parallelFor's, over workItems()).
  void build(const NeighborList& list, int particles, const std::vector<RollingResistance::Pair>* rolling = nullptr,
             bool periodic = false, int threads = 1);
  /// Copies each slot's two radii (`radius` per particle) beside its indices: the kernel then
  /// loads them in order instead of gathering them (the radii are fixed while the list is).
  /// Call after build().
  void layRadii(const double* radius);
  /// The work items: the slot blocks, then the wall pairs in groups of kWallPairsPerItem.
  int blocks() const { return padded_ / kDiscPairBlock; }
  int workItems() const { return blocks() + (static_cast<int>(wallPairs_.size()) + kWallPairsPerItem - 1) / kWallPairsPerItem; }
  /// Wall pairs per work item: a wall pair takes the scalar law, several times a slot's cost,
  /// so a slice is not weighed down by the walls at its end.
  static constexpr int kWallPairsPerItem = 4;
  bool rolls() const { return rolls_; }
  /// Periodic cell: each slot's image shift, n1 and n2 as doubles (null without a cell).
  const double* imageN1() const { return periodic_ ? imageN1_.data() : nullptr; }
  const double* imageN2() const { return periodic_ ? imageN2_.data() : nullptr; }
  /// Writes the slots' state into the list's pairs (those build() was given).
  void writeBack(std::vector<PairState>& pairs) const;
  /// Where the kernel reads and writes; the particles' arrays and the law are the caller's.
  int slots() const { return slots_; }
  int paddedSlots() const { return padded_; }
  const std::int64_t* i() const { return i_.data(); }
  const std::int64_t* j() const { return j_.data(); }
  const double* radiusI() const { return radiusI_.data(); }
  const double* radiusJ() const { return radiusJ_.data(); }
  const double* dampN() const { return dampN_.data(); }
  const double* dampT() const { return dampT_.data(); }
  double* history() { return history_.data(); }
  double* fn() { return fn_.data(); }
  double* ft() { return ft_.data(); }
  double* overlap() { return overlap_.data(); }
  /// The same, read only: the state the slots hold after a step, in pair order (disc-disc pairs).
  const double* fn() const { return fn_.data(); }
  const double* ft() const { return ft_.data(); }
  const double* overlap() const { return overlap_.data(); }
  /// Rolling resistance's slots (null without it): θ_r, and the constants k_r, 1/k_r, μ_r R*, c_r.
  double* rollingHistory() { return rolls_ ? rollingHistory_.data() : nullptr; }
  const double* rollingStiffness() const { return rollingStiffness_.data(); }
  const double* rollingCompliance() const { return rollingCompliance_.data(); }
  const double* rollingCapPerForce() const { return rollingCapPerForce_.data(); }
  const double* rollingDamping() const { return rollingDamping_.data(); }
  /// Records (fx fy torque 0) of the shares that wait: slot s's i end at ends()[4 iEnd()[s]]
  /// and its j end at ends()[4 jEnd()[s]], or −1 where that end is added at once;
  /// blockDefers()[b] is 1 where block b has an end that waits (null: none has, one thread).
  double* ends() { return ends_.data(); }
  const std::int32_t* iEnd() const { return iEnd_.data(); }
  const std::int32_t* jEnd() const { return jEnd_.data(); }
  const std::uint8_t* blockDefers() const { return deferring_ ? blockDefers_.data() : nullptr; }
  /// The disc-wall pairs (their indices in the list), and wall pair w's record (−1: at once).
  const std::vector<int>& wallPairs() const { return wallPairs_; }
  std::int32_t wallEnd(int w) const { return wallEnd_[static_cast<size_t>(w)]; }
  void setRecord(std::int32_t record, double fx, double fy, double torque) {
    double* at = ends_.data() + 4 * static_cast<size_t>(record);
    at[0] = fx;
    at[1] = fy;
    at[2] = torque;
  }
  /// Adds each waiting share, in order, to its particle's force and torque (after the loop).
  void addDeferred(Vec2* force, double* torque) const {
    for (const int k : deferredParticles_) {
      // In locals: the sums stay in registers instead of going through memory at each record.
      double fx = force[k].x(), fy = force[k].y(), t = torque[k];
      const double* end = ends_.data() + 4 * static_cast<size_t>(recordStart_[static_cast<size_t>(k) + 1]);
      for (const double* e = ends_.data() + 4 * static_cast<size_t>(recordStart_[static_cast<size_t>(k)]); e < end; e += 4) {
        fx += e[0];
        fy += e[1];
        t += e[2];
      }
      force[k] = Vec2(fx, fy);
      torque[k] = t;
    }
  }

 private:
  int slots_ = 0;
  int padded_ = 0;  // slots in whole blocks
  std::vector<std::int64_t> i_, j_;
  std::vector<int> pair_;  // the slot's pair in the list
  std::vector<double> dampN_, dampT_, history_, fn_, ft_, overlap_;
  std::vector<double> radiusI_, radiusJ_;  // layRadii()
  bool rolls_ = false;
  bool periodic_ = false;
  std::vector<double> imageN1_, imageN2_;  // padding: n = 0
  std::vector<double> rollingHistory_, rollingStiffness_, rollingCompliance_, rollingCapPerForce_, rollingDamping_;
  std::vector<int> wallPairs_;
  std::vector<double> ends_;                  // fx fy torque 0: the waiting shares, particle by particle, in order
  std::vector<std::int32_t> iEnd_, jEnd_;     // per slot: its ends' records, −1 where added at once
  std::vector<std::int32_t> wallEnd_;         // per wall pair: its end's record, or −1
  std::vector<std::uint8_t> blockDefers_;     // per block: 1 where some end waits
  bool deferring_ = false;                    // some end waits (several threads)
  std::vector<int> recordStart_;              // particle k's records: [recordStart_[k], recordStart_[k+1])
  std::vector<int> deferredParticles_;        // the particles with records, in index order
};

}  // namespace grainlab

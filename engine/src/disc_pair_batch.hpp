#pragma once
// A discs-only scene's pairs laid out for the wide path: the disc-disc pairs in
// structure-of-arrays slots (what discPairForces() reads and writes) and the disc-wall pairs
// apart. Each particle adds its shares of force and torque in one order whatever the number
// of threads: its disc-disc pairs in pair order, then its walls. With one thread the kernel
// adds them at once (slots are in pair order); with several, where two threads may share a
// particle, each share waits in a record of its particle's and the particle sums them after.
// Every particle has room for kEndsHeld records (−0 where it has fewer: adding −0 changes
// nothing), so that sum is a loop of fixed length, which the processor does not mispredict;
// the records past kEndsHeld, rare, follow per particle.
// The disc-disc pairs' state (spring, fn, ft, overlap, and with rolling resistance the relative
// rotation) lives in the slots from one step to the next; writeBack() hands it to the
// neighbour list's pairs when they are read.
#include <cstdint>
#include <vector>

#include "grainlab/math.hpp"
#include "neighbor_list.hpp"
#include "rolling_resistance.hpp"

namespace grainlab {

class DiscPairBatch {
 public:
  /// Lays out the list's pairs as they are now (after a rebuild or a restore), with their state;
  /// with `rolling` (each pair's rolling constants, in pair order), their rolling lanes too;
  /// in a periodic cell, each slot's image shift n (the list's shifts()).
  void build(const NeighborList& list, int particles, const std::vector<RollingResistance::Pair>* rolling = nullptr,
             bool periodic = false);
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
  const double* dampN() const { return dampN_.data(); }
  const double* dampT() const { return dampT_.data(); }
  double* history() { return history_.data(); }
  double* fn() { return fn_.data(); }
  double* ft() { return ft_.data(); }
  double* overlap() { return overlap_.data(); }
  /// Rolling resistance's slots (null without it): θ_r, and the constants k_r, 1/k_r, μ_r R*, c_r.
  double* rollingHistory() { return rolls_ ? rollingHistory_.data() : nullptr; }
  const double* rollingStiffness() const { return rollingStiffness_.data(); }
  const double* rollingCompliance() const { return rollingCompliance_.data(); }
  const double* rollingCapPerForce() const { return rollingCapPerForce_.data(); }
  const double* rollingDamping() const { return rollingDamping_.data(); }
  /// Records (fx fy torque 0): slot s's i end at ends()[4 iEnd()[s]], its j end at ends()[4 jEnd()[s]].
  double* ends() { return ends_.data(); }
  const std::int32_t* iEnd() const { return iEnd_.data(); }
  const std::int32_t* jEnd() const { return jEnd_.data(); }
  /// The disc-wall pairs (their indices in the list), and the share of wall pair w.
  const std::vector<int>& wallPairs() const { return wallPairs_; }
  void setWallEnd(int w, double fx, double fy, double torque) {
    double* at = ends_.data() + 4 * static_cast<size_t>(wallEnd_[static_cast<size_t>(w)]);
    at[0] = fx;
    at[1] = fy;
    at[2] = torque;
  }
  /// Adds particle k's records, in order, to its force and torque.
  void addEnds(int k, Vec2& force, double& torque) const {
    // In locals: the sums stay in registers instead of going through memory at each record.
    double fx = force.x(), fy = force.y(), t = torque;
    const double* held = ends_.data() + 4 * kEndsHeld * static_cast<size_t>(k);
    for (int m = 0; m < kEndsHeld; ++m) {
      fx += held[4 * m];
      fy += held[4 * m + 1];
      t += held[4 * m + 2];
    }
    const double* end = ends_.data() + 4 * static_cast<size_t>(overflowStart_[static_cast<size_t>(k) + 1]);
    for (const double* e = ends_.data() + 4 * static_cast<size_t>(overflowStart_[static_cast<size_t>(k)]); e < end; e += 4) {
      fx += e[0];
      fy += e[1];
      t += e[2];
    }
    force = Vec2(fx, fy);
    torque = t;
  }

 private:
  int slots_ = 0;
  int padded_ = 0;  // slots in whole blocks
  std::vector<std::int64_t> i_, j_;
  std::vector<int> pair_;  // the slot's pair in the list
  std::vector<double> dampN_, dampT_, history_, fn_, ft_, overlap_;
  bool rolls_ = false;
  bool periodic_ = false;
  std::vector<double> imageN1_, imageN2_;  // padding: n = 0
  std::vector<double> rollingHistory_, rollingStiffness_, rollingCompliance_, rollingCapPerForce_, rollingDamping_;
  std::vector<int> wallPairs_;
  std::vector<double> ends_;                  // fx fy torque 0: particle k's m-th at k × kEndsHeld + m, then the overflow
  std::vector<std::int32_t> iEnd_, jEnd_;     // per slot: its ends' places (padding: one past the last)
  std::vector<std::int32_t> wallEnd_;         // per wall pair: its end's place
  static constexpr int kEndsHeld = 8;         // a settled disc pile has about 5 candidates a particle
  std::vector<int> overflowStart_;            // particle k's shares past kEndsHeld: [overflowStart_[k], …[k+1])
};

}  // namespace grainlab

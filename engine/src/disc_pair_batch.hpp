#pragma once
// A discs-only scene's pairs laid out for the wide path: the disc-disc pairs in
// structure-of-arrays slots (what discPairForces() reads), the disc-wall pairs apart, and
// room for each pair end's share of force and torque. A particle then sums its ends in pair
// order (the order the scalar loop adds them), so the result is the same bits whatever the
// number of threads, and no two lanes or threads ever add to one particle.
#include <cstdint>
#include <vector>

#include "grainlab/math.hpp"
#include "neighbor_list.hpp"

namespace grainlab {

class DiscPairBatch {
 public:
  /// Lays out the list's pairs as they are now (after a rebuild or a restore).
  void build(const NeighborList& list, int particles);
  /// Where the kernel reads and writes; the particles' arrays and the law are the caller's.
  int slots() const { return slots_; }
  int paddedSlots() const { return padded_; }
  const std::int64_t* i() const { return i_.data(); }
  const std::int64_t* j() const { return j_.data(); }
  const std::int64_t* state() const { return state_.data(); }
  const double* dampN() const { return dampN_.data(); }
  const double* dampT() const { return dampT_.data(); }
  double* endFx() { return endFx_.data(); }
  double* endFy() { return endFy_.data(); }
  double* endTorque() { return endTorque_.data(); }
  int endStride() const { return endStride_; }
  /// The disc-wall pairs (their indices in the list), and the slot of wall pair w's i end.
  const std::vector<int>& wallPairs() const { return wallPairs_; }
  int wallSlot(int w) const { return paddedSlots() + w; }
  /// Adds particle k's ends, in pair order, to its force and torque.
  void addEnds(int k, Vec2& force, double& torque) const {
    // In locals: the sums stay in registers instead of going through memory at each end.
    double fx = force.x(), fy = force.y(), t = torque;
    for (int e = endStart_[k]; e < endStart_[k + 1]; ++e) {
      const size_t at = static_cast<size_t>(ends_[static_cast<size_t>(e)]);
      fx += endFx_[at];
      fy += endFy_[at];
      t += endTorque_[at];
    }
    force = Vec2(fx, fy);
    torque = t;
  }

 private:
  int slots_ = 0;
  int padded_ = 0;  // slots in whole blocks
  std::vector<std::int64_t> i_, j_, state_;
  std::vector<double> dampN_, dampT_;
  std::vector<int> wallPairs_;
  int endStride_ = 0;                            // slots including padding and wall pairs
  std::vector<double> endFx_, endFy_, endTorque_;  // i ends at [slot], j ends at [endStride_ + slot]
  std::vector<int> endStart_, ends_;             // particle k's ends: [endStart_[k], endStart_[k+1])
};

}  // namespace grainlab

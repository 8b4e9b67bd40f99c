#pragma once
// A clump scene's member-member pairs laid out for the wide path: structure-of-arrays slots
// (what discPairForces() reads and writes with its member lanes), each slot naming its two
// member discs and their bodies, and the member-wall pairs apart. One thread adds every
// share at once, in slot (= pair) order, so a body's sums are in one fixed order.
// The pairs' state (spring, fn, ft, overlap) lives in the slots from one step to the next;
// writeBack() hands it to the neighbour list's pairs when they are read.
#include <cstdint>
#include <vector>

#include "neighbor_list.hpp"

namespace grainlab {

class MemberPairBatch {
 public:
  /// Lays out `pairs` as they are now (after a rebuild or a restore), with their state;
  /// owner[m] is member m's body.
  void build(const std::vector<PairState>& pairs, const std::vector<int>& owner);
  /// Writes the slots' state into the pairs build() was given.
  void writeBack(std::vector<PairState>& pairs) const;
  int paddedSlots() const { return static_cast<int>(i_.size()); }
  const std::int64_t* i() const { return i_.data(); }
  const std::int64_t* j() const { return j_.data(); }
  const std::int64_t* bodyI() const { return bodyI_.data(); }
  const std::int64_t* bodyJ() const { return bodyJ_.data(); }
  const double* dampN() const { return dampN_.data(); }
  const double* dampT() const { return dampT_.data(); }
  double* history() { return history_.data(); }
  double* fn() { return fn_.data(); }
  double* ft() { return ft_.data(); }
  double* overlap() { return overlap_.data(); }
  /// The member-wall pairs, by index in the list, in order.
  const std::vector<int>& wallPairs() const { return wallPairs_; }

 private:
  std::vector<std::int64_t> i_, j_, bodyI_, bodyJ_;
  std::vector<int> pair_;  // the slot's pair in the list
  std::vector<double> dampN_, dampT_, history_, fn_, ft_, overlap_;
  std::vector<int> wallPairs_;
};

}  // namespace grainlab

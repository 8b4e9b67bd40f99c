#include "disc_pair_batch.hpp"

#include <cstddef>

#include "disc_pair_kernel.hpp"

namespace grainlab {

// The kernel reads and writes a pair's state through a view of the list as doubles.
static_assert(sizeof(PairState) == 7 * sizeof(double));
static_assert(offsetof(PairState, dampN) == 1 * sizeof(double) && offsetof(PairState, history) == 3 * sizeof(double) &&
              offsetof(PairState, fn) == 4 * sizeof(double) && offsetof(PairState, ft) == 5 * sizeof(double) &&
              offsetof(PairState, overlap) == 6 * sizeof(double));

void DiscPairBatch::build(const NeighborList& list, int particles) {
  const std::vector<PairState>& pairs = list.pairs();
  i_.clear();
  j_.clear();
  state_.clear();
  dampN_.clear();
  dampT_.clear();
  wallPairs_.clear();
  std::vector<int> slotOfPair(pairs.size(), -1);
  for (size_t k = 0; k < pairs.size(); ++k) {
    const PairState& p = pairs[k];
    if (p.j < 0) {
      wallPairs_.push_back(static_cast<int>(k));
      continue;
    }
    slotOfPair[k] = static_cast<int>(i_.size());
    i_.push_back(p.i);
    j_.push_back(p.j);
    state_.push_back(static_cast<std::int64_t>(k) * 7);
    dampN_.push_back(p.dampN);
    dampT_.push_back(p.dampT);
  }
  slots_ = static_cast<int>(i_.size());
  // Padding to whole blocks: i = j = 0 is a pair at zero distance, which never touches.
  const size_t padded = (i_.size() + kDiscPairBlock - 1) / kDiscPairBlock * kDiscPairBlock;
  padded_ = static_cast<int>(padded);
  i_.resize(padded, 0);
  j_.resize(padded, 0);
  state_.resize(padded, 0);
  dampN_.resize(padded, 0);
  dampT_.resize(padded, 0);
  for (size_t w = 0; w < wallPairs_.size(); ++w) slotOfPair[static_cast<size_t>(wallPairs_[w])] = wallSlot(static_cast<int>(w));
  endStride_ = static_cast<int>(padded + wallPairs_.size());
  endFx_.assign(2 * static_cast<size_t>(endStride_), -0.0);
  endFy_.assign(2 * static_cast<size_t>(endStride_), -0.0);
  endTorque_.assign(2 * static_cast<size_t>(endStride_), -0.0);
  // Each particle's ends in pair order, as the list's adjacency names them.
  const std::vector<int>& start = list.adjacencyStart();
  const std::vector<int>& adjacency = list.adjacency();
  endStart_.assign(start.begin(), start.begin() + particles + 1);
  ends_.resize(adjacency.size());
  for (size_t e = 0; e < adjacency.size(); ++e) {
    const int pairEnd = adjacency[e];  // pair × 2, + 1 for its j end
    ends_[e] = slotOfPair[static_cast<size_t>(pairEnd >> 1)] + (pairEnd & 1) * endStride_;
  }
}

}  // namespace grainlab

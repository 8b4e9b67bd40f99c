#include "disc_pair_batch.hpp"

#include "disc_pair_kernel.hpp"

namespace grainlab {

void DiscPairBatch::build(const NeighborList& list, int particles, const std::vector<RollingResistance::Pair>* rolling,
                          bool periodic) {
  const std::vector<PairState>& pairs = list.pairs();
  rolls_ = rolling != nullptr;
  periodic_ = periodic;
  imageN1_.clear();
  imageN2_.clear();
  for (std::vector<double>* v : {&rollingHistory_, &rollingStiffness_, &rollingCompliance_, &rollingCapPerForce_,
                                 &rollingDamping_}) {
    v->clear();
  }
  i_.clear();
  j_.clear();
  pair_.clear();
  dampN_.clear();
  dampT_.clear();
  history_.clear();
  wallPairs_.clear();
  iEnd_.clear();
  jEnd_.clear();
  wallEnd_.clear();
  // Each pair end's record: particle k's disc-disc ends in pair order (as the list's adjacency
  // names them), then its walls; the first kEndsHeld at k × kEndsHeld on, the rest in the
  // overflow after all of those.
  const std::vector<int>& adjacency = list.adjacency();
  const std::vector<int>& adjacencyStart = list.adjacencyStart();
  const size_t n = static_cast<size_t>(particles);
  std::vector<std::int32_t> place(2 * pairs.size(), 0);
  overflowStart_.assign(n + 1, 0);
  auto next = static_cast<std::int32_t>(n * kEndsHeld);
  for (size_t k = 0; k < n; ++k) {
    overflowStart_[k] = next;
    int m = 0;
    for (const bool walls : {false, true}) {
      for (int e = adjacencyStart[k]; e < adjacencyStart[k + 1]; ++e) {
        const int pairEnd = adjacency[static_cast<size_t>(e)];  // pair × 2, + 1 for its j end
        if ((pairs[static_cast<size_t>(pairEnd >> 1)].j < 0) != walls) continue;
        place[static_cast<size_t>(pairEnd)] = m < kEndsHeld ? static_cast<std::int32_t>(k * kEndsHeld + m) : next++;
        ++m;
      }
    }
  }
  overflowStart_[n] = next;
  for (size_t k = 0; k < pairs.size(); ++k) {
    const PairState& p = pairs[k];
    if (p.j < 0) {
      wallPairs_.push_back(static_cast<int>(k));
      wallEnd_.push_back(place[2 * k]);
      continue;
    }
    i_.push_back(p.i);
    j_.push_back(p.j);
    iEnd_.push_back(place[2 * k]);
    jEnd_.push_back(place[2 * k + 1]);
    pair_.push_back(static_cast<int>(k));
    dampN_.push_back(p.dampN);
    dampT_.push_back(p.dampT);
    history_.push_back(p.history.tangential);
    if (periodic_) {
      imageN1_.push_back(list.shifts()[k].n1);
      imageN2_.push_back(list.shifts()[k].n2);
    }
    if (rolls_) {
      const RollingResistance::Pair& r = (*rolling)[k];
      rollingHistory_.push_back(p.history.rolling);
      rollingStiffness_.push_back(r.stiffness);
      rollingCompliance_.push_back(r.compliance);
      rollingCapPerForce_.push_back(r.capPerForce);
      rollingDamping_.push_back(r.damping);
    }
  }
  slots_ = static_cast<int>(i_.size());
  // Padding to whole blocks: i = j = 0 is a pair at zero distance, which never touches; its
  // ends go to a place no particle reads.
  const size_t padded = (i_.size() + kDiscPairBlock - 1) / kDiscPairBlock * kDiscPairBlock;
  const std::int32_t spare = next;
  padded_ = static_cast<int>(padded);
  i_.resize(padded, 0);
  j_.resize(padded, 0);
  iEnd_.resize(padded, spare);
  jEnd_.resize(padded, spare);
  dampN_.resize(padded, 0);
  dampT_.resize(padded, 0);
  history_.resize(padded, 0);
  fn_.assign(padded, 0);
  ft_.assign(padded, 0);
  overlap_.assign(padded, 0);
  if (periodic_) {
    imageN1_.resize(padded, 0);
    imageN2_.resize(padded, 0);
  }
  if (rolls_) {
    for (std::vector<double>* v : {&rollingHistory_, &rollingStiffness_, &rollingCompliance_, &rollingCapPerForce_,
                                   &rollingDamping_}) {
      v->resize(padded, 0);
    }
  }
  ends_.assign(4 * (static_cast<size_t>(next) + 1), -0.0);
}

void DiscPairBatch::writeBack(std::vector<PairState>& pairs) const {
  for (int s = 0; s < slots_; ++s) {
    PairState& p = pairs[static_cast<size_t>(pair_[static_cast<size_t>(s)])];
    p.history.tangential = history_[static_cast<size_t>(s)];
    p.fn = fn_[static_cast<size_t>(s)];
    p.ft = ft_[static_cast<size_t>(s)];
    p.overlap = overlap_[static_cast<size_t>(s)];
    if (rolls_) p.history.rolling = rollingHistory_[static_cast<size_t>(s)];
  }
}

}  // namespace grainlab

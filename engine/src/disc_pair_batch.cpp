#include "disc_pair_batch.hpp"

#include <algorithm>

#include "disc_pair_kernel.hpp"
#include "worker_pool.hpp"

namespace grainlab {

void DiscPairBatch::build(const NeighborList& list, int particles, const std::vector<RollingResistance::Pair>* rolling,
                          bool periodic, int threads) {
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
  // Each pair's place: its slot (disc-disc) or its index among the wall pairs.
  std::vector<int> placeOfPair(pairs.size());
  for (size_t k = 0; k < pairs.size(); ++k) {
    const PairState& p = pairs[k];
    if (p.j < 0) {
      placeOfPair[k] = static_cast<int>(wallPairs_.size());
      wallPairs_.push_back(static_cast<int>(k));
      continue;
    }
    placeOfPair[k] = static_cast<int>(i_.size());
    i_.push_back(p.i);
    j_.push_back(p.j);
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
  // Padding to whole blocks: i = j = 0 is a pair at zero distance, which never touches.
  const size_t padded = (i_.size() + kDiscPairBlock - 1) / kDiscPairBlock * kDiscPairBlock;
  padded_ = static_cast<int>(padded);
  i_.resize(padded, 0);
  j_.resize(padded, 0);
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

  // Which slice computes each pair (parallelFor's contiguous slices of the work items).
  const int items = workItems();
  std::vector<int> sliceEnd(static_cast<size_t>(threads));
  for (int t = 0; t < threads; ++t) sliceEnd[static_cast<size_t>(t)] = WorkerPool::sliceBegin(items, t + 1, threads);
  auto sliceOf = [&](size_t pair) {
    const int item = pairs[pair].j < 0 ? blocks() + placeOfPair[pair] / kWallPairsPerItem
                                       : placeOfPair[pair] / kDiscPairBlock;
    return static_cast<int>(std::upper_bound(sliceEnd.begin(), sliceEnd.end(), item) - sliceEnd.begin());
  };
  // Each particle's ends in the order it adds them: its disc-disc pairs in pair order (as the
  // list's adjacency names them), then its walls. The first end's slice owns the particle; an
  // end computed in another slice gets the particle's next record.
  const std::vector<int>& adjacency = list.adjacency();
  const std::vector<int>& adjacencyStart = list.adjacencyStart();
  const size_t n = static_cast<size_t>(particles);
  std::vector<std::int32_t> record(2 * pairs.size(), -1);
  recordStart_.assign(n + 1, 0);
  deferredParticles_.clear();
  std::int32_t next = 0;
  for (size_t k = 0; k < n; ++k) {
    recordStart_[k] = next;
    int owner = -1;
    for (const bool walls : {false, true}) {
      for (int e = adjacencyStart[k]; e < adjacencyStart[k + 1]; ++e) {
        const int pairEnd = adjacency[static_cast<size_t>(e)];  // pair × 2, + 1 for its j end
        const size_t pair = static_cast<size_t>(pairEnd >> 1);
        if ((pairs[pair].j < 0) != walls) continue;
        const int slice = sliceOf(pair);
        if (owner < 0) owner = slice;
        if (slice != owner) record[static_cast<size_t>(pairEnd)] = next++;
      }
    }
    if (next > recordStart_[k]) deferredParticles_.push_back(static_cast<int>(k));
  }
  recordStart_[n] = next;
  deferring_ = next > 0;
  iEnd_.assign(padded, -1);
  jEnd_.assign(padded, -1);
  blockDefers_.assign(padded / kDiscPairBlock, 0);
  for (int s = 0; s < slots_; ++s) {
    const size_t k = static_cast<size_t>(pair_[static_cast<size_t>(s)]);
    iEnd_[static_cast<size_t>(s)] = record[2 * k];
    jEnd_[static_cast<size_t>(s)] = record[2 * k + 1];
    if (record[2 * k] >= 0 || record[2 * k + 1] >= 0) blockDefers_[static_cast<size_t>(s / kDiscPairBlock)] = 1;
  }
  wallEnd_.clear();
  for (const int k : wallPairs_) wallEnd_.push_back(record[2 * static_cast<size_t>(k)]);
  ends_.assign(4 * (static_cast<size_t>(next) + 1), -0.0);
}

void DiscPairBatch::layRadii(const double* radius) {
  radiusI_.resize(i_.size());
  radiusJ_.resize(j_.size());
  for (size_t s = 0; s < i_.size(); ++s) {
    radiusI_[s] = radius[i_[s]];
    radiusJ_[s] = radius[j_[s]];
  }
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

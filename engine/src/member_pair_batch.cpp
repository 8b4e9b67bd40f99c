#include "member_pair_batch.hpp"

#include "disc_pair_kernel.hpp"

namespace grainlab {

void MemberPairBatch::build(const std::vector<PairState>& pairs, const std::vector<int>& owner) {
  for (auto* v : {&i_, &j_, &bodyI_, &bodyJ_}) v->clear();
  for (auto* v : {&dampN_, &dampT_, &history_}) v->clear();
  pair_.clear();
  wallPairs_.clear();
  for (size_t k = 0; k < pairs.size(); ++k) {
    const PairState& p = pairs[k];
    if (p.j < 0) {
      wallPairs_.push_back(static_cast<int>(k));
      continue;
    }
    i_.push_back(p.i);
    j_.push_back(p.j);
    bodyI_.push_back(owner[static_cast<size_t>(p.i)]);
    bodyJ_.push_back(owner[static_cast<size_t>(p.j)]);
    pair_.push_back(static_cast<int>(k));
    dampN_.push_back(p.dampN);
    dampT_.push_back(p.dampT);
    history_.push_back(p.history.tangential);
  }
  // Padding to whole blocks: members 0 and 0 are at zero distance, which never touches.
  const size_t padded = (i_.size() + kDiscPairBlock - 1) / kDiscPairBlock * kDiscPairBlock;
  for (auto* v : {&i_, &j_, &bodyI_, &bodyJ_}) v->resize(padded, 0);
  for (auto* v : {&dampN_, &dampT_, &history_}) v->resize(padded, 0);
  fn_.assign(padded, 0);
  ft_.assign(padded, 0);
  overlap_.assign(padded, 0);
}

void MemberPairBatch::writeBack(std::vector<PairState>& pairs) const {
  for (size_t s = 0; s < pair_.size(); ++s) {
    PairState& p = pairs[static_cast<size_t>(pair_[s])];
    p.history.tangential = history_[s];
    p.fn = fn_[s];
    p.ft = ft_[s];
    p.overlap = overlap_[s];
  }
}

}  // namespace grainlab

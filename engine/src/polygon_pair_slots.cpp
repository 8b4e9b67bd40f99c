#include "polygon_pair_slots.hpp"

#include <stdexcept>

namespace grainlab {

void PolygonSlotAnchors::resize(size_t slots) {
  pair_.resize(slots);
  i_.resize(slots);
  j_.resize(slots);
  for (std::vector<double>* v : {&offsetX_, &offsetY_, &lever_, &ca_, &sa_, &cb_, &sb_, &slack_, &reach_}) {
    v->resize(slots);
  }
}

void PolygonSlotAnchors::set(int slot, int k, int i, int j, const CachedContact& c, double reach) {
  const auto s = static_cast<size_t>(slot);
  pair_[s] = k;
  i_[s] = i;
  j_[s] = j;
  offsetX_[s] = c.offset.x();
  offsetY_[s] = c.offset.y();
  lever_[s] = c.lever;
  ca_[s] = c.ca;
  sa_[s] = c.sa;
  cb_[s] = c.cb;
  sb_[s] = c.sb;
  slack_[s] = c.slack;
  reach_[s] = reach;
}

void PolygonSlotAnchors::move(int from, int to) {
  const auto f = static_cast<size_t>(from), t = static_cast<size_t>(to);
  pair_[t] = pair_[f];
  i_[t] = i_[f];
  j_[t] = j_[f];
  for (std::vector<double>* v : {&offsetX_, &offsetY_, &lever_, &ca_, &sa_, &cb_, &sb_, &slack_, &reach_}) {
    (*v)[t] = (*v)[f];
  }
}

PolygonHoldInput PolygonSlotAnchors::holdInput(int begin) const {
  const auto s = static_cast<size_t>(begin);
  PolygonHoldInput in{};
  in.i = i_.data() + s;
  in.j = j_.data() + s;
  in.offsetX = offsetX_.data() + s;
  in.offsetY = offsetY_.data() + s;
  in.lever = lever_.data() + s;
  in.ca = ca_.data() + s;
  in.sa = sa_.data() + s;
  in.cb = cb_.data() + s;
  in.sb = sb_.data() + s;
  in.slack = slack_.data() + s;
  in.reach = reach_.data() + s;
  return in;
}

void PolygonPairSlots::reset(int pairs, std::span<const int> begins) {
  const auto n = static_cast<size_t>(pairs);
  slotOf_.assign(n, kOther);
  others_.resize(n);
  failedFaces_.resize(n);
  failedAparts_.resize(n);
  faceAnchors_.resize(n);
  apartAnchors_.resize(n);
  ranges_.clear();
  for (size_t t = 0; t < begins.size(); ++t) {
    Range r;
    r.begin = begins[t];
    r.end = t + 1 < begins.size() ? begins[t + 1] : pairs;
    r.others = r.end - r.begin;
    for (int k = r.begin; k < r.end; ++k) others_[static_cast<size_t>(k)] = k;
    ranges_.push_back(r);
  }
  stale_ = false;
}

PolygonPairSlots::Range& PolygonPairSlots::range(int begin, int end) {
  for (Range& r : ranges_) {
    if (r.begin == begin && r.end == end) return r;
  }
  throw std::logic_error("PolygonPairSlots: no such range of pairs (the slicing changed without a reset)");
}

void PolygonPairSlots::fillFace(PolygonFaceBatch& batch, int slot, int k, const CachedContact& c, int i, int j,
                                double reach, int a, const Pose& pi, int b, const Pose& pj,
                                const PolygonCollider& collider) {
  batch.setParticles(slot, i, j);
  batch.add(slot, k, c, a, pi, b, pj, collider);
  faceAnchors_.set(slot, k, i, j, c, reach);
  slotOf_[static_cast<size_t>(k)] = slot;
}

void PolygonPairSlots::fillApart(int slot, int k, const CachedContact& c, int i, int j, double reach) {
  apartAnchors_.set(slot, k, i, j, c, reach);
  slotOf_[static_cast<size_t>(k)] = kApart;
}

void PolygonPairSlots::removeFace(PolygonFaceBatch& batch, Range& r, int slot) {
  const int last = r.begin + r.faces - 1;
  slotOf_[static_cast<size_t>(batch.pairOf(slot))] = kOther;
  if (slot != last) {
    batch.moveSlot(last, slot);
    faceAnchors_.move(last, slot);
    slotOf_[static_cast<size_t>(batch.pairOf(slot))] = slot;
  }
  --r.faces;
}

void PolygonPairSlots::removeApart(Range& r, int slot) {
  const int last = r.begin + r.aparts - 1;
  slotOf_[static_cast<size_t>(apartAnchors_.pairOf(slot))] = kOther;
  if (slot != last) apartAnchors_.move(last, slot);
  --r.aparts;
}

PolygonHoldInput PolygonPairSlots::faceHoldInput(PolygonFaceBatch& batch, const Range& r,
                                                 const PolygonHoldInput::Particles& p) const {
  PolygonHoldInput in = faceAnchors_.holdInput(r.begin);
  in.particles = p;
  batch.addPoses(r.begin, in);
  return in;
}

PolygonHoldInput PolygonPairSlots::apartHoldInput(const Range& r, const PolygonHoldInput::Particles& p) const {
  PolygonHoldInput in = apartAnchors_.holdInput(r.begin);
  in.particles = p;
  return in;
}

}  // namespace grainlab

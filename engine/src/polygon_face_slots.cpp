#include "polygon_face_slots.hpp"

#include <stdexcept>

namespace grainlab {

void PolygonFaceSlots::reset(int pairs, std::span<const int> begins) {
  const auto n = static_cast<size_t>(pairs);
  slotOf_.assign(n, -1);
  others_.resize(n);
  failed_.resize(n);
  for (std::vector<double>* v : {&offsetX_, &offsetY_, &lever_, &ca_, &sa_, &cb_, &sb_, &slack_, &reach_}) v->resize(n);
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

PolygonFaceSlots::Range& PolygonFaceSlots::range(int begin) {
  for (Range& r : ranges_) {
    if (r.begin == begin) return r;
  }
  throw std::logic_error("PolygonFaceSlots: no range begins at this pair (the slicing changed without a reset)");
}

void PolygonFaceSlots::fill(PolygonFaceBatch& batch, int slot, int k, const CachedContact& c, int i, int j,
                            double reach, int a, const Pose& pi, int b, const Pose& pj,
                            const PolygonCollider& collider) {
  batch.setParticles(slot, i, j);
  batch.add(slot, k, c, a, pi, b, pj, collider);
  const auto s = static_cast<size_t>(slot);
  offsetX_[s] = c.offset.x();
  offsetY_[s] = c.offset.y();
  lever_[s] = c.lever;
  ca_[s] = c.ca;
  sa_[s] = c.sa;
  cb_[s] = c.cb;
  sb_[s] = c.sb;
  slack_[s] = c.slack;
  reach_[s] = reach;
  slotOf_[static_cast<size_t>(k)] = slot;
}

void PolygonFaceSlots::remove(PolygonFaceBatch& batch, Range& r, int slot) {
  const int last = r.begin + r.faces - 1;
  slotOf_[static_cast<size_t>(batch.pairOf(slot))] = -1;
  if (slot != last) {
    batch.moveSlot(last, slot);
    const auto to = static_cast<size_t>(slot), from = static_cast<size_t>(last);
    for (std::vector<double>* v : {&offsetX_, &offsetY_, &lever_, &ca_, &sa_, &cb_, &sb_, &slack_, &reach_}) {
      (*v)[to] = (*v)[from];
    }
    slotOf_[static_cast<size_t>(batch.pairOf(slot))] = slot;
  }
  --r.faces;
}

PolygonHoldInput PolygonFaceSlots::holdInput(PolygonFaceBatch& batch, const Range& r, const double* position,
                                             const double* cosAngle, const double* sinAngle) {
  PolygonHoldInput in = batch.holdInput(r.begin);
  const auto s = static_cast<size_t>(r.begin);
  in.offsetX = offsetX_.data() + s;
  in.offsetY = offsetY_.data() + s;
  in.lever = lever_.data() + s;
  in.ca = ca_.data() + s;
  in.sa = sa_.data() + s;
  in.cb = cb_.data() + s;
  in.sb = sb_.data() + s;
  in.slack = slack_.data() + s;
  in.reach = reach_.data() + s;
  in.position = position;
  in.cosAngle = cosAngle;
  in.sinAngle = sinAngle;
  return in;
}

}  // namespace grainlab

#pragma once
// The wide path's face-against-edge pairs kept in their batch slots from one step to the next
// (outside a periodic cell).
//
// Between two rebuilds of the neighbour list a polygon pair seldom changes its kind: counted
// over a full elongated-bedding-30 run, 1,320 of a step's 3,275 pairs were a face against an
// edge, and about 50 a step were searched again, nearly all finding a face again. So a pair
// that is a face against an edge keeps its slot: each step one kernel (polygon_hold_kernel.hpp)
// tests every slot's bounding circles and motion, several slots per instruction, and writes its
// poses; only the slots that fail those tests, and the pairs that are not in a slot, go through
// the scalar first pass. Each decision is the one the first pass would have taken, in its
// operations, and forces are still added in pair order: the bits do not change.
//
// A pair range [begin, end) (one thread's slice) owns slots [begin, begin + faces) of the batch
// and the list of its other pairs; slots are unordered (a slot that leaves is filled by the
// last one).
#include <cstdint>
#include <span>
#include <vector>

#include "polygon_face_batch.hpp"
#include "polygon_hold_kernel.hpp"

namespace grainlab {

class PolygonFaceSlots {
 public:
  struct Range {
    int begin = 0, end = 0;
    int faces = 0;   // slots [begin, begin + faces) are in use
    int others = 0;  // its other pairs: others()[0, others)
  };

  /// Whether the slots must be laid out again (reset()) before the next pass.
  bool stale() const { return stale_; }
  /// The pair list, its slicing, the pairs' features or the path changed: every slot is dropped
  /// at the next pass.
  void markStale() { stale_ = true; }
  /// No slots: each of the slices [begins[t], begins[t + 1]) of the `pairs` pairs starts with
  /// all its pairs in its list of others, in pair order.
  void reset(int pairs, std::span<const int> begins);

  /// The range that begins at `begin` (one of reset()'s slices).
  Range& range(int begin);
  /// The range's other pairs (room for all of its pairs).
  int* others(const Range& r) { return others_.data() + r.begin; }
  /// Room for the range's failed slots.
  std::int32_t* failed(const Range& r) { return failed_.data() + r.begin; }
  /// Pair k's slot, or −1.
  int slotOf(int k) const { return slotOf_[static_cast<size_t>(k)]; }

  /// Puts pair k (particles i, j; reach r_i + r_j) with face features `c` into `slot` of
  /// `batch`, with its poses and the anchor its features were found at.
  void fill(PolygonFaceBatch& batch, int slot, int k, const CachedContact& c, int i, int j, double reach, int a,
            const Pose& pi, int b, const Pose& pj, const PolygonCollider& collider);
  /// Takes `slot` out of the range; the range's last slot moves into it.
  void remove(PolygonFaceBatch& batch, Range& r, int slot);

  /// The hold kernel's view of the range's slots.
  PolygonHoldInput holdInput(PolygonFaceBatch& batch, const Range& r, const double* position, const double* cosAngle,
                             const double* sinAngle);

 private:
  bool stale_ = true;
  std::vector<Range> ranges_;
  std::vector<int> slotOf_;             // per pair
  std::vector<int> others_;             // per range, from its begin
  std::vector<std::int32_t> failed_;    // per range, from its begin
  // Per slot: the anchor (CachedContact's offset, lever, rotations), slack and reach.
  std::vector<double> offsetX_, offsetY_, lever_, ca_, sa_, cb_, sb_, slack_, reach_;
};

}  // namespace grainlab

#pragma once
// The wide path's polygon pairs kept in slots from one step to the next, by what their kept
// features say: a face against an edge (in the face batch's slots, measured by its kernel) or
// apart (outside a periodic cell).
//
// Between two rebuilds of the neighbour list a polygon pair seldom changes its answer: counted
// over a full elongated-bedding-30 run, of a step's 3,275 pairs 1,320 were a face against an
// edge and 1,344 kept apart by their features, and about 50 a step were searched again, nearly
// all finding the same kind. So such a pair keeps its slot: each step one kernel
// (polygon_hold_kernel.hpp) tests every slot's bounding circles and motion, several slots per
// instruction, and writes the face slots' poses; only the slots that fail those tests, and the
// pairs in no slot (a disc or a wall at an end, bounding circles apart), go through the scalar
// first pass. Each decision is the one the first pass would have taken, in its operations, and
// forces are still added in pair order: the bits do not change.
//
// A pair range [begin, end) (one thread's slice) owns face slots [begin, begin + faces) of the
// batch, apart slots [begin, begin + aparts) and the list of its other pairs; slots are
// unordered (a slot that leaves is filled by its range's last one).
#include <cstdint>
#include <span>
#include <vector>

#include "polygon_face_batch.hpp"
#include "polygon_hold_kernel.hpp"

namespace grainlab {

/// Per slot: the pair, its particles and the anchor its features were found at: what the hold
/// kernel tests.
class PolygonSlotAnchors {
 public:
  void resize(size_t slots);
  void set(int slot, int k, int i, int j, const CachedContact& c, double reach);
  void move(int from, int to);
  int pairOf(int slot) const { return pair_[static_cast<size_t>(slot)]; }
  /// The hold kernel's view of the slots from `begin` on (no poses to write).
  PolygonHoldInput holdInput(int begin) const;

 private:
  std::vector<std::int32_t> pair_;
  std::vector<std::int64_t> i_, j_;
  // CachedContact's offset, lever and rotations; its slack; the pair's reach r_i + r_j.
  std::vector<double> offsetX_, offsetY_, lever_, ca_, sa_, cb_, sb_, slack_, reach_;
};

class PolygonPairSlots {
 public:
  struct Range {
    int begin = 0, end = 0;
    int faces = 0;   // face slots [begin, begin + faces) are in use
    int aparts = 0;  // apart slots [begin, begin + aparts)
    int others = 0;  // its other pairs: others()[0, others)
  };
  /// Where a pair is (slotOf()): a face slot's index is >= 0.
  static constexpr int kOther = -1, kApart = -2;

  /// Whether the slots must be laid out again (reset()) before the next pass.
  bool stale() const { return stale_; }
  /// The pair list, its slicing, the pairs' features or the path changed: every slot is dropped
  /// at the next pass.
  void markStale() { stale_ = true; }
  /// No slots: each of the slices [begins[t], begins[t + 1]) of the `pairs` pairs starts with
  /// all its pairs in its list of others, in pair order.
  void reset(int pairs, std::span<const int> begins);

  /// The range [begin, end) (one of reset()'s slices).
  Range& range(int begin, int end);
  /// The range's other pairs (room for all of its pairs).
  int* others(const Range& r) { return others_.data() + r.begin; }
  /// Room for the range's failed face slots and failed apart slots.
  std::int32_t* failedFaces(const Range& r) { return failedFaces_.data() + r.begin; }
  std::int32_t* failedAparts(const Range& r) { return failedAparts_.data() + r.begin; }
  /// Pair k's face slot, or kApart, or kOther.
  int slotOf(int k) const { return slotOf_[static_cast<size_t>(k)]; }

  /// Puts pair k (particles i, j; reach r_i + r_j) with face features `c` into face `slot` of
  /// `batch`, with its poses and the anchor its features were found at.
  void fillFace(PolygonFaceBatch& batch, int slot, int k, const CachedContact& c, int i, int j, double reach, int a,
                const Pose& pi, int b, const Pose& pj, const PolygonCollider& collider);
  /// Puts pair k with features `c` saying apart into apart `slot`.
  void fillApart(int slot, int k, const CachedContact& c, int i, int j, double reach);
  /// Takes face `slot` out of the range; the range's last face slot moves into it.
  void removeFace(PolygonFaceBatch& batch, Range& r, int slot);
  /// Takes apart `slot` out of the range; the range's last apart slot moves into it.
  void removeApart(Range& r, int slot);
  int apartPair(int slot) const { return apartAnchors_.pairOf(slot); }

  /// The hold kernel's view of the range's face slots (with their poses to write) and of its
  /// apart slots.
  PolygonHoldInput faceHoldInput(PolygonFaceBatch& batch, const Range& r, const PolygonHoldInput::Particles& p) const;
  PolygonHoldInput apartHoldInput(const Range& r, const PolygonHoldInput::Particles& p) const;

 private:
  bool stale_ = true;
  std::vector<Range> ranges_;
  std::vector<int> slotOf_;  // per pair
  std::vector<int> others_;  // per range, from its begin
  std::vector<std::int32_t> failedFaces_, failedAparts_;  // per range, from its begin
  PolygonSlotAnchors faceAnchors_, apartAnchors_;
};

}  // namespace grainlab

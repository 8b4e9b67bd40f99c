#pragma once
// A polygon scene's face-against-edge contacts laid out for the wide path: the pairs whose kept
// features are a face against an edge (PolygonCollider::keepPolygonFeatures) sit in
// structure-of-arrays slots and are measured several per instruction (polygon_face_kernel.hpp),
// to the bits of PolygonCollider::measurePolygons. Outside a periodic cell a pair keeps its slot
// from step to step (polygon_pair_slots.hpp); in a cell the slots are filled each step. Every pair has a
// contact here, by its index in the list: the batch's measurement, or whatever the caller
// wrote (the scalar narrow phase's answer for the other pairs). A range of pairs
// [begin, end) uses the slots from begin on, so threads on disjoint ranges share nothing.
#include <cstdint>
#include <vector>

#include "contact_geometry.hpp"
#include "polygon_collider.hpp"
#include "polygon_face_kernel.hpp"
#include "polygon_hold_kernel.hpp"

namespace grainlab {

/// A batched pair's answer, as the pair loop hands it on: the force on j from i and the
/// torques about i's and j's centroids (the pair's state is already updated).
struct PolygonFaceForce {
  Vec2 force;
  double torqueI, torqueJ;
};

class PolygonFaceBatch {
 public:
  /// Room for `pairs` pairs.
  void resize(size_t pairs) {
    contacts_.resize(pairs);
    for (std::vector<double>* v : {&refX_, &refY_, &refC_, &refS_, &incX_, &incY_, &incC_, &incS_, &normalSign_}) {
      v->resize(pairs);
    }
    face_.resize(pairs);
    edge_.resize(pairs);
    pair_.resize(pairs);
    for (std::vector<std::int64_t>* v : {&i_, &j_}) v->resize(pairs);
    for (std::vector<double>* v : {&fx_, &fy_, &torqueI_, &torqueJ_}) v->resize(pairs);
    touching_.resize(pairs);
  }
  /// Pair k's contact: measured (after measure()) or as the caller wrote it.
  ContactGeometry& contact(int k) { return contacts_[static_cast<size_t>(k)]; }
  const ContactGeometry& contact(int k) const { return contacts_[static_cast<size_t>(k)]; }

  /// Puts pair k, polygon a at pa against polygon b at pb with face features `c` (FaceA or
  /// FaceB), in `slot`, and fetches its shape records from `collider`'s tables ahead of measure().
  [[gnu::always_inline]] void add(int slot, int k, const CachedContact& c, int a, const Pose& pa, int b, const Pose& pb,
           const PolygonCollider& collider) {
    const bool faceA = c.kind == CachedContact::Kind::FaceA;
    const Pose& r = faceA ? pa : pb;
    const Pose& i = faceA ? pb : pa;
    const auto s = static_cast<size_t>(slot);
    refX_[s] = r.x.x();
    refY_[s] = r.x.y();
    refC_[s] = r.c;
    refS_[s] = r.s;
    incX_[s] = i.x.x();
    incY_[s] = i.x.y();
    incC_[s] = i.c;
    incS_[s] = i.s;
    normalSign_[s] = faceA ? 1.0 : -1.0;
    face_[s] = kFaceRecord * (static_cast<std::int64_t>(faceA ? a : b) * kMaxPolygonVertices + c.reference);
    edge_[s] = kEdgeRecord * (static_cast<std::int64_t>(faceA ? b : a) * kMaxPolygonVertices + c.incident);
    pair_[s] = k;
    // The records are scattered (a polygon's own shape per particle): their cache misses
    // overlap here, where nothing waits on them, instead of stalling the kernel's gathers.
    __builtin_prefetch(collider.faceTable() + face_[s]);
    __builtin_prefetch(collider.faceTable() + face_[s] + kFaceRecord - 1);
    __builtin_prefetch(collider.edgeTable() + edge_[s]);
    __builtin_prefetch(collider.edgeTable() + edge_[s] + kEdgeRecord - 1);
  }

  /// The particles i and j of the pair in `slot` (for measureForces()).
  void setParticles(int slot, int i, int j) {
    i_[static_cast<size_t>(slot)] = i;
    j_[static_cast<size_t>(slot)] = j;
  }

  /// Moves slot `from` into `to`: its pair, particles, features and poses (not its answers).
  void moveSlot(int from, int to) {
    const auto f = static_cast<size_t>(from), t = static_cast<size_t>(to);
    for (std::vector<double>* v : {&refX_, &refY_, &refC_, &refS_, &incX_, &incY_, &incC_, &incS_, &normalSign_}) {
      (*v)[t] = (*v)[f];
    }
    for (std::vector<std::int64_t>* v : {&face_, &edge_, &i_, &j_}) (*v)[t] = (*v)[f];
    pair_[t] = pair_[f];
  }
  /// Where the hold kernel writes the poses of the slots from `begin` on, and their normals' signs.
  void addPoses(int begin, PolygonHoldInput& in) {
    const auto s = static_cast<size_t>(begin);
    in.normalSign = normalSign_.data() + s;
    in.refX = refX_.data() + s;
    in.refY = refY_.data() + s;
    in.refC = refC_.data() + s;
    in.refS = refS_.data() + s;
    in.incX = incX_.data() + s;
    in.incY = incY_.data() + s;
    in.incC = incC_.data() + s;
    in.incS = incS_.data() + s;
  }

  /// Measures slots [begin, begin + count) into their pairs' contacts.
  void measure(const PolygonCollider& collider, int begin, int count) {
    if (count == 0) return;
    const auto s = static_cast<size_t>(begin);
    const PolygonFaceKernelInput in = kernelInput(collider, s);
    measurePolygonFaces(in, count);
  }
  /// Measures slots [begin, begin + count) and applies `law` at each (the pairs' state in
  /// `pairs` read and written in place): the slot's force(), torques and touches(), and the
  /// touching pairs' contacts.
  void measureForces(const PolygonCollider& collider, const PolygonFaceLaw& law, const double* velocity,
                     const double* spin, PairState* pairs, int begin, int count) {
    if (count == 0) return;
    const auto s = static_cast<size_t>(begin);
    const PolygonFaceKernelInput in = kernelInput(collider, s);
    const PolygonFaceForceInput forces{i_.data() + s, j_.data() + s, velocity, spin, pairs, law,
                                       fx_.data() + s, fy_.data() + s, torqueI_.data() + s, torqueJ_.data() + s,
                                       touching_.data() + s};
    measurePolygonFaceForces(in, forces, count);
  }
  /// After measureForces(): the pair in `slot`, whether it touches, the force on j from i, and
  /// the torques about i's and j's centroids.
  int pairOf(int slot) const { return pair_[static_cast<size_t>(slot)]; }
  bool touches(int slot) const { return touching_[static_cast<size_t>(slot)] != 0; }
  Vec2 force(int slot) const { return {fx_[static_cast<size_t>(slot)], fy_[static_cast<size_t>(slot)]}; }
  double torqueI(int slot) const { return torqueI_[static_cast<size_t>(slot)]; }
  double torqueJ(int slot) const { return torqueJ_[static_cast<size_t>(slot)]; }

 private:
  /// The kernel's view of the slots from `s` on.
  PolygonFaceKernelInput kernelInput(const PolygonCollider& collider, size_t s) {
    return {refX_.data() + s, refY_.data() + s, refC_.data() + s, refS_.data() + s,
            incX_.data() + s, incY_.data() + s, incC_.data() + s, incS_.data() + s,
            face_.data() + s, edge_.data() + s, normalSign_.data() + s, pair_.data() + s,
            collider.faceTable(), collider.edgeTable(), contacts_.data()};
  }
  std::vector<ContactGeometry> contacts_;  // per pair
  std::vector<double> refX_, refY_, refC_, refS_, incX_, incY_, incC_, incS_, normalSign_;  // per slot
  std::vector<std::int64_t> face_, edge_;
  std::vector<std::int32_t> pair_;
  std::vector<std::int64_t> i_, j_;
  std::vector<double> fx_, fy_, torqueI_, torqueJ_;
  std::vector<std::uint8_t> touching_;
};

}  // namespace grainlab

#include "contact_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "contact_law.hpp"
#include "disc_pair_kernel.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/state_archive.hpp"
#include "local_damping.hpp"
#include "rolling_resistance.hpp"
#include "runaway_overlap.hpp"
#include "worker_pool.hpp"

namespace grainlab {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// The law at a touching pair whose relative motion is m, with unit normal n and tangent t:
// the force on j from i. Records the pair's history and last forces. Both contact forms
// below end here.
template <class Law>
inline Vec2 lawForce(PairState& p, const ContactMotion& m, const Vec2& n, const Vec2& t, const Law& law, double dt) {
  p.fn = law.normal.force(m, p.dampN);
  p.ft = law.tangential.force(p.fn, m, p.dampT, dt, p.history.tangential);
  p.overlap = m.overlap;
  return p.fn * n + p.ft * t;
}

// Cundall-Strack friction with rolling resistance (rolling_resistance.hpp).
using RollingLaw = ContactLaw<LinearSpringDashpot, CundallStrack, RollingResistance>;
RollingResistance rollingModel(const Material& m) {
  return {m.rollingStiffnessRatio, m.tangentialStiffness, m.rollingFriction, m.rollingDamping};
}

// A pair that does not touch keeps no history and reports no force.
void clearContact(PairState& p) {
  p.history = {};
  p.fn = p.ft = p.overlap = 0;
}

}  // namespace

ContactSolver::ContactSolver(ParticleStore& particles, const Material& material, double skinFraction,
                             WorkerPool* pool, Profile& profile)
    : particles_(particles), material_(material), skinFraction_(skinFraction), pool_(pool), profile_(profile) {}

ContactSolver::~ContactSolver() = default;

void ContactSolver::initialize() {
  batchContactsCurrent_ = false;
  if (particles_.cell && !particles_.walls.empty()) {
    throw std::invalid_argument("a periodic cell has no walls: its particles meet each other's images instead");
  }
  // Polygon features are decided with Box2D's tolerances at the scale at which Box2D would
  // see the particles: about one unit (its tuning range).
  const std::vector<Polygon>& polygons = particles_.polygons;
  double meanPolygonRadius = 0;
  for (const Polygon& p : polygons) meanPolygonRadius += p.circumradius;
  const double scale = polygons.empty() ? 1.0 : polygons.size() / meanPolygonRadius;
  polygonCollider_ = std::make_unique<PolygonCollider>(scale);
  for (const Polygon& p : polygons) polygonCollider_->add(p);
  double meanRadius = 0;
  for (double r : particles_.boundingRadius) meanRadius += r;
  const int n = particles_.size();
  // In a periodic cell a rebuild wraps the positions into the cell (a rounding): the skin sets
  // when that happens, so it is part of a cell's results and stays the one they were made with.
  constexpr double kCellSkinFraction = 0.3;
  skin_ = n ? (particles_.cell ? kCellSkinFraction : skinFraction_) * meanRadius / n : 0.0;
  writeBackWideState();
  neighbors_.invalidate();
}

bool ContactSolver::movedOutOfSkin(int begin, int end) const {
  return neighbors_.outdated(particles_.position, begin, end, simdPath() == SimdPath::Wide);
}

void ContactSolver::clearTangentialHistory() {
  writeBackWideState();
  for (PairState& p : neighbors_.pairs()) p.history.tangential = 0;
  discBatchStale_ = true;
}

void ContactSolver::setPool(WorkerPool* pool) {
  writeBackWideState();  // the disc batch is planned per thread: its state goes back to the list first
  pool_ = pool;
  discBatchStale_ = true;
  pairSlots_.markStale();  // the slots are laid out per thread
  deferredSlotsStale_ = true;
}

void ContactSolver::writeBackWideState() const {
  if (!wideStateAhead_) return;
  // The pairs' state is part of this solver's value: the batch only held it for the wide path.
  discBatch_.writeBack(const_cast<NeighborList&>(neighbors_).pairs());
  wideStateAhead_ = false;
}

// The contact between the two members of a pair, whatever their shapes. A pair involving a
// polygon goes through its kept features (PolygonCollider), which `cache` keeps; `guards` says
// which decisions a polygon-disc pair's slack guards (the wide path: the choices alone).
ContactGeometry ContactSolver::pairGeometry(const PairState& p, CachedContact* cache, const Vec2* shift,
                                            SlackGuards guards) const {
  const int i = p.i, j = p.j;
  const auto& x = particles_.position;
  const auto& radius = particles_.boundingRadius;
  const auto& shape = particles_.shape;
  const auto& cosA = particles_.cosAngle;
  const auto& sinA = particles_.sinAngle;
  if (j < 0) {
    const Wall& wall = particles_.walls[static_cast<size_t>(-1 - j)];
    return shape[i] == ShapeKind::Disc ? collideDiscWall(x[i], radius[i], wall)
                                       : collidePolygonWall(particles_.polygonOf(i), x[i], cosA[i], sinA[i], wall);
  }
  const bool iDisc = shape[i] == ShapeKind::Disc, jDisc = shape[j] == ShapeKind::Disc;
  const Vec2 xj = shift ? Vec2(x[j] + *shift) : x[j];  // j, or its image in a periodic cell
  if (iDisc && jDisc) return collideDiscs(x[i], radius[i], xj, radius[j]);
  const double reach = radius[i] + radius[j];
  if ((xj - x[i]).squaredNorm() >= reach * reach) {
    if (cache) cache->kind = CachedContact::Kind::None;  // bounding circles apart
    return {};
  }
  const Pose pi{x[i], cosA[i], sinA[i]}, pj{xj, cosA[j], sinA[j]};
  const int si = particles_.shapeIndex[i], sj = particles_.shapeIndex[j];
  if (!iDisc && !jDisc) return polygonCollider_->collidePolygons(si, pi, sj, pj, cache);
  if (!iDisc) return polygonCollider_->collidePolygonDisc(si, pi, xj, radius[j], cache, guards);
  ContactGeometry g = polygonCollider_->collidePolygonDisc(sj, pj, x[i], radius[i], cache, guards);
  g.normal = -g.normal;
  return g;
}

// The force of a touching pair with geometry g: F on j from i (−F on i), and the torques it
// exerts about each centroid. Updates the pair's history and last forces.
template <bool kPeriodic, class Law>
inline void ContactSolver::contactForce(PairState& p, const ContactGeometry& g, const Law& law, double dt, Vec2& F,
                                        double& ti, double& tj) const {
  const int i = p.i, j = p.j;
  const Vec2* x = particles_.position.data();
  const Vec2* v = particles_.velocity.data();
  const double* w = particles_.spin.data();
  const Vec2& n = g.normal;
  const Vec2 t = perp(n);
  const Vec2 ri = g.point - x[i];
  Vec2 dv = -(v[i] + cross(w[i], ri));
  Vec2 rj = Vec2::Zero();
  if (j >= 0) {
    if constexpr (kPeriodic) {
      // j's image: its lever from the image's centre, its velocity with the image's affine part.
      const size_t k = static_cast<size_t>(&p - neighbors_.pairs().data());
      rj = g.point - (x[j] + imageShift(k));
      dv += v[j] + cross(w[j], rj) + affineRelativeVelocity(p, k);
    } else {
      rj = g.point - x[j];
      dv += v[j] + cross(w[j], rj);
    }
  }
  F = lawForce(p, ContactMotion{g.overlap, dv.dot(n), dv.dot(t)}, n, t, law, dt);
  ti = cross(ri, F);
  tj = cross(rj, F);
}

// The same force for a disc contact, with the lever vectors folded in: r_i = armI·n and
// r_j = −armJ·n, so ω × r adds −(ω_i armI + ω_j armJ) to the tangential relative velocity and
// nothing to the normal one, and r × F is armI·f_t and −armJ·f_t. The exact values of the
// terms the general form rounds (a normal force's torque about a disc's centre is zero), in
// about half its operations.
template <bool kPeriodic, class Law>
inline void ContactSolver::contactForce(PairState& p, const DiscContact& c, const Law& law, double dt, Vec2& F,
                                        double& ti, double& tj) const {
  const int i = p.i, j = p.j;
  const Vec2* v = particles_.velocity.data();
  const double* w = particles_.spin.data();
  const Vec2& n = c.normal;
  const Vec2 t = perp(n);
  Vec2 dv = -v[i];
  double spin = w[i] * c.armI;
  if (j >= 0) {
    dv += v[j];
    spin += w[j] * c.armJ;
    if constexpr (kPeriodic) dv += affineRelativeVelocity(p, static_cast<size_t>(&p - neighbors_.pairs().data()));
  }
  ContactMotion m{c.overlap, dv.dot(n), dv.dot(t) - spin};
  F = lawForce(p, m, n, t, law, dt);
  ti = c.armI * p.ft;
  tj = -c.armJ * p.ft;
  if constexpr (decltype(law.rolling)::kKeepsHistory) {
    // The rolling couple on j, and its opposite on i (the loop subtracts ti from i's torque).
    m.spin = (j >= 0 ? w[j] : 0.0) - w[i];
    const RollingResistance::Pair& constants = rollingPairs_[static_cast<size_t>(&p - neighbors_.pairs().data())];
    const double couple = law.rolling.couple(p.fn, m, constants, dt, p.history.rolling);
    ti += couple;
    tj += couple;
  }
}

// Calls force(k, g) for each touching pair k in [begin, end), in pair order, and apart(k) for
// each other one (after clearing its state), in two passes: every touching pair's geometry
// into scratch, then the forces. A contact's force hangs on a long chain of dependent
// operations (for discs a square root and a division, for polygons the clipping's division),
// and whether a pair touches is a branch the processor cannot predict; in one pass the core
// overlapped only about two pairs' chains. Split, each chain is half as long and more pairs are
// in flight: a settled disc pile's step got 1.2-1.3x faster, a polygon pile's about 1.1x
// (measured together with the one-division clipping), with bit-identical results.
template <bool kDiscsOnly, bool kPeriodic, class Force, class Apart>
inline void ContactSolver::forEachTouching(int begin, int end, Force&& force, Apart&& apart) {
  PairState* pairs = neighbors_.pairs().data();
  int n = 0;
  if constexpr (kDiscsOnly) {
    TouchingDiscs* scratch = touchingDiscs_.data() + begin;  // this range's own part
    const Vec2* x = particles_.position.data();
    const double* radius = particles_.boundingRadius.data();
    const Wall* walls = particles_.walls.data();
    for (int k = begin; k < end; ++k) {
      PairState& p = pairs[k];
      DiscContact c;
      if constexpr (kPeriodic) c = touchDiscs(x[p.i], radius[p.i], x[p.j] + imageShift(static_cast<size_t>(k)), radius[p.j]);
      else c = p.j >= 0 ? touchDiscs(x[p.i], radius[p.i], x[p.j], radius[p.j])
                        : touchDiscWall(x[p.i], radius[p.i], walls[-1 - p.j]);
      if (c.overlap <= 0) {
        clearContact(p);
        apart(k);
        continue;
      }
      scratch[n].contact = c;
      scratch[n].pair = k;
      ++n;
    }
    for (int e = 0; e < n; ++e) force(scratch[e].pair, scratch[e].contact);
  } else if (widePolygons_) {
    if constexpr (kPeriodic) forEachTouchingInCell(begin, end, force, apart);
    else forEachTouchingKept(begin, end, force, apart);
  } else {
    TouchingShapes* scratch = touchingShapes_.data() + begin;
    for (int k = begin; k < end; ++k) {
      ContactGeometry g;
      if constexpr (kPeriodic) {
        const Vec2 shift = imageShift(static_cast<size_t>(k));
        g = pairGeometry(pairs[k], &polygonCache_[static_cast<size_t>(k)], &shift);
      } else {
        g = pairGeometry(pairs[k], &polygonCache_[static_cast<size_t>(k)]);
      }
      if (g.overlap <= 0) {
        clearContact(pairs[k]);
        apart(k);
        continue;
      }
      scratch[n].contact = g;
      scratch[n].pair = k;
      ++n;
    }
    for (int e = 0; e < n; ++e) force(scratch[e].pair, scratch[e].contact);
  }
}

// The wide path's first pass over pair k: Face where its kept features are a face against an
// edge (searched again if they no longer hold), with what the batch needs of it in `found`.
// Otherwise its contact is written to the batch (the scalar narrow phase's answer for a pair
// with a disc or a wall at an end, no overlap for one that does not touch), and the answer is
// Apart where a polygon pair's features say so (`found` then holds the pair too), else Other.
template <bool kPeriodic>
[[gnu::always_inline]] inline ContactSolver::WideAnswer ContactSolver::decideWidePair(int k, WidePolygonPair& found) {
  const PairState& p = neighbors_.pairs()[static_cast<size_t>(k)];
  CachedContact& cache = polygonCache_[static_cast<size_t>(k)];
  const ShapeKind* shape = particles_.shape.data();
  const int i = p.i, j = p.j;
  Vec2 shift = Vec2::Zero();
  if constexpr (kPeriodic) shift = imageShift(static_cast<size_t>(k));
  if (j < 0 || shape[i] == ShapeKind::Disc || shape[j] == ShapeKind::Disc) {
    polygonBatch_.contact(k) = pairGeometry(p, &cache, kPeriodic ? &shift : nullptr, SlackGuards::FeatureChoices);
    return WideAnswer::Other;
  }
  const Vec2* x = particles_.position.data();
  const double* radius = particles_.boundingRadius.data();
  const Vec2 xj = kPeriodic ? Vec2(x[j] + shift) : x[j];
  const double reach = radius[i] + radius[j];
  if ((xj - x[i]).squaredNorm() >= reach * reach) {  // bounding circles apart
    cache.kind = CachedContact::Kind::None;
    polygonBatch_.contact(k).overlap = -1;
    return WideAnswer::Other;
  }
  found.i = i;
  found.j = j;
  found.reach = reach;
  found.pi = {x[i], particles_.cosAngle[i], particles_.sinAngle[i]};
  found.pj = {xj, particles_.cosAngle[j], particles_.sinAngle[j]};
  found.si = particles_.shapeIndex[i];
  found.sj = particles_.shapeIndex[j];
  if (polygonCollider_->keepPolygonFeatures(found.si, found.pi, found.sj, found.pj, cache)) return WideAnswer::Face;
  polygonBatch_.contact(k).overlap = -1;
  return WideAnswer::Apart;
}

// The wide path with polygons outside a periodic cell. Polygon pairs keep their slots from
// step to step while their features say the same (polygon_pair_slots.hpp): the hold kernel
// tests every kept slot at once, and the first pass (decideWidePair) runs only for the slots
// that fail and for the pairs in no slot. The batch measures the face slots and applies the
// law (to contactForce's bits); the forces follow in pair order, every other pair's from its
// contact. The same decisions, measures and calls in the same order as forEachTouching, so the
// same bits.
template <class Force, class Apart>
void ContactSolver::forEachTouchingKept(int begin, int end, Force&& force, Apart&& apart) {
  PairState* pairs = neighbors_.pairs().data();
  PolygonFaceBatch& batch = polygonBatch_;
  PolygonPairSlots& slots = pairSlots_;
  PolygonPairSlots::Range& range = slots.range(begin, end);
  const PolygonCollider& collider = *polygonCollider_;
  // A pair just decided: into a slot of its kind (`slot`, or the range's next), or the others.
  auto place = [&](int k, WideAnswer answer, const WidePolygonPair& found, int slot) {
    const CachedContact& c = polygonCache_[static_cast<size_t>(k)];
    if (answer == WideAnswer::Face) {
      slots.fillFace(batch, slot >= 0 ? slot : range.begin + range.faces++, k, c, found.i, found.j, found.reach,
                     found.si, found.pi, found.sj, found.pj, collider);
    } else if (answer == WideAnswer::Apart) {
      slots.fillApart(slot >= 0 ? slot : range.begin + range.aparts++, k, c, found.i, found.j, found.reach);
    }
  };
  // The kept slots: the face slots' poses, and which slots no longer hold.
  const PolygonHoldInput::Particles now{particles_.position.data()->data(), particles_.cosAngle.data(),
                                        particles_.sinAngle.data()};
  std::int32_t* failedFaces = slots.failedFaces(range);
  std::int32_t* failedAparts = slots.failedAparts(range);
  const int faceFailures = holdPolygonSlots(slots.faceHoldInput(batch, range, now), range.faces, failedFaces);
  const int apartFailures = holdPolygonSlots(slots.apartHoldInput(range, now), range.aparts, failedAparts);
  // The other pairs; those now a face against an edge or kept apart take a slot.
  int* others = slots.others(range);
  int stay = 0;
  for (int o = 0; o < range.others; ++o) {
    const int k = others[o];
    WidePolygonPair found;
    const WideAnswer answer = decideWidePair<false>(k, found);
    if (answer == WideAnswer::Other) {
      others[stay++] = k;
      continue;
    }
    place(k, answer, found, -1);
  }
  range.others = stay;
  // The slots that failed, each kind from its last (a removed slot takes the range's last one
  // of its kind, which has then been decided already): each pair is decided again, and keeps
  // its slot if its answer is the same kind (`kind`); otherwise `leave` takes it out.
  auto decideAgain = [&](int slot, int k, WideAnswer kind, auto&& leave) {
    WidePolygonPair found;
    const WideAnswer answer = decideWidePair<false>(k, found);
    if (answer == kind) {
      place(k, answer, found, slot);
      return;
    }
    leave();
    if (answer == WideAnswer::Other) others[range.others++] = k;
    else place(k, answer, found, -1);
  };
  for (int f = apartFailures - 1; f >= 0; --f) {
    const int slot = range.begin + failedAparts[f];
    decideAgain(slot, slots.apartPair(slot), WideAnswer::Apart, [&] { slots.removeApart(range, slot); });
  }
  for (int f = faceFailures - 1; f >= 0; --f) {
    const int slot = range.begin + failedFaces[f];
    decideAgain(slot, batch.pairOf(slot), WideAnswer::Face, [&] { slots.removeFace(batch, range, slot); });
  }
  batch.measureForces(collider, polygonLaw_, particles_.velocity.data()->data(), particles_.spin.data(), pairs,
                      range.begin, range.faces);
  for (int k = begin; k < end; ++k) {
    const int s = slots.slotOf(k);
    if (s >= 0 && batch.touches(s)) {
      force(k, PolygonFaceForce{batch.force(s), batch.torqueI(s), batch.torqueJ(s)});
      continue;
    }
    // Not `overlap > 0`: a NaN overlap goes on to the force, as forEachTouching's test lets
    // it, so that the health check stops the run instead of the pair passing for apart.
    if (s == PolygonPairSlots::kOther) {
      if (const ContactGeometry& g = batch.contact(k); !(g.overlap <= 0)) {
        force(k, g);
        continue;
      }
    }
    clearContact(pairs[k]);
    apart(k);
  }
}

// The wide path's forEachTouching in a periodic cell: the polygon pairs whose kept features
// are a face against an edge are measured in a batch (polygon_face_batch.hpp), to
// measurePolygons' bits; every other pair as pairGeometry measures it. The law is the scalar
// one (the batch knows no images). The same calls in the same order as forEachTouching, so the
// same bits.
template <class Force, class Apart>
void ContactSolver::forEachTouchingInCell(int begin, int end, Force&& force, Apart&& apart) {
  PairState* pairs = neighbors_.pairs().data();
  PolygonFaceBatch& batch = polygonBatch_;
  // In chunks, so that a chunk's shape records (fetched ahead by add()) and contacts are still
  // in cache when the kernel and the forces read them.
  constexpr int kChunk = 128;
  for (int first = begin; first < end; first += kChunk) {
    const int last = std::min(end, first + kChunk);
    int slot = first;  // this chunk's slots
    for (int k = first; k < last; ++k) {
      WidePolygonPair found;
      if (decideWidePair<true>(k, found) != WideAnswer::Face) continue;
      batch.add(slot++, k, polygonCache_[static_cast<size_t>(k)], found.si, found.pi, found.sj, found.pj,
                *polygonCollider_);
    }
    batch.measure(*polygonCollider_, first, slot - first);
    for (int k = first; k < last; ++k) {
      const ContactGeometry& g = batch.contact(k);
      if (g.overlap <= 0) {
        clearContact(pairs[k]);
        apart(k);
        continue;
      }
      force(k, g);
    }
  }
}

// One thread, or several each on a contiguous slice of the pairs. A particle's shares from
// the slice holding its first pair are added at once, in pair order; shares computed in later
// slices wait in their slots (assignDeferredSlots) and are added after the loop, in pair order.
// Every particle sees the same additions in the same order whatever the number of threads, so
// the result is bit-identical. With one thread there are no slots: every share is added at
// once. In a scene whose particle indices follow space, almost nothing waits.
template <class Law, bool kDiscsOnly, bool kPeriodic>
void ContactSolver::pairForces(const Law& law, double dt) {
  if (pool_ && deferredSlotsStale_) {
    assignDeferredSlots();
    deferredSlotsStale_ = false;
  }
  std::vector<PairState>& pairs = neighbors_.pairs();
  if constexpr (!kDiscsOnly && !kPeriodic) {
    if (widePolygons_ && pairSlots_.stale()) {
      // One range of slots per thread's slice of the pairs, as parallelFor slices them.
      const int slices = pool_ ? pool_->threads() : 1, count = static_cast<int>(pairs.size());
      std::vector<int> begins(static_cast<size_t>(slices));
      for (int t = 0; t < slices; ++t) begins[static_cast<size_t>(t)] = WorkerPool::sliceBegin(count, t, slices);
      pairSlots_.reset(count, begins);
    }
  }
  if constexpr (kDiscsOnly) touchingDiscs_.resize(pairs.size());
  else touchingShapes_.resize(pairs.size());
  Vec2* f = particles_.force.data();
  double* tau = particles_.torque.data();
  const int* slot = pool_ ? deferredSlot_.data() : nullptr;
  DeferredForce* deferred = deferred_.data();
  // `threaded` is std::true_type when slices may share particles: one thread's loop then
  // carries no test for slots at all.
  auto pairRange = [&](auto threaded, int begin, int end) {
    constexpr bool kThreaded = decltype(threaded)::value;
    forEachTouching<kDiscsOnly, kPeriodic>(begin, end, [&](int k, const auto& g) {
      PairState& p = pairs[static_cast<size_t>(k)];
      Vec2 F;
      double ti, tj;
      contactForce<kPeriodic>(p, g, law, dt, F, ti, tj);
      // x − y and x + (−y) are the same IEEE operation: a waiting share is stored negated.
      if (const int s = kThreaded ? slot[2 * k] : -1; s < 0) {
        f[p.i] -= F;
        tau[p.i] -= ti;
      } else {
        deferred[s] = {-F, -ti, true};
      }
      if (p.j < 0) return;
      if (const int s = kThreaded ? slot[2 * k + 1] : -1; s < 0) {
        f[p.j] += F;
        tau[p.j] += tj;
      } else {
        deferred[s] = {F, tj, true};
      }
    }, [&](int k) {
      if constexpr (kThreaded) {
        if (const int s = slot[2 * k]; s >= 0) deferred[s].touching = false;
        if (const int s = slot[2 * k + 1]; s >= 0) deferred[s].touching = false;
      }
    });
  };
  const int pairCount = static_cast<int>(pairs.size());
  if (pool_) pool_->parallelFor(pairCount, [&](int begin, int end) { pairRange(std::true_type{}, begin, end); });
  else pairRange(std::false_type{}, 0, pairCount);
  // The waiting shares, then each particle's local damping (both are the end of a particle's
  // force; the same range of particles, in cache, on the same thread).
  if (deferred_.empty() && material_.localDamping == 0) return;
  auto finish = [&](int begin, int end) {
    if (slot) {
      for (int k = begin; k < end; ++k) {
        for (int s = deferredStart_[k]; s < deferredStart_[k + 1]; ++s) {
          const DeferredForce& d = deferred[s];
          if (!d.touching) continue;
          f[k] += d.force;
          tau[k] += d.torque;
        }
      }
    }
    if (material_.localDamping > 0) applyLocalDamping(particles_, begin, end, material_.localDamping, widePolygons_);
  };
  if (pool_) pool_->parallelFor(particles_.size(), finish);
  else finish(0, particles_.size());
}

template <class Law>
void ContactSolver::widePairForces(const Law& law, double dt) {
  if (discBatchStale_) {
    discBatch_.build(neighbors_, particles_.size(), material_.rollingFriction > 0 ? &rollingPairs_ : nullptr,
                     particles_.cell.has_value(), pool_ ? pool_->threads() : 1);
    discBatch_.layRadii(particles_.boundingRadius.data());
    discBatchStale_ = false;
  }
  DiscPairBatch& b = discBatch_;
  std::vector<PairState>& pairs = neighbors_.pairs();
  Vec2* f = particles_.force.data();
  double* tau = particles_.torque.data();
  // Each thread adds the shares of the particles it owns at once; the others' wait in records
  // (disc_pair_batch.hpp), added after the loop.
  DiscPairKernelInput in{
      particles_.position.data()->data(), particles_.velocity.data()->data(), particles_.spin.data(),
      particles_.boundingRadius.data(), b.i(), b.j(), b.dampN(), b.dampT(), b.history(), b.fn(), b.ft(),
      b.overlap(), material_.normalStiffness, material_.tangentialStiffness, material_.friction, dt,
      std::is_same_v<decltype(law.tangential), CundallStrack>, f->data(), tau, b.ends(), b.iEnd(), b.jEnd(),
      b.blockDefers()};
  in.radiusI = b.radiusI();
  in.radiusJ = b.radiusJ();
  if (b.rolls()) {  // rolling resistance: the couple's lanes (the walls' couples are the scalar law's, below)
    in.rollingHistory = b.rollingHistory();
    in.rollingStiffness = b.rollingStiffness();
    in.rollingCompliance = b.rollingCompliance();
    in.rollingCapPerForce = b.rollingCapPerForce();
    in.rollingDamping = b.rollingDamping();
  }
  if (particles_.cell) setWideCell(in);
  wideStateAhead_ = true;
  const int blocks = b.blocks();
  const int wallPairs = static_cast<int>(b.wallPairs().size());
  // Work items: the blocks of disc-disc slots, then the disc-wall pairs (scalar, as the
  // baseline) in groups, as DiscPairBatch planned the records for.
  auto work = [&](int begin, int end) {
    if (const int last = std::min(end, blocks); begin < last) discPairForces(in, begin * kDiscPairBlock, last * kDiscPairBlock);
    const Vec2* x = particles_.position.data();
    const double* radius = particles_.boundingRadius.data();
    const int first = (std::max(begin, blocks) - blocks) * DiscPairBatch::kWallPairsPerItem;
    const int stop = std::min(wallPairs, (end - blocks) * DiscPairBatch::kWallPairsPerItem);
    for (int w = first; w < stop; ++w) {
      PairState& p = pairs[static_cast<size_t>(b.wallPairs()[static_cast<size_t>(w)])];
      const std::int32_t record = b.wallEnd(w);
      const DiscContact c = touchDiscWall(x[p.i], radius[p.i], particles_.walls[static_cast<size_t>(-1 - p.j)]);
      if (c.overlap <= 0) {
        clearContact(p);
        if (record >= 0) b.setRecord(record, -0.0, -0.0, -0.0);
        continue;
      }
      Vec2 F;
      double ti, tj;
      contactForce<false>(p, c, law, dt, F, ti, tj);
      if (record < 0) {
        f[p.i] -= F;
        tau[p.i] -= ti;
      } else {
        b.setRecord(record, -F.x(), -F.y(), -ti);
      }
    }
  };
  if (pool_) pool_->parallelFor(b.workItems(), work);
  else work(0, b.workItems());
  // The shares that waited, in order, then each particle's local damping.
  b.addDeferred(f, tau);
  if (material_.localDamping > 0) {
    auto damp = [&](int begin, int end) {
      applyLocalDamping(particles_, begin, end, material_.localDamping, true);
    };
    if (pool_) pool_->parallelFor(particles_.size(), damp);
    else damp(0, particles_.size());
  }
}

// Which pair ends the parallel force loop adds at once and which wait, for the current pair
// list and number of threads. Particle k belongs to the slice holding its first pair; a share
// computed in any other slice (a later one: pairs are in order) gets a slot.
void ContactSolver::assignDeferredSlots() {
  const int pairCount = static_cast<int>(neighbors_.pairs().size());
  const int threads = pool_->threads();
  const int n = particles_.size();
  const std::vector<int>& start = neighbors_.adjacencyStart();
  const std::vector<int>& entries = neighbors_.adjacency();
  std::vector<int> sliceEnd(static_cast<size_t>(threads));
  for (int t = 0; t < threads; ++t) sliceEnd[static_cast<size_t>(t)] = WorkerPool::sliceBegin(pairCount, t + 1, threads);
  auto sliceOf = [&](int pair) {
    return static_cast<int>(std::upper_bound(sliceEnd.begin(), sliceEnd.end(), pair) - sliceEnd.begin());
  };
  deferredSlot_.assign(2 * static_cast<size_t>(pairCount), -1);
  deferredStart_.assign(static_cast<size_t>(n) + 1, 0);
  int slots = 0;
  for (int k = 0; k < n; ++k) {
    deferredStart_[k] = slots;
    if (start[k] == start[k + 1]) continue;
    const int owner = sliceOf(entries[static_cast<size_t>(start[k])] >> 1);
    for (int e = start[k]; e < start[k + 1]; ++e) {
      const int pairEnd = entries[static_cast<size_t>(e)];  // pair × 2, + 1 where k is its j
      if (sliceOf(pairEnd >> 1) != owner) deferredSlot_[static_cast<size_t>(pairEnd)] = slots++;
    }
  }
  deferredStart_[n] = slots;
  deferred_.assign(static_cast<size_t>(slots), DeferredForce{});
}

void ContactSolver::assignDamping() {
  const double zeta = dampingRatio(material_.restitution);
  const double kn = material_.normalStiffness, kt = material_.tangentialStiffness;
  const std::vector<double>& mass = particles_.mass;
  const std::vector<Motion>& motion = particles_.motion;
  for (PairState& p : neighbors_.pairs()) {
    // Effective mass of the pair: against a wall or an immovable particle, the particle's own.
    const double mi = mass[p.i];
    double m = mi;
    if (p.j >= 0 && motion[p.j] == Motion::Dynamic && motion[p.i] == Motion::Dynamic) {
      m = mi * mass[p.j] / (mi + mass[p.j]);
    } else if (p.j >= 0 && motion[p.i] != Motion::Dynamic) {
      m = mass[p.j];
    }
    p.dampN = 2 * zeta * std::sqrt(m * kn);
    p.dampT = 2 * zeta * std::sqrt(m * kt);
  }
}

// Each pair's rolling constants (rolling_resistance.hpp), from its particles: the effective
// radius, and the inertia for relative rolling about the contact (a wall's or a fixed
// particle's term drops out). Like the damping, they follow the pair list.
void ContactSolver::assignRollingPairs() {
  const RollingResistance model = rollingModel(material_);
  const std::vector<double>& radius = particles_.boundingRadius;
  const std::vector<double>& mass = particles_.mass;
  const std::vector<double>& inertia = particles_.inertia;
  const std::vector<Motion>& motion = particles_.motion;
  auto inverseInertia = [&](int k) {
    return motion[k] == Motion::Dynamic ? 1 / (inertia[k] + mass[k] * radius[k] * radius[k]) : 0.0;
  };
  const std::vector<PairState>& pairs = neighbors_.pairs();
  rollingPairs_.resize(pairs.size());
  for (size_t k = 0; k < pairs.size(); ++k) {
    const PairState& p = pairs[k];
    const double ri = radius[p.i];
    const double effective = p.j >= 0 ? ri * radius[p.j] / (ri + radius[p.j]) : ri;
    const double inverse = inverseInertia(p.i) + (p.j >= 0 ? inverseInertia(p.j) : 0.0);
    rollingPairs_[k] = model.pair(effective, inverse > 0 ? 1 / inverse : 0.0);
  }
}

void ContactSolver::carryPolygonCache() {
  const std::vector<int>& from = neighbors_.carriedFrom();
  std::vector<CachedContact> carried(from.size());
  for (size_t k = 0; k < from.size(); ++k) {
    if (from[k] >= 0 && static_cast<size_t>(from[k]) < polygonCache_.size()) carried[k] = polygonCache_[static_cast<size_t>(from[k])];
  }
  polygonCache_.swap(carried);
}

void ContactSolver::computeForces(double dt, bool moved) {
  auto t0 = Clock::now();
  // The wide kernel knows the linear spring-dashpot with Coulomb friction or none, and rolling
  // resistance (whose relative rotation it keeps, in a frictionless stage too), and a periodic
  // cell's images.
  const bool periodic = particles_.cell.has_value();
  const bool wide = particles_.polygons.empty() && simdPath() == SimdPath::Wide;
  // The pairs' state goes back to the list when the baseline reads it or a rebuild carries it
  // over; after a baseline step the batch reloads it.
  if (!wide || moved) writeBackWideState();
  if (!wide) discBatchStale_ = true;
  const bool rebuilt = periodic ? updatePeriodicNeighbors(moved)
                                : neighbors_.update(particles_.position, particles_.boundingRadius, particles_.motion,
                                                    particles_.walls, skin_, moved);
  const bool polygons = !particles_.polygons.empty();
  widePolygons_ = polygons && simdPath() == SimdPath::Wide;
  // The kept slots follow the pair list and the features: a rebuild or a step on the
  // baseline path (which searches with other guards) drops them.
  if (rebuilt || !widePolygons_) pairSlots_.markStale();
  if (widePolygons_) {
    polygonBatch_.resize(neighbors_.pairs().size());
    polygonLaw_ = {material_.normalStiffness, material_.tangentialStiffness, material_.friction, dt,
                   material_.friction != 0};
  }
  if (rebuilt) {
    assignDamping();
    if (material_.rollingFriction > 0) assignRollingPairs();
    if (polygons) carryPolygonCache();
    ++profile_.rebuilds;
    deferredSlotsStale_ = true;  // the baseline's slots follow the pair list (assigned when it runs)
    discBatchStale_ = true;
  }
  auto t1 = Clock::now();
  // One instantiation of the pair loop per law and geometry: a discs-only scene runs no
  // polygon code, a frictionless one keeps no tangential history (nor rolling resistance: a
  // frictionless stage is frictionless throughout), and only discs roll with resistance.
  const LinearSpringDashpot normal{material_.normalStiffness};
  if (material_.rollingFriction > 0 && material_.friction > 0 && !polygons) {
    const RollingLaw law{normal, {material_.tangentialStiffness, material_.friction}, rollingModel(material_)};
    if (wide) widePairForces(law, dt);
    else if (periodic) pairForces<RollingLaw, true, true>(law, dt);
    else pairForces<RollingLaw, true>(law, dt);
  } else if (material_.friction == 0) {
    const ContactLaw<LinearSpringDashpot, Frictionless> law{normal, {}};
    if (wide) widePairForces(law, dt);
    else if (periodic) polygons ? pairForces<decltype(law), false, true>(law, dt) : pairForces<decltype(law), true, true>(law, dt);
    else polygons ? pairForces<decltype(law), false>(law, dt) : pairForces<decltype(law), true>(law, dt);
  } else {
    const ContactLaw<LinearSpringDashpot, CundallStrack> law{
        normal, {material_.tangentialStiffness, material_.friction}};
    if (wide) widePairForces(law, dt);
    else if (periodic) polygons ? pairForces<decltype(law), false, true>(law, dt) : pairForces<decltype(law), true, true>(law, dt);
    else polygons ? pairForces<decltype(law), false>(law, dt) : pairForces<decltype(law), true>(law, dt);
  }
  batchContactsCurrent_ = widePolygons_;
  auto t2 = Clock::now();
  profile_.neighbors += seconds(t0, t1);
  profile_.forces += seconds(t1, t2);
  if (polygonCollider_) profile_.featureSearches = polygonCollider_->featureSearches();
}

void ContactSolver::contacts(std::vector<ContactRecord>& out) const {
  writeBackWideState();
  const std::vector<PairState>& pairs = neighbors_.pairs();
  for (size_t k = 0; k < pairs.size(); ++k) {
    const PairState& p = pairs[k];
    if (p.overlap <= 0) continue;
    // The cached answer as the forces saw it (positions have not moved since).
    CachedContact cache = k < polygonCache_.size() ? polygonCache_[k] : CachedContact{};
    const Vec2 shift = particles_.cell ? imageShift(k) : Vec2::Zero();
    const ContactGeometry g = pairGeometry(p, &cache, particles_.cell ? &shift : nullptr);
    ContactRecord c;
    c.i = p.i;
    c.j = p.j;
    c.point = g.point;
    c.normal = g.normal;
    c.fn = p.fn;
    c.ft = p.ft;
    c.overlap = p.overlap;
    out.push_back(c);
  }
}

void ContactSolver::countContacts(std::vector<int>& count) const {
  writeBackWideState();
  count.assign(static_cast<size_t>(particles_.size()), 0);
  for (const PairState& p : neighbors_.pairs()) {
    if (p.overlap <= 0) continue;
    ++count[static_cast<size_t>(p.i)];
    if (p.j >= 0) ++count[static_cast<size_t>(p.j)];
  }
}

double ContactSolver::elasticEnergy() const {
  writeBackWideState();
  double e = 0;
  const LinearSpringDashpot normal{material_.normalStiffness};
  const CundallStrack tangential{material_.tangentialStiffness, material_.friction};
  const std::vector<PairState>& pairs = neighbors_.pairs();
  for (size_t k = 0; k < pairs.size(); ++k) {
    const PairState& p = pairs[k];
    if (p.overlap <= 0) continue;
    e += normal.energy(p.overlap) + tangential.energy(p.history.tangential);
    if (p.history.rolling != 0 && k < rollingPairs_.size()) e += RollingResistance::energy(rollingPairs_[k], p.history.rolling);
  }
  return e;
}

void ContactSolver::checkOverlaps(std::int64_t step, double dt, double criticalDt) const {
  writeBackWideState();
  const std::vector<double>& radius = particles_.boundingRadius;
  for (const PairState& p : neighbors_.pairs()) {
    if (p.overlap <= 0) continue;
    const double size = p.j >= 0 ? std::min(radius[p.i], radius[p.j]) : radius[p.i];
    if (p.overlap > 0.5 * size) throwRunawayOverlap(step, p.i, p.j, p.overlap / size, "particle", dt, criticalDt);
  }
}

void ContactSolver::persist(StateArchive& a) {
  a.section("contacts");
  if (a.loading()) batchContactsCurrent_ = false;
  writeBackWideState();
  neighbors_.persist(a, particles_.size(), static_cast<int>(particles_.walls.size()));
  if (particles_.cell) {
    neighbors_.persistShifts(a);
    a.bitwise(cellAtBuild_);
  }
  a.bitwise(polygonCache_);
  if (a.loading()) {
    // The polygon cache is read per pair, by index, and its features index a polygon's
    // corners: a cache that cannot have come from this world is refused.
    a.require(particles_.polygons.empty() || polygonCache_.size() == neighbors_.pairs().size(),
              "the polygon contact cache's length differs from the pair count");
    for (const CachedContact& c : polygonCache_) {
      a.require(c.kind <= CachedContact::Kind::VertexDisc && c.reference >= 0 && c.reference < kMaxPolygonVertices &&
                    c.incident >= 0 && c.incident < kMaxPolygonVertices,
                "a polygon contact cache entry is out of range");
    }
    if (polygonCollider_) polygonCollider_->setFeatureSearches(profile_.featureSearches);
    deferredSlotsStale_ = true;  // the slots follow the pair list
    pairSlots_.markStale();      // and so do the kept pair slots
    if (material_.rollingFriction > 0) assignRollingPairs();  // and so do the rolling constants
    discBatchStale_ = true;
  }
}

}  // namespace grainlab

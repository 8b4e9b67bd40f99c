#include "member_contacts.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <type_traits>

#include "contact_law.hpp"
#include "disc_pair_kernel.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/state_archive.hpp"
#include "local_damping.hpp"
#include "runaway_overlap.hpp"

namespace grainlab {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

MemberContactSolver::MemberContactSolver(ParticleStore& particles, const Material& material, double skinFraction,
                                         Profile& profile)
    : particles_(particles), material_(material), skinFraction_(skinFraction), profile_(profile) {}

void MemberContactSolver::initialize() {
  if (!particles_.polygons.empty()) {
    throw SimulationError("a scene with clumps cannot also have polygons: clumps' contacts are between discs");
  }
  owner_.clear();
  offset_.clear();
  radius_.clear();
  motion_.clear();
  for (int k = 0; k < particles_.size(); ++k) {
    auto add = [&](const Vec2& offset, double radius) {
      owner_.push_back(k);
      offset_.push_back(offset);
      radius_.push_back(radius);
      motion_.push_back(particles_.motion[k]);
    };
    if (particles_.shape[k] == ShapeKind::Clump) {
      for (const ClumpMember& m : particles_.clumpOf(k).members) add(m.centre, m.radius);
    } else {
      add(Vec2::Zero(), particles_.boundingRadius[k]);
    }
  }
  double meanRadius = 0;
  for (double r : radius_) meanRadius += r;
  skin_ = owner_.empty() ? 0.0 : skinFraction_ * meanRadius / static_cast<double>(owner_.size());
  lever_.assign(owner_.size(), Vec2::Zero());
  position_.assign(owner_.size(), Vec2::Zero());
  writeBackWideState();
  neighbors_.invalidate();
}

void MemberContactSolver::clearTangentialHistory() {
  writeBackWideState();
  for (PairState& p : neighbors_.pairs()) p.history.tangential = 0;
  batchStale_ = true;
}

void MemberContactSolver::writeBackWideState() const {
  if (!wideStateAhead_) return;
  // The pairs' state is part of this solver's value: the batch only held it for the wide path.
  batch_.writeBack(const_cast<NeighborList&>(neighbors_).pairs());
  wideStateAhead_ = false;
}

// Each member where its body now is. A lone disc's offset is zero, so its position is its
// body's to the bit (x + 0 = x).
void MemberContactSolver::placeMembers() {
  const Vec2* x = particles_.position.data();
  const double* c = particles_.cosAngle.data();
  const double* s = particles_.sinAngle.data();
  const int n = memberCount();
  for (int m = 0; m < n; ++m) {
    const int b = owner_[static_cast<size_t>(m)];
    const Vec2& o = offset_[static_cast<size_t>(m)];
    const Vec2 lever(c[b] * o.x() - s[b] * o.y(), s[b] * o.x() + c[b] * o.y());
    lever_[static_cast<size_t>(m)] = lever;
    position_[static_cast<size_t>(m)] = x[b] + lever;
  }
}

// As ContactSolver::assignDamping, with each member's body's mass.
void MemberContactSolver::assignDamping() {
  const double zeta = dampingRatio(material_.restitution);
  const double kn = material_.normalStiffness, kt = material_.tangentialStiffness;
  const std::vector<double>& mass = particles_.mass;
  for (PairState& p : neighbors_.pairs()) {
    const int bi = owner_[static_cast<size_t>(p.i)];
    const int bj = p.j >= 0 ? owner_[static_cast<size_t>(p.j)] : -1;
    const double mi = mass[bi];
    double m = mi;
    if (bj >= 0 && motion_[static_cast<size_t>(p.j)] == Motion::Dynamic && motion_[static_cast<size_t>(p.i)] == Motion::Dynamic) {
      m = mi * mass[bj] / (mi + mass[bj]);
    } else if (bj >= 0 && motion_[static_cast<size_t>(p.i)] != Motion::Dynamic) {
      m = mass[bj];
    }
    p.dampN = 2 * zeta * std::sqrt(m * kn);
    p.dampT = 2 * zeta * std::sqrt(m * kt);
  }
}

DiscContact MemberContactSolver::touch(const PairState& p) const {
  const size_t i = static_cast<size_t>(p.i);
  if (p.j < 0) return touchDiscWall(position_[i], radius_[i], particles_.walls[static_cast<size_t>(-1 - p.j)]);
  const size_t j = static_cast<size_t>(p.j);
  return touchDiscs(position_[i], radius_[i], position_[j], radius_[j]);
}

// The disc fast path's force (ContactSolver::contactForce for a DiscContact) with each
// member's lever from its body's centroid added: the lever is arm·n from the member's centre
// plus the member's offset, so ω × r and r × F gain the offset's terms. With a zero offset
// (a lone disc) those terms are zero and the result is the fast path's to the bit.
template <class Law>
inline void MemberContactSolver::pairForce(PairState& p, const DiscContact& c, const Law& law, double dt) {
  Vec2* f = particles_.force.data();
  double* tau = particles_.torque.data();
  const Vec2* v = particles_.velocity.data();
  const double* w = particles_.spin.data();
  const int a = owner_[static_cast<size_t>(p.i)];
  const Vec2& leverA = lever_[static_cast<size_t>(p.i)];
  const Vec2& n = c.normal;
  const Vec2 t = perp(n);
  Vec2 dv = -v[a];
  dv -= cross(w[a], leverA);
  double spin = w[a] * c.armI;
  int b = -1;
  Vec2 leverB = Vec2::Zero();
  if (p.j >= 0) {
    b = owner_[static_cast<size_t>(p.j)];
    leverB = lever_[static_cast<size_t>(p.j)];
    dv += v[b];
    dv += cross(w[b], leverB);
    spin += w[b] * c.armJ;
  }
  const ContactMotion m{c.overlap, dv.dot(n), dv.dot(t) - spin};
  p.fn = law.normal.force(m, p.dampN);
  p.ft = law.tangential.force(p.fn, m, p.dampT, dt, p.history.tangential);
  p.overlap = m.overlap;
  const Vec2 F = p.fn * n + p.ft * t;
  f[a] -= F;
  tau[a] -= c.armI * p.ft + cross(leverA, F);
  if (b < 0) return;
  f[b] += F;
  tau[b] += -c.armJ * p.ft + cross(leverB, F);
}

template <class Law>
void MemberContactSolver::pairForces(const Law& law, double dt) {
  for (PairState& p : neighbors_.pairs()) {
    const DiscContact c = touch(p);
    if (c.overlap <= 0) {
      p.history = {};
      p.fn = p.ft = p.overlap = 0;
      continue;
    }
    pairForce(p, c, law, dt);
  }
  if (material_.localDamping > 0) {
    applyLocalDamping(particles_, 0, particles_.size(), material_.localDamping, false);
  }
}

// The member-member pairs through the disc kernel with its member lanes, in slot (= pair)
// order, then the member-wall pairs in order, scalar.
template <class Law>
void MemberContactSolver::widePairForces(const Law& law, double dt) {
  if (batchStale_) {
    batch_.build(neighbors_.pairs(), owner_);
    batchStale_ = false;
  }
  MemberPairBatch& b = batch_;
  DiscPairKernelInput in{
      position_.data()->data(), particles_.velocity.data()->data(), particles_.spin.data(), radius_.data(), b.i(),
      b.j(), b.dampN(), b.dampT(), b.history(), b.fn(), b.ft(), b.overlap(), material_.normalStiffness,
      material_.tangentialStiffness, material_.friction, dt, std::is_same_v<decltype(law.tangential), CundallStrack>,
      particles_.force.data()->data(), particles_.torque.data(), nullptr, nullptr, nullptr};
  in.bodyI = b.bodyI();
  in.bodyJ = b.bodyJ();
  in.lever = lever_.data()->data();
  wideStateAhead_ = true;
  discPairForces(in, 0, b.paddedSlots());
  std::vector<PairState>& pairs = neighbors_.pairs();
  for (const int k : b.wallPairs()) {
    PairState& p = pairs[static_cast<size_t>(k)];
    const DiscContact c = touch(p);
    if (c.overlap <= 0) {
      p.history = {};
      p.fn = p.ft = p.overlap = 0;
      continue;
    }
    pairForce(p, c, law, dt);
  }
  if (material_.localDamping > 0) {
    applyLocalDamping(particles_, 0, particles_.size(), material_.localDamping, true);
  }
}

void MemberContactSolver::computeForces(double dt) {
  auto t0 = Clock::now();
  placeMembers();
  const bool wide = simdPath() == SimdPath::Wide;
  const bool moved = neighbors_.outdated(position_, 0, memberCount());
  // The pairs' state goes back to the list when the baseline reads it or a rebuild carries it over.
  if (!wide || moved) writeBackWideState();
  if (!wide) batchStale_ = true;
  if (neighbors_.update(position_, radius_, motion_, particles_.walls, skin_, moved)) {
    // A clump's own members never touch: their pairs are dropped as the list is built.
    std::vector<PairState>& pairs = neighbors_.pairs();
    std::erase_if(pairs, [&](const PairState& p) {
      return p.j >= 0 && owner_[static_cast<size_t>(p.i)] == owner_[static_cast<size_t>(p.j)];
    });
    assignDamping();
    ++profile_.rebuilds;
    batchStale_ = true;
  }
  auto t1 = Clock::now();
  const LinearSpringDashpot normal{material_.normalStiffness};
  if (material_.friction == 0) {
    const ContactLaw<LinearSpringDashpot, Frictionless> law{normal, {}};
    wide ? widePairForces(law, dt) : pairForces(law, dt);
  } else {
    const ContactLaw<LinearSpringDashpot, CundallStrack> law{normal, {material_.tangentialStiffness, material_.friction}};
    wide ? widePairForces(law, dt) : pairForces(law, dt);
  }
  auto t2 = Clock::now();
  profile_.neighbors += seconds(t0, t1);
  profile_.forces += seconds(t1, t2);
}

void MemberContactSolver::contacts(std::vector<ContactRecord>& out) const {
  writeBackWideState();
  for (const PairState& p : neighbors_.pairs()) {
    if (p.overlap <= 0) continue;
    const DiscContact c = touch(p);
    ContactRecord r;
    r.i = owner_[static_cast<size_t>(p.i)];
    r.j = p.j >= 0 ? owner_[static_cast<size_t>(p.j)] : p.j;
    r.point = position_[static_cast<size_t>(p.i)] + c.normal * c.armI;
    r.normal = c.normal;
    r.fn = p.fn;
    r.ft = p.ft;
    r.overlap = p.overlap;
    out.push_back(r);
  }
}

void MemberContactSolver::countContacts(std::vector<int>& count) const {
  writeBackWideState();
  count.assign(static_cast<size_t>(particles_.size()), 0);
  for (const PairState& p : neighbors_.pairs()) {
    if (p.overlap <= 0) continue;
    ++count[static_cast<size_t>(owner_[static_cast<size_t>(p.i)])];
    if (p.j >= 0) ++count[static_cast<size_t>(owner_[static_cast<size_t>(p.j)])];
  }
}

double MemberContactSolver::elasticEnergy() const {
  writeBackWideState();
  double e = 0;
  const LinearSpringDashpot normal{material_.normalStiffness};
  const CundallStrack tangential{material_.tangentialStiffness, material_.friction};
  for (const PairState& p : neighbors_.pairs()) {
    if (p.overlap <= 0) continue;
    e += normal.energy(p.overlap) + tangential.energy(p.history.tangential);
  }
  return e;
}

void MemberContactSolver::checkOverlaps(std::int64_t step, double dt, double criticalDt) const {
  writeBackWideState();
  for (const PairState& p : neighbors_.pairs()) {
    if (p.overlap <= 0) continue;
    const double size = p.j >= 0 ? std::min(radius_[static_cast<size_t>(p.i)], radius_[static_cast<size_t>(p.j)])
                                 : radius_[static_cast<size_t>(p.i)];
    if (p.overlap <= 0.5 * size) continue;
    const int j = p.j >= 0 ? owner_[static_cast<size_t>(p.j)] : p.j;
    throwRunawayOverlap(step, owner_[static_cast<size_t>(p.i)], j, p.overlap / size, "member disc", dt, criticalDt);
  }
}

void MemberContactSolver::persist(StateArchive& a) {
  a.section("member contacts");
  writeBackWideState();
  neighbors_.persist(a, memberCount(), static_cast<int>(particles_.walls.size()));
  if (a.loading()) {
    for (const PairState& p : neighbors_.pairs()) {
      a.require(p.j < 0 || owner_[static_cast<size_t>(p.i)] != owner_[static_cast<size_t>(p.j)],
                "a member pair inside one clump is in the neighbour list");
    }
    batchStale_ = true;
  }
}

}  // namespace grainlab

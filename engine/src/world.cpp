#include "grainlab/world.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "contact_geometry.hpp"
#include "contact_law.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/state_archive.hpp"
#include "neighbor_list.hpp"
#include "polygon_collider.hpp"
#include "rigid_body_solver.hpp"
#include "worker_pool.hpp"

namespace grainlab {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

World::World(const Material& material, WorldSettings settings)
    : material_(material), settings_(settings), neighbors_(std::make_unique<NeighborList>()) {
  if (settings_.threads < 1) throw std::invalid_argument("threads must be at least 1");
  if (settings_.threads > 1) pool_ = std::make_unique<WorkerPool>(settings_.threads);
}

World::~World() = default;

int World::addParticle(const ParticleSpec& spec) {
  const int index = size();
  Vec2 centre = spec.position;
  double area = 0, polar = 0, bounding = 0;
  int shapeIndex = -1;
  if (spec.shape == ShapeKind::Disc) {
    if (!(spec.radius > 0) || !std::isfinite(spec.radius)) {
      throw std::invalid_argument("disc radius must be positive and finite");
    }
    area = discArea(spec.radius);
    polar = 0.5 * area * spec.radius * spec.radius;
    bounding = spec.radius;
  } else {
    Vec2 centroid;
    Polygon poly = makePolygon(spec.vertices, &centroid);
    // Vertices are relative to `position` in the body frame turned by `angle`.
    centre = spec.position + rotate(centroid, spec.angle);
    area = poly.area;
    polar = poly.polarMoment;
    bounding = poly.circumradius;
    shapeIndex = static_cast<int>(polygons_.size());
    polygons_.push_back(poly);
  }
  const double mass = material_.density * area;
  const double inertia = material_.density * polar;
  const bool dynamic = spec.motion == Motion::Dynamic;
  const bool moving = spec.motion != Motion::Fixed;

  position_.push_back(centre);
  angle_.push_back(spec.angle);
  cos_.push_back(std::cos(spec.angle));
  sin_.push_back(std::sin(spec.angle));
  velocity_.push_back(moving ? spec.velocity : Vec2::Zero());
  spin_.push_back(moving ? spec.spin : 0.0);
  force_.push_back(Vec2::Zero());
  torque_.push_back(0.0);
  invMass_.push_back(dynamic ? 1.0 / mass : 0.0);
  invInertia_.push_back(dynamic ? 1.0 / inertia : 0.0);
  mass_.push_back(mass);
  inertia_.push_back(inertia);
  boundingRadius_.push_back(bounding);
  shape_.push_back(spec.shape);
  motion_.push_back(spec.motion);
  boundary_.push_back(spec.boundary ? 1 : 0);
  shapeIndex_.push_back(shapeIndex);
  prepared_ = false;
  return index;
}

int World::addWall(const Wall& wall) {
  Wall w = wall;
  const double len = w.normal.norm();
  if (!(len > 0) || !std::isfinite(len)) throw std::invalid_argument("wall normal must be non-zero");
  w.normal /= len;
  walls_.push_back(w);
  prepared_ = false;
  return static_cast<int>(walls_.size()) - 1;
}

void World::setFriction(double mu) {
  if (mu == material_.friction) return;
  material_.friction = mu;
  if (rigid_) rigid_->setFriction(mu);
  // A spring built up under another friction would be stale; frictionless keeps none.
  for (PairState& p : neighbors_->pairs()) p.history = 0;
}

double World::stiffestSpring(int k, bool tangential) const {
  // A force at the bounding radius R, off the centre's line, moves the contact point as if
  // the mass were m / (1 + m R²/I). A disc's normal force passes through its centre; a
  // polygon's need not.
  const double r = boundingRadius_[k];
  const double rotational = 1.0 + mass_[k] * r * r / inertia_[k];
  const double normal = material_.normalStiffness * (shape_[k] == ShapeKind::Disc ? 1.0 : rotational);
  return tangential ? std::max(normal, material_.tangentialStiffness * rotational) : normal;
}

double World::criticalTimestep() const {
  if (prepared_) return criticalTimestep_;
  double dt = std::numeric_limits<double>::infinity();
  // The tangential spring counts whatever the friction now: it is cached once for the run,
  // and friction may change between stages.
  for (int k = 0; k < size(); ++k) dt = std::min(dt, 2.0 * std::sqrt(0.5 * mass_[k] / stiffestSpring(k, true)));
  return dt;
}

double World::packingTimestep(int* particle, int* contacts) const {
  std::vector<int> count(static_cast<size_t>(size()), 0);
  for (const PairState& p : neighbors_->pairs()) {
    if (p.overlap <= 0) continue;
    ++count[static_cast<size_t>(p.i)];
    if (p.j >= 0) ++count[static_cast<size_t>(p.j)];
  }
  const double zeta = dampingRatio(material_.restitution);
  const double dampingFactor = std::sqrt(1 + zeta * zeta) - zeta;
  double dt = std::numeric_limits<double>::infinity();
  for (int k = 0; k < size(); ++k) {
    if (motion_[k] != Motion::Dynamic || count[static_cast<size_t>(k)] == 0) continue;
    // The same spring as criticalTimestep(), once per contact; frictionless contacts (the
    // friction as it is now) have no tangential spring.
    const double stiffest = stiffestSpring(k, material_.friction > 0);
    const double bound = dampingFactor * 2.0 * std::sqrt(0.5 * mass_[k] / (stiffest * count[static_cast<size_t>(k)]));
    if (bound < dt) {
      dt = bound;
      if (particle) *particle = k;
      if (contacts) *contacts = count[static_cast<size_t>(k)];
    }
  }
  return dt;
}

double World::timestep() const {
  if (timestep_ > 0) return timestep_;
  const bool rigid = settings_.engine == WorldSettings::Engine::Box2d;
  return timestepSafety_ * criticalTimestep() * (rigid ? RigidBodySolver::kTimestepScale : 1.0);
}

double World::contactStiffness() const {
  return rigid_ ? rigid_->apparentStiffness(timestep()) : material_.normalStiffness;
}

void World::setKinematicVelocity(int i, const Vec2& v, double spin) {
  if (motion_[i] != Motion::Kinematic) return;
  velocity_[i] = v;
  spin_[i] = spin;
}

double World::area(int i) const {
  return shape_[i] == ShapeKind::Disc ? discArea(boundingRadius_[i])
                                      : polygons_[static_cast<size_t>(shapeIndex_[i])].area;
}

void World::worldVertices(int i, std::vector<Vec2>& out) const {
  const Polygon& poly = polygon(i);
  out.resize(static_cast<size_t>(poly.count));
  for (int k = 0; k < poly.count; ++k) out[k] = position_[i] + rotate(poly.vertices[k], angle_[i]);
}

void World::initialize() {
  if (settings_.engine == WorldSettings::Engine::Box2d) {
    criticalTimestep_ = criticalTimestep();
    prepared_ = true;
    if (timestep() <= 0 || !std::isfinite(timestep())) {
      throw SimulationError("no usable timestep: the scene has no particle with mass");
    }
    rigid_ = std::make_unique<RigidBodySolver>(*this);  // no spring: no critical-timestep bound
    return;
  }
  // Polygon features are decided with Box2D's tolerances at the scale at which Box2D would
  // see the particles: about one unit (its tuning range).
  double meanPolygonRadius = 0;
  for (const Polygon& p : polygons_) meanPolygonRadius += p.circumradius;
  const double scale = polygons_.empty() ? 1.0 : polygons_.size() / meanPolygonRadius;
  polygonCollider_ = std::make_unique<PolygonCollider>(scale);
  for (const Polygon& p : polygons_) polygonCollider_->add(p);
  double meanRadius = 0;
  for (double r : boundingRadius_) meanRadius += r;
  skin_ = size() ? settings_.skinFraction * meanRadius / size() : 0.0;
  neighbors_->invalidate();
  criticalTimestep_ = criticalTimestep();  // particles are fixed from here on: compute once
  prepared_ = true;
  if (timestep() <= 0 || !std::isfinite(timestep())) {
    throw SimulationError("no usable timestep: the scene has no particle with mass");
  }
  if (timestep() > criticalTimestep()) {
    std::ostringstream os;
    os << "the timestep " << timestep() << " s exceeds the critical timestep " << criticalTimestep()
       << " s of the stiffest, lightest contact: explicit integration would be unstable (lower"
          " solver.timestep or solver.timestep_safety below 1)";
    throw SimulationError(os.str());
  }
  for (int k = 0; k < size(); ++k) resetForce(k);
  computeForces();
}

void World::step() {
  if (!prepared_) initialize();
  const double dt = timestep();
  auto t0 = Clock::now();
  if (rigid_) {
    rigid_->step(dt);
    ++steps_;
    time_ += dt;
    if (steps_ % RigidBodySolver::kRebuildEvery == 0) rigid_->rebuild();
    profile_.forces += seconds(t0, Clock::now());
    return;
  }
  forEachParticleRange([&](int begin, int end) {
    advance(dt, begin, end);
    if (neighbors_->outdated(position_, begin, end)) neighborsOutdated_.store(true, std::memory_order_relaxed);
  });
  auto t1 = Clock::now();
  computeForces();
  profile_.integrate += seconds(t0, t1);
  ++steps_;
  time_ += dt;
}

bool World::resumable() const { return !rigid_ || steps_ % RigidBodySolver::kRebuildEvery == 0; }

void World::persist(StateArchive& a) {
  a.section("world");
  a.require(prepared_, "the world must be initialized before its state is loaded");
  a.same(size(), "the particle count");
  a.same(walls_.size(), "the wall count");
  double massSum = 0;  // the particles' masses, in order: a fingerprint of the specimen
  for (int k = 0; k < size(); ++k) massSum = massSum * 1.000001 + mass_[k];
  a.same(massSum, "the particles' masses");
  a(material_);  // friction changes between stages
  a(timestep_);
  a(steps_);
  a(time_);
  a.bitwise(position_);
  a.bitwise(velocity_);
  a.bitwise(force_);
  a(angle_);
  a(spin_);
  a(torque_);
  a(cos_);
  a(sin_);
  a(profile_);
  if (a.loading()) {
    const size_t n = static_cast<size_t>(size());
    a.require(position_.size() == n && velocity_.size() == n && force_.size() == n && angle_.size() == n &&
                  spin_.size() == n && torque_.size() == n && cos_.size() == n && sin_.size() == n,
              "a per-particle array's length differs from the particle count");
  }
  if (rigid_) {
    a.section("box2d");
    rigid_->persist(a);
    return;
  }
  a.section("contacts");
  neighbors_->persist(a, size(), static_cast<int>(walls_.size()));
  a.bitwise(polygonCache_);
  if (a.loading()) {
    // The polygon cache is read per pair, by index, and its features index a polygon's
    // corners: a cache that cannot have come from this world is refused.
    a.require(polygons_.empty() || polygonCache_.size() == neighbors_->pairs().size(),
              "the polygon contact cache's length differs from the pair count");
    for (const CachedContact& c : polygonCache_) {
      a.require(c.kind <= CachedContact::Kind::VertexDisc && c.reference >= 0 && c.reference < kMaxPolygonVertices &&
                    c.incident >= 0 && c.incident < kMaxPolygonVertices,
                "a polygon contact cache entry is out of range");
    }
    if (polygonCollider_) polygonCollider_->setFeatureSearches(profile_.featureSearches);
    if (pool_) assignDeferredSlots();  // the slots follow the pair list
  }
}

void World::forEachParticleRange(const std::function<void(int, int)>& body) {
  if (pool_) pool_->parallelFor(size(), body);
  else body(0, size());
}

// Kick, drift and the next force's start, particle by particle in one pass: the particle's
// data is loaded once (three loops over the particles took a fifth of a disc pile's step).
void World::advance(double dt, int begin, int end) {
  // Local pointers: through the members, every store would make the compiler reload them.
  Vec2* __restrict x = position_.data();
  Vec2* __restrict v = velocity_.data();
  Vec2* __restrict f = force_.data();
  double* __restrict angle = angle_.data();
  double* __restrict w = spin_.data();
  double* __restrict tau = torque_.data();
  const double* invMass = invMass_.data();
  const double* invInertia = invInertia_.data();
  for (int k = begin; k < end; ++k) {
    v[k] += f[k] * (invMass[k] * dt);
    w[k] += tau[k] * (invInertia[k] * dt);
    x[k] += v[k] * dt;
    if (w[k] != 0) {
      angle[k] += w[k] * dt;
      // Only polygons' contacts depend on their orientation: a disc's rotation is kept in
      // angle_ alone (sincos was a fifth of a disc pile's step).
      if (shape_[k] == ShapeKind::Polygon) ::sincos(angle[k], &sin_[k], &cos_[k]);
    }
    f[k] = bodyForce(k);  // resetForce(k), through the restrict pointers
    tau[k] = 0;
  }
}

// The contact between the two members of a pair, whatever their shapes. A pair involving a
// polygon goes through its kept features (PolygonCollider), which `cache` keeps.
ContactGeometry World::pairGeometry(const PairState& p, CachedContact* cache) const {
  const int i = p.i, j = p.j;
  const auto& x = position_;
  const auto& radius = boundingRadius_;
  if (j < 0) {
    const Wall& wall = walls_[static_cast<size_t>(-1 - j)];
    return shape_[i] == ShapeKind::Disc
               ? collideDiscWall(x[i], radius[i], wall)
               : collidePolygonWall(polygons_[static_cast<size_t>(shapeIndex_[i])], x[i], cos_[i], sin_[i], wall);
  }
  const bool iDisc = shape_[i] == ShapeKind::Disc, jDisc = shape_[j] == ShapeKind::Disc;
  if (iDisc && jDisc) return collideDiscs(x[i], radius[i], x[j], radius[j]);
  const double reach = radius[i] + radius[j];
  if ((x[j] - x[i]).squaredNorm() >= reach * reach) {
    if (cache) cache->kind = CachedContact::Kind::None;  // bounding circles apart
    return {};
  }
  const Pose pi{x[i], cos_[i], sin_[i]}, pj{x[j], cos_[j], sin_[j]};
  if (!iDisc && !jDisc) return polygonCollider_->collidePolygons(shapeIndex_[i], pi, shapeIndex_[j], pj, cache);
  if (!iDisc) return polygonCollider_->collidePolygonDisc(shapeIndex_[i], pi, x[j], radius[j], cache);
  ContactGeometry g = polygonCollider_->collidePolygonDisc(shapeIndex_[j], pj, x[i], radius[i], cache);
  g.normal = -g.normal;
  return g;
}

namespace {
// The law at a touching pair whose relative motion is m, with unit normal n and tangent t:
// the force on j from i. Records the pair's history and last forces. Both contact forms
// below end here.
template <class Law>
inline Vec2 lawForce(PairState& p, const ContactMotion& m, const Vec2& n, const Vec2& t, const Law& law, double dt) {
  p.fn = law.normal.force(m, p.dampN);
  p.ft = law.tangential.force(p.fn, m, p.dampT, dt, p.history);
  p.overlap = m.overlap;
  return p.fn * n + p.ft * t;
}
}  // namespace

// The force of a touching pair with geometry g: F on j from i (−F on i), and the torques it
// exerts about each centroid. Updates the pair's history and last forces.
template <class Law>
inline void World::contactForce(PairState& p, const ContactGeometry& g, const Law& law, double dt, Vec2& F,
                                double& ti, double& tj) const {
  const int i = p.i, j = p.j;
  const Vec2* x = position_.data();
  const Vec2* v = velocity_.data();
  const double* w = spin_.data();
  const Vec2& n = g.normal;
  const Vec2 t = perp(n);
  const Vec2 ri = g.point - x[i];
  Vec2 dv = -(v[i] + cross(w[i], ri));
  Vec2 rj = Vec2::Zero();
  if (j >= 0) {
    rj = g.point - x[j];
    dv += v[j] + cross(w[j], rj);
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
template <class Law>
inline void World::contactForce(PairState& p, const DiscContact& c, const Law& law, double dt, Vec2& F, double& ti,
                                double& tj) const {
  const int i = p.i, j = p.j;
  const Vec2* v = velocity_.data();
  const double* w = spin_.data();
  const Vec2& n = c.normal;
  const Vec2 t = perp(n);
  Vec2 dv = -v[i];
  double spin = w[i] * c.armI;
  if (j >= 0) {
    dv += v[j];
    spin += w[j] * c.armJ;
  }
  F = lawForce(p, ContactMotion{c.overlap, dv.dot(n), dv.dot(t) - spin}, n, t, law, dt);
  ti = c.armI * p.ft;
  tj = -c.armJ * p.ft;
}

namespace {
// A pair that does not touch keeps no history and reports no force.
void clearContact(PairState& p) {
  p.history = 0;
  p.fn = p.ft = p.overlap = 0;
}
}  // namespace

// Calls force(k, g) for each touching pair k in [begin, end), in pair order, and apart(k) for
// each other one (after clearing its state), in two passes: every touching pair's geometry
// into scratch, then the forces. A contact's force hangs on a long chain of dependent
// operations (for discs a square root and a division, for polygons the clipping's division),
// and whether a pair touches is a branch the processor cannot predict; in one pass the core
// overlapped only about two pairs' chains. Split, each chain is half as long and more pairs are
// in flight: a settled disc pile's step got 1.2-1.3x faster, a polygon pile's about 1.1x
// (measured together with the one-division clipping), with bit-identical results.
template <bool kDiscsOnly, class Force, class Apart>
inline void World::forEachTouching(int begin, int end, Force&& force, Apart&& apart) {
  PairState* pairs = neighbors_->pairs().data();
  int n = 0;
  if constexpr (kDiscsOnly) {
    TouchingDiscs* scratch = touchingDiscs_.data() + begin;  // this range's own part
    const Vec2* x = position_.data();
    const double* radius = boundingRadius_.data();
    for (int k = begin; k < end; ++k) {
      PairState& p = pairs[k];
      const DiscContact c = p.j >= 0 ? touchDiscs(x[p.i], radius[p.i], x[p.j], radius[p.j])
                                     : touchDiscWall(x[p.i], radius[p.i], walls_[static_cast<size_t>(-1 - p.j)]);
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
  } else {
    TouchingShapes* scratch = touchingShapes_.data() + begin;
    for (int k = begin; k < end; ++k) {
      const ContactGeometry g = pairGeometry(pairs[k], &polygonCache_[static_cast<size_t>(k)]);
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

// One thread, or several each on a contiguous slice of the pairs. A particle's shares from
// the slice holding its first pair are added at once, in pair order; shares computed in later
// slices wait in their slots (assignDeferredSlots) and are added after the loop, in pair order.
// Every particle sees the same additions in the same order whatever the number of threads, so
// the result is bit-identical. With one thread there are no slots: every share is added at
// once. In a scene whose particle indices follow space, almost nothing waits.
template <class Law, bool kDiscsOnly>
void World::pairForces(const Law& law) {
  const double dt = timestep();
  std::vector<PairState>& pairs = neighbors_->pairs();
  if constexpr (kDiscsOnly) touchingDiscs_.resize(pairs.size());
  else touchingShapes_.resize(pairs.size());
  Vec2* f = force_.data();
  double* tau = torque_.data();
  const int* slot = pool_ ? deferredSlot_.data() : nullptr;
  DeferredForce* deferred = deferred_.data();
  // `threaded` is std::true_type when slices may share particles: one thread's loop then
  // carries no test for slots at all.
  auto pairRange = [&](auto threaded, int begin, int end) {
    constexpr bool kThreaded = decltype(threaded)::value;
    forEachTouching<kDiscsOnly>(begin, end, [&](int k, const auto& g) {
      PairState& p = pairs[static_cast<size_t>(k)];
      Vec2 F;
      double ti, tj;
      contactForce(p, g, law, dt, F, ti, tj);
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
  // The waiting shares, then each particle's local damping.
  if (deferred_.empty() && material_.localDamping == 0) return;
  forEachParticleRange([&](int begin, int end) {
    for (int k = begin; k < end; ++k) {
      const int first = slot ? deferredStart_[k] : 0, last = slot ? deferredStart_[k + 1] : 0;
      for (int s = first; s < last; ++s) {
        const DeferredForce& d = deferred[s];
        if (!d.touching) continue;
        f[k] += d.force;
        tau[k] += d.torque;
      }
      if (material_.localDamping > 0) applyLocalDamping(k);
    }
  });
}

// Which pair ends the parallel force loop adds at once and which wait, for the current pair
// list and number of threads. Particle k belongs to the slice holding its first pair; a share
// computed in any other slice (a later one: pairs are in order) gets a slot.
void World::assignDeferredSlots() {
  const int pairCount = static_cast<int>(neighbors_->pairs().size());
  const int threads = pool_->threads();
  const std::vector<int>& start = neighbors_->adjacencyStart();
  const std::vector<int>& entries = neighbors_->adjacency();
  std::vector<int> sliceEnd(static_cast<size_t>(threads));
  for (int t = 0; t < threads; ++t) sliceEnd[static_cast<size_t>(t)] = WorkerPool::sliceBegin(pairCount, t + 1, threads);
  auto sliceOf = [&](int pair) {
    return static_cast<int>(std::upper_bound(sliceEnd.begin(), sliceEnd.end(), pair) - sliceEnd.begin());
  };
  deferredSlot_.assign(2 * static_cast<size_t>(pairCount), -1);
  deferredStart_.assign(static_cast<size_t>(size()) + 1, 0);
  int slots = 0;
  for (int k = 0; k < size(); ++k) {
    deferredStart_[k] = slots;
    if (start[k] == start[k + 1]) continue;
    const int owner = sliceOf(entries[static_cast<size_t>(start[k])] >> 1);
    for (int e = start[k]; e < start[k + 1]; ++e) {
      const int pairEnd = entries[static_cast<size_t>(e)];  // pair × 2, + 1 where k is its j
      if (sliceOf(pairEnd >> 1) != owner) deferredSlot_[static_cast<size_t>(pairEnd)] = slots++;
    }
  }
  deferredStart_[size()] = slots;
  deferred_.assign(static_cast<size_t>(slots), DeferredForce{});
}

void World::assignDamping() {
  const double zeta = dampingRatio(material_.restitution);
  const double kn = material_.normalStiffness, kt = material_.tangentialStiffness;
  for (PairState& p : neighbors_->pairs()) {
    // Effective mass of the pair: against a wall or an immovable particle, the particle's own.
    const double mi = mass_[p.i];
    double m = mi;
    if (p.j >= 0 && motion_[p.j] == Motion::Dynamic && motion_[p.i] == Motion::Dynamic) {
      m = mi * mass_[p.j] / (mi + mass_[p.j]);
    } else if (p.j >= 0 && motion_[p.i] != Motion::Dynamic) {
      m = mass_[p.j];
    }
    p.dampN = 2 * zeta * std::sqrt(m * kn);
    p.dampT = 2 * zeta * std::sqrt(m * kt);
  }
}

void World::carryPolygonCache() {
  const std::vector<int>& from = neighbors_->carriedFrom();
  std::vector<CachedContact> carried(from.size());
  for (size_t k = 0; k < from.size(); ++k) {
    if (from[k] >= 0 && static_cast<size_t>(from[k]) < polygonCache_.size()) carried[k] = polygonCache_[static_cast<size_t>(from[k])];
  }
  polygonCache_.swap(carried);
}

void World::computeForces() {
  auto t0 = Clock::now();
  bool rebuilt = false;
  try {
    rebuilt = neighbors_->update(position_, boundingRadius_, motion_, walls_, skin_,
                                 neighborsOutdated_.exchange(false, std::memory_order_relaxed));
  } catch (const std::domain_error&) {
    checkHealth();  // names the particle and the likely cause
    throw;
  }
  if (rebuilt) {
    assignDamping();
    if (!polygons_.empty()) carryPolygonCache();
    ++profile_.rebuilds;
  }
  if (pool_ && rebuilt) assignDeferredSlots();  // the slots follow the pair list
  auto t1 = Clock::now();
  // One instantiation of the pair loop per law and geometry: a discs-only scene runs no
  // polygon code, a frictionless one keeps no tangential history.
  const LinearSpringDashpot normal{material_.normalStiffness};
  const bool discsOnly = polygons_.empty();
  if (material_.friction == 0) {
    const ContactLaw<LinearSpringDashpot, Frictionless> law{normal, {}};
    discsOnly ? pairForces<decltype(law), true>(law) : pairForces<decltype(law), false>(law);
  } else {
    const ContactLaw<LinearSpringDashpot, CundallStrack> law{
        normal, {material_.tangentialStiffness, material_.friction}};
    discsOnly ? pairForces<decltype(law), true>(law) : pairForces<decltype(law), false>(law);
  }
  auto t2 = Clock::now();
  profile_.neighbors += seconds(t0, t1);
  profile_.forces += seconds(t1, t2);
  if (polygonCollider_) profile_.featureSearches = polygonCollider_->featureSearches();
}

void World::applyLocalDamping(int k) {
  // Cundall's non-viscous damping: each force component is reduced by α|F| against the
  // direction of motion, so it removes energy without slowing a steady drift.
  if (motion_[k] != Motion::Dynamic) return;
  const double a = material_.localDamping;
  auto sign = [](double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); };
  Vec2& f = force_[k];
  f.x() -= a * std::abs(f.x()) * sign(velocity_[k].x());
  f.y() -= a * std::abs(f.y()) * sign(velocity_[k].y());
  torque_[k] -= a * std::abs(torque_[k]) * sign(spin_[k]);
}

void World::contacts(std::vector<ContactRecord>& out) const {
  out.clear();
  if (!prepared_) return;
  if (rigid_) return rigid_->contacts(out);
  const std::vector<PairState>& pairs = neighbors_->pairs();
  for (size_t k = 0; k < pairs.size(); ++k) {
    const PairState& p = pairs[k];
    if (p.overlap <= 0) continue;
    // The cached answer as the forces saw it (positions have not moved since).
    CachedContact cache = k < polygonCache_.size() ? polygonCache_[k] : CachedContact{};
    const ContactGeometry g = pairGeometry(p, &cache);
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

double World::kineticEnergy() const {
  // Velocities live half a step behind the positions (leapfrog); the energy is taken with
  // them brought to the positions' time, v + a·dt/2, as velocity Verlet would report it.
  const double half = rigid_ ? 0.0 : 0.5 * timestep();  // Box2D's velocities are the positions'

  double e = 0;
  for (int k = 0; k < size(); ++k) {
    if (motion_[k] != Motion::Dynamic) continue;
    const Vec2 v = velocity_[k] + force_[k] * (invMass_[k] * half);
    const double w = spin_[k] + torque_[k] * invInertia_[k] * half;
    e += 0.5 * mass_[k] * v.squaredNorm() + 0.5 * inertia_[k] * w * w;
  }
  return e;
}

double World::elasticEnergy() const {
  if (rigid_) return 0;
  double e = 0;
  const LinearSpringDashpot normal{material_.normalStiffness};
  const CundallStrack tangential{material_.tangentialStiffness, material_.friction};
  for (const PairState& p : neighbors_->pairs()) {
    if (p.overlap <= 0) continue;
    e += normal.energy(p.overlap) + tangential.energy(p.history);
  }
  return e;
}

void World::checkHealth() const {
  for (int k = 0; k < size(); ++k) {
    const bool finite = std::isfinite(position_[k].x()) && std::isfinite(position_[k].y()) &&
                        std::isfinite(velocity_[k].x()) && std::isfinite(velocity_[k].y()) &&
                        std::isfinite(angle_[k]) && std::isfinite(spin_[k]);
    if (!finite) {
      std::ostringstream os;
      os << "particle " << k << " has a non-finite position or velocity at step " << steps_
         << " (t = " << time_ << " s): the simulation diverged; the timestep " << timestep()
         << " s against a critical timestep of " << criticalTimestep() << " s is the usual cause";
      throw SimulationError(os.str());
    }
  }
  if (rigid_) rigid_->checkOverlaps();
  for (const PairState& p : neighbors_->pairs()) {
    if (p.overlap <= 0) continue;
    const double size = p.j >= 0 ? std::min(boundingRadius_[p.i], boundingRadius_[p.j]) : boundingRadius_[p.i];
    if (p.overlap > 0.5 * size) {
      std::ostringstream os;
      os << "runaway overlap " << (steps_ == 0 ? std::string("at the start") : "at step " + std::to_string(steps_)) << ": ";
      if (p.j >= 0) os << "particles " << p.i << " and " << p.j;
      else os << "particle " << p.i << " and wall " << (-1 - p.j);
      os << " overlap by " << 100 * p.overlap / size << "% of the smaller particle's radius";
      if (steps_ == 0) {
        os << " at the start (more than 50% is refused: separate the particles in the scene)";
      } else {
        os << "; the contacts are too soft for the load or the timestep (" << timestep() << " s, critical "
           << criticalTimestep() << " s) is too large";
      }
      throw SimulationError(os.str());
    }
  }
}

}  // namespace grainlab

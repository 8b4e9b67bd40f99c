#include "rigid_body_solver.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "grainlab/errors.hpp"

namespace grainlab {
namespace {

b2Vec2 toB2(const Vec2& v) { return b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y())); }
Vec2 fromB2(const b2Vec2& v) { return Vec2(v.x, v.y); }

// Particle index k, or −1 − w for wall w, as a fixture's user data.
uintptr_t encode(int id) { return static_cast<uintptr_t>(static_cast<intptr_t>(id)); }
int decode(b2Fixture* f) { return static_cast<int>(static_cast<intptr_t>(f->GetUserData().pointer)); }

// The polygon moved inward by `skin` along every face normal: vertex k is where the offset
// faces k−1 and k meet, v − skin (n₁ + n₂) / (1 + n₁·n₂). Vertices in Box2D units, CCW.
b2PolygonShape shrunkPolygon(const Polygon& poly, double scale, double skin) {
  b2Vec2 v[b2_maxPolygonVertices];
  const int n = poly.count;
  for (int k = 0; k < n; ++k) {
    const Vec2& a = poly.normals[(k + n - 1) % n];
    const Vec2& b = poly.normals[k];
    v[k] = toB2(poly.vertices[k] * scale - skin * (a + b) / (1.0 + a.dot(b)));
  }
  b2PolygonShape shape;
  shape.Set(v, n);  // may reorder (convex hull): only Box2D uses this copy
  if (shape.m_count != n) {
    throw std::invalid_argument("polygon too small or with edges too short for Box2D's skin (" +
                                std::to_string(b2_polygonRadius) + " units)");
  }
  return shape;
}

// b2World keeps 1/dt of its last step (m_inv_dt0) to scale the warm-start impulses by the
// ratio of timesteps; a new b2World has 0 there and would drop them on its first step. Box2D
// has no setter, so the member is reached the one way the language allows without Box2D's
// co-operation: an explicit instantiation may name a private member, and a friend defined in
// it hands out the pointer.
struct InvDt0Tag {
  using type = float b2World::*;
  friend type member(InvDt0Tag);
};
template <class Tag, typename Tag::type M>
struct ExposeMember {
  friend typename Tag::type member(Tag) { return M; }
};
template struct ExposeMember<InvDt0Tag, &b2World::m_inv_dt0>;

b2ContactID swapped(b2ContactID id) {
  std::swap(id.cf.indexA, id.cf.indexB);
  std::swap(id.cf.typeA, id.cf.typeB);
  return id;
}

}  // namespace

RigidBodySolver::RigidBodySolver(ParticleStore& particles, const Material& material, int velocityIterations,
                                 int positionIterations, Profile& profile)
    : particles_(particles),
      material_(material),
      velocityIterations_(velocityIterations),
      positionIterations_(positionIterations),
      profile_(profile) {}

void RigidBodySolver::initialize(double dt) {
  dt_ = dt;
  contacts_.clear();
  lengthScale_ = massScale_ = 1;
  origin_ = Vec2::Zero();
  const int n = particles_.size();
  double radius = 0, mass = 0;
  for (int k = 0; k < n; ++k) {
    radius += particles_.boundingRadius[k];
    mass += particles_.mass[k];
    origin_ += particles_.position[k];
  }
  if (n > 0) {
    lengthScale_ = n / radius;
    massScale_ = n / mass;
    origin_ /= n;
  }
  // Walls are boxes reaching far past every particle: twice the particles' extent about the
  // origin, plus a thousand mean radii (a block sliding down a slope must not fall off its
  // end). Their vertices are then ~1e3 units out, where float rounding is ~1e-4 units, 2% of
  // the slop.
  double extent = 0;
  for (int k = 0; k < n; ++k) {
    extent = std::max(extent, (particles_.position[k] - origin_).norm() + particles_.boundingRadius[k]);
  }
  halfWidth_ = 2 * extent * lengthScale_ + 1000;
  std::vector<BodyState> bodies(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const b2Vec2 x = toB2((particles_.position[k] - origin_) * lengthScale_);
    const b2Vec2 v = toB2(particles_.velocity[k] * lengthScale_);
    bodies[k] = {x.x, x.y, static_cast<float>(particles_.angle[k]), v.x, v.y, static_cast<float>(particles_.spin[k])};
  }
  build(bodies, {});
}

void RigidBodySolver::build(const std::vector<BodyState>& bodies, const std::vector<ContactState>& contacts) {
  bodies_.clear();
  fixtures_.clear();
  b2_ = std::make_unique<b2World>(toB2(particles_.gravity * lengthScale_));
  b2_->SetAllowSleeping(false);
  b2_->SetContinuousPhysics(false);
  b2_->SetSubStepping(false);
  b2_->SetWarmStarting(true);
  for (int k = 0; k < particles_.size(); ++k) addParticle(k, bodies[static_cast<size_t>(k)]);
  for (int w = 0; w < static_cast<int>(particles_.walls.size()); ++w) addWall(w, halfWidth_);
  if (contacts.empty()) return;
  restoreWarmStart(contacts);
}

RigidBodySolver::~RigidBodySolver() = default;

void RigidBodySolver::addParticle(int k, const BodyState& state) {
  const Motion motion = particles_.motion[k];
  b2BodyDef def;
  def.type = motion == Motion::Dynamic ? b2_dynamicBody : motion == Motion::Kinematic ? b2_kinematicBody : b2_staticBody;
  def.position.Set(state.x, state.y);
  def.angle = state.angle;
  def.linearVelocity.Set(state.vx, state.vy);
  def.angularVelocity = state.spin;
  def.allowSleep = false;
  def.bullet = false;
  b2Body* body = b2_->CreateBody(&def);

  b2FixtureDef fixture;
  fixture.friction = static_cast<float>(material_.friction);
  fixture.restitution = static_cast<float>(material_.restitution);
  fixture.density = 0;  // the mass is set below, from the store's
  fixture.userData.pointer = encode(k);
  b2CircleShape circle;
  b2PolygonShape polygon;
  if (particles_.shape[k] == ShapeKind::Clump) {
    throw SimulationError("clumps run in the dem engine only (the box2d engine builds one shape per body)");
  }
  if (particles_.shape[k] == ShapeKind::Disc) {
    circle.m_radius = static_cast<float>(particles_.boundingRadius[k] * lengthScale_);
    fixture.shape = &circle;
  } else {
    polygon = shrunkPolygon(particles_.polygonOf(k), lengthScale_, b2_polygonRadius);
    fixture.shape = &polygon;
  }
  fixtures_.push_back(body->CreateFixture(&fixture));
  if (motion == Motion::Dynamic) {
    b2MassData mass;
    mass.mass = static_cast<float>(particles_.mass[k] * massScale_);
    mass.center.SetZero();  // the body's origin is the particle's centroid
    mass.I = static_cast<float>(particles_.inertia[k] * massScale_ * lengthScale_ * lengthScale_);
    body->SetMassData(&mass);
  }
  bodies_.push_back(body);
}

void RigidBodySolver::addWall(int index, double halfWidth) {
  // A half-plane as a static box behind its surface, as deep as it is wide. The body sits at
  // the surface's point nearest the origin so the box's own coordinates stay small. The box
  // face is set back by the skin, so the skinned face is the wall's surface.
  const Wall& wall = particles_.walls[static_cast<size_t>(index)];
  const Vec2 n = wall.normal;
  const Vec2 q = (wall.point - origin_) * lengthScale_;
  const Vec2 foot = q.dot(n) * n;  // the surface's point nearest the origin
  const Vec2 t = perp(n);
  const double skin = b2_polygonRadius, depth = halfWidth;
  b2Vec2 v[4] = {toB2(-halfWidth * t - skin * n), toB2(halfWidth * t - skin * n),
                 toB2(halfWidth * t - (skin + depth) * n), toB2(-halfWidth * t - (skin + depth) * n)};
  b2PolygonShape box;
  box.Set(v, 4);
  b2BodyDef def;
  def.type = b2_staticBody;
  def.position = toB2(foot);
  b2Body* body = b2_->CreateBody(&def);
  b2FixtureDef fixture;
  fixture.shape = &box;
  fixture.friction = static_cast<float>(material_.friction);
  fixture.restitution = static_cast<float>(material_.restitution);
  fixture.userData.pointer = encode(-1 - index);
  fixtures_.push_back(body->CreateFixture(&fixture));
}

void RigidBodySolver::capture(std::vector<BodyState>& bodies, std::vector<ContactState>& contacts) const {
  bodies.resize(bodies_.size());
  for (size_t k = 0; k < bodies_.size(); ++k) {
    const b2Body* b = bodies_[k];
    bodies[k] = {b->GetPosition().x, b->GetPosition().y, b->GetAngle(),
                 b->GetLinearVelocity().x, b->GetLinearVelocity().y, b->GetAngularVelocity()};
  }
  contacts.clear();
  for (b2Contact* c = b2_->GetContactList(); c; c = c->GetNext()) {
    const b2Manifold* m = c->GetManifold();
    if (m->pointCount == 0) continue;  // nothing to warm-start
    ContactState s{decode(c->GetFixtureA()), decode(c->GetFixtureB()), m->pointCount, {0, 0}, {0, 0}, {0, 0}};
    for (int p = 0; p < m->pointCount; ++p) {
      s.ids[p] = m->points[p].id.key;
      s.normalImpulse[p] = m->points[p].normalImpulse;
      s.tangentImpulse[p] = m->points[p].tangentImpulse;
    }
    contacts.push_back(s);
  }
}

// The new b2World's contacts are made now (as its first step would make them) and given
// their old manifolds' ids and impulses, which that step's collision carries over to the
// points it finds, as in the old b2World. A pair whose fixtures now come in the other order
// gets its feature ids turned round; its impulses keep their signs (normal and tangent both
// reverse with the order, and so does the force they act on).
void RigidBodySolver::restoreWarmStart(const std::vector<ContactState>& contacts) {
  const_cast<b2ContactManager&>(b2_->GetContactManager()).FindNewContacts();
  std::vector<const ContactState*> sorted(contacts.size());
  for (size_t k = 0; k < contacts.size(); ++k) sorted[k] = &contacts[k];
  auto key = [](int a, int b) { return std::pair(std::min(a, b), std::max(a, b)); };
  std::sort(sorted.begin(), sorted.end(), [&](const ContactState* x, const ContactState* y) {
    return key(x->a, x->b) < key(y->a, y->b);
  });
  for (b2Contact* c = b2_->GetContactList(); c; c = c->GetNext()) {
    const int a = decode(c->GetFixtureA()), b = decode(c->GetFixtureB());
    const auto it = std::lower_bound(sorted.begin(), sorted.end(), key(a, b),
                                     [&](const ContactState* s, const std::pair<int, int>& k) { return key(s->a, s->b) < k; });
    if (it == sorted.end() || key((*it)->a, (*it)->b) != key(a, b)) continue;
    const ContactState& s = **it;
    const bool turned = s.a != a;
    b2Manifold* m = c->GetManifold();
    m->pointCount = s.points;
    for (int p = 0; p < s.points; ++p) {
      b2ContactID id;
      id.key = s.ids[p];
      m->points[p].id = turned ? swapped(id) : id;
      m->points[p].normalImpulse = s.normalImpulse[p];
      m->points[p].tangentImpulse = s.tangentImpulse[p];
    }
  }
  b2_.get()->*member(InvDt0Tag{}) = 1.0f / static_cast<float>(dt_);  // as after a step of dt
}

void RigidBodySolver::rebuild() {
  std::vector<BodyState> bodies;
  std::vector<ContactState> contacts;
  capture(bodies, contacts);
  build(bodies, contacts);
}

void RigidBodySolver::persist(StateArchive& a, double dt) {
  a.section("box2d");
  dt_ = dt;
  a.same(lengthScale_, "box2d's length scale");
  a.same(massScale_, "box2d's mass scale");
  std::vector<BodyState> bodies;
  std::vector<ContactState> contacts;
  if (!a.loading()) capture(bodies, contacts);
  a(bodies);
  a(contacts);
  a.bitwise(contacts_);
  if (a.loading()) {
    a.require(bodies.size() == bodies_.size(), "box2d's body count differs from the scene's");
    // Indices the solver reads with: a manifold's points (Box2D holds two at most) and the
    // contacts' particles and walls.
    for (const ContactState& c : contacts) {
      a.require(c.points >= 0 && c.points <= b2_maxManifoldPoints, "a box2d contact has " + std::to_string(c.points) + " points");
      a.require(std::isfinite(c.normalImpulse[0]) && std::isfinite(c.normalImpulse[1]) &&
                    std::isfinite(c.tangentImpulse[0]) && std::isfinite(c.tangentImpulse[1]),
                "a box2d contact's impulse is not finite");
    }
    // Box2D asserts that a body it creates has a finite pose and velocity.
    for (const BodyState& b : bodies) {
      a.require(std::isfinite(b.x) && std::isfinite(b.y) && std::isfinite(b.angle) && std::isfinite(b.vx) &&
                    std::isfinite(b.vy) && std::isfinite(b.spin),
                "a box2d body's position or velocity is not finite");
    }
    const int n = particles_.size(), walls = static_cast<int>(particles_.walls.size());
    for (const ContactRecord& r : contacts_)
      a.require(r.i >= 0 && r.i < n && r.j >= -walls && r.j < n, "a box2d contact's particle or wall is out of range");
    build(bodies, contacts);
  }
}

double RigidBodySolver::contactStiffness(double dt) const {
  const double meanMass = 1.0 / massScale_;
  return 4.0 / 3.0 * velocityIterations_ * meanMass / (dt * dt);
}

void RigidBodySolver::frictionChanged(double mu) {
  if (!b2_) return;  // not built yet: initialize() reads the material's friction
  for (b2Fixture* f : fixtures_) f->SetFriction(static_cast<float>(mu));
  for (b2Contact* c = b2_->GetContactList(); c; c = c->GetNext()) c->ResetFriction();
}

void RigidBodySolver::step(double dt, std::int64_t step) {
  const auto start = std::chrono::steady_clock::now();
  dt_ = dt;
  const int n = particles_.size();
  const double L = lengthScale_;
  for (int k = 0; k < n; ++k) {
    if (particles_.motion[k] != Motion::Kinematic) continue;
    b2Body* b = bodies_[static_cast<size_t>(k)];
    b->SetTransform(toB2((particles_.position[k] - origin_) * L), static_cast<float>(particles_.angle[k]));
    b->SetLinearVelocity(toB2(particles_.velocity[k] * L));
    b->SetAngularVelocity(static_cast<float>(particles_.spin[k]));
  }
  b2_->Step(static_cast<float>(dt), velocityIterations_, positionIterations_);
  for (int k = 0; k < n; ++k) {
    const b2Body* b = bodies_[static_cast<size_t>(k)];
    switch (particles_.motion[k]) {
      case Motion::Dynamic:
        particles_.position[k] = origin_ + fromB2(b->GetPosition()) / L;
        particles_.angle[k] = b->GetAngle();
        particles_.velocity[k] = fromB2(b->GetLinearVelocity()) / L;
        particles_.spin[k] = b->GetAngularVelocity();
        break;
      case Motion::Kinematic:  // in double, as the DEM's drift; Box2D gets it next step
        particles_.position[k] += particles_.velocity[k] * dt;
        particles_.angle[k] += particles_.spin[k] * dt;
        break;
      case Motion::Fixed: break;
    }
  }
  gatherContacts(dt);
  if (step % kRebuildEvery == 0) rebuild();
  profile_.forces += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void RigidBodySolver::gatherContacts(double dt) {
  const double L = lengthScale_;
  const double toForce = 1.0 / (massScale_ * L * dt);  // Box2D impulse → N per metre
  contacts_.clear();
  for (b2Contact* c = b2_->GetContactList(); c; c = c->GetNext()) {
    if (!c->IsTouching()) continue;
    const b2Manifold* m = c->GetManifold();
    if (m->pointCount == 0) continue;
    b2WorldManifold wm;
    c->GetWorldManifold(&wm);
    const int a = decode(c->GetFixtureA()), b = decode(c->GetFixtureB());
    // i is the particle of lower index (a wall, j < 0, is always j); Box2D's normal runs
    // from A to B, so it flips when A is j. The tangential force keeps its sign under the
    // flip (n and t = n turned +90° both reverse): Box2D's tangent is n turned −90°, so
    // the force on B is λn n − λt t, and on j from i always fn n + ft t with ft = −Σλt/dt.
    const bool swap = b >= 0 && (a < 0 || b < a);
    ContactRecord r;
    r.i = swap ? b : a;
    r.j = swap ? a : b;
    const Vec2 normal = fromB2(wm.normal).normalized();
    r.normal = swap ? Vec2(-normal) : normal;
    double ln = 0, lt = 0, depth = 0;
    Vec2 weighted = Vec2::Zero(), mean = Vec2::Zero();
    for (int k = 0; k < m->pointCount; ++k) {
      const b2ManifoldPoint& p = m->points[k];
      const Vec2 x = fromB2(wm.points[k]);
      ln += p.normalImpulse;
      lt += p.tangentImpulse;
      weighted += p.normalImpulse * x;
      mean += x;
      depth = std::max(depth, -static_cast<double>(wm.separations[k]));
    }
    const Vec2 point = ln > 0 ? Vec2(weighted / ln) : Vec2(mean / m->pointCount);
    r.point = origin_ + point / L;
    r.fn = ln * toForce;
    r.ft = -lt * toForce;
    r.overlap = depth / L;
    contacts_.push_back(r);
  }
  // The store's forces and torques: the contact forces above and gravity, about the centroids.
  for (int k = 0; k < particles_.size(); ++k) {
    particles_.force[k] = particles_.motion[k] == Motion::Dynamic ? Vec2(particles_.mass[k] * particles_.gravity) : Vec2::Zero();
    particles_.torque[k] = 0;
  }
  for (const ContactRecord& r : contacts_) {
    const Vec2 f = r.fn * r.normal + r.ft * perp(r.normal);  // on j from i
    particles_.force[r.i] -= f;
    particles_.torque[r.i] -= cross(r.point - particles_.position[r.i], f);
    if (r.j >= 0) {
      particles_.force[r.j] += f;
      particles_.torque[r.j] += cross(r.point - particles_.position[r.j], f);
    }
  }
}

double RigidBodySolver::packingTimestep(int*, int*) const { return std::numeric_limits<double>::infinity(); }

void RigidBodySolver::contacts(std::vector<ContactRecord>& out) const {
  out = contacts_;
  std::sort(out.begin(), out.end(), [](const ContactRecord& x, const ContactRecord& y) {
    return x.i < y.i || (x.i == y.i && x.j < y.j);
  });
}

void RigidBodySolver::checkOverlaps(std::int64_t step, double, double) const {
  for (const ContactRecord& r : contacts_) {
    const double size = r.j >= 0 ? std::min(particles_.boundingRadius[r.i], particles_.boundingRadius[r.j])
                                 : particles_.boundingRadius[r.i];
    if (r.overlap > 0.5 * size) {
      std::ostringstream os;
      os << "runaway overlap at step " << step << ": ";
      if (r.j >= 0) os << "particles " << r.i << " and " << r.j;
      else os << "particle " << r.i << " and wall " << r.wallIndex();
      os << " overlap by " << 100 * r.overlap / size
         << "% of the smaller particle's radius: Box2D's solver could not keep them apart (raise"
            " solver.velocity_iterations or solver.position_iterations, or lower the timestep)";
      throw SimulationError(os.str());
    }
  }
}

}  // namespace grainlab

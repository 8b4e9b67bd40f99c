#include "grainlab/world.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "dem_solver.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/state_archive.hpp"
#include "rigid_body_solver.hpp"
#include "timestep_bounds.hpp"

namespace grainlab {
namespace {

std::unique_ptr<Solver> makeSolver(const WorldSettings& settings, ParticleStore& particles, const Material& material,
                                   Profile& profile) {
  if (settings.threads < 1) throw std::invalid_argument("threads must be at least 1");
  if (settings.engine == WorldSettings::Engine::Box2d) {
    return std::make_unique<RigidBodySolver>(particles, material, settings.velocityIterations,
                                             settings.positionIterations, profile);
  }
  return std::make_unique<DemSolver>(particles, material, settings.threads, settings.skinFraction, profile);
}

}  // namespace

World::World(const Material& material, WorldSettings settings)
    : material_(material), settings_(settings), solver_(makeSolver(settings_, particles_, material_, profile_)) {}

World::~World() = default;

int World::addParticle(const ParticleSpec& spec) {
  const int index = particles_.add(spec, material_);
  prepared_ = false;
  return index;
}

int World::addWall(const Wall& wall) {
  const int index = particles_.addWall(wall);
  prepared_ = false;
  return index;
}

void World::setThreads(int threads) {
  if (threads < 1) throw std::invalid_argument("threads must be at least 1, not " + std::to_string(threads));
  if (threads == settings_.threads) return;
  settings_.threads = threads;
  solver_->setThreads(threads);
}

void World::setFriction(double mu) {
  if (mu == material_.friction) return;
  material_.friction = mu;
  solver_->frictionChanged(mu);
}

double World::criticalTimestep() const {
  return prepared_ ? criticalTimestep_ : grainlab::criticalTimestep(particles_, material_);
}

double World::packingTimestep(int* particle, int* contacts) const { return solver_->packingTimestep(particle, contacts); }

double World::timestep() const {
  if (timestep_ > 0) return timestep_;
  return timestepSafety_ * criticalTimestep() * solver_->timestepScale();
}

double World::contactStiffness() const { return solver_->contactStiffness(timestep()); }

void World::setPeriodicCell(const Eigen::Matrix2d& h) {
  if (settings_.engine == WorldSettings::Engine::Box2d) {
    throw std::invalid_argument("the box2d engine has no periodic cell: use the dem engine");
  }
  particles_.cell.emplace(h);
  prepared_ = false;
}

void World::setCellVelocityGradient(const Eigen::Matrix2d& L) {
  if (!particles_.cell) throw std::logic_error("setCellVelocityGradient: the world has no periodic cell");
  if (!L.allFinite()) throw std::invalid_argument("the periodic cell's velocity gradient must be finite");
  particles_.cell->setVelocityGradient(L);
}

void World::setKinematicVelocity(int i, const Vec2& v, double spin) {
  if (particles_.motion[i] != Motion::Kinematic) return;
  particles_.velocity[i] = v;
  particles_.spin[i] = spin;
}

void World::worldVertices(int i, std::vector<Vec2>& out) const {
  const Polygon& poly = polygon(i);
  out.resize(static_cast<size_t>(poly.count));
  for (int k = 0; k < poly.count; ++k) out[k] = particles_.position[i] + rotate(poly.vertices[k], particles_.angle[i]);
}

void World::worldMembers(int i, std::vector<ClumpMember>& out) const {
  const Clump& c = clump(i);
  out.resize(c.members.size());
  for (size_t k = 0; k < c.members.size(); ++k) {
    out[k] = {particles_.position[i] + rotate(c.members[k].centre, particles_.angle[i]), c.members[k].radius};
  }
}

template <class Action>
void World::namingDivergence(Action&& action) {
  try {
    action();
  } catch (const std::domain_error&) {
    checkHealth();  // names the particle and the likely cause
    throw;
  }
}

void World::initialize() {
  criticalTimestep_ = grainlab::criticalTimestep(particles_, material_);  // particles are fixed from here on
  prepared_ = true;
  const double dt = timestep();
  if (dt <= 0 || !std::isfinite(dt)) throw SimulationError("no usable timestep: the scene has no particle with mass");
  if (solver_->boundedByCriticalTimestep() && dt > criticalTimestep_) {
    std::ostringstream os;
    os << "the timestep " << dt << " s exceeds the critical timestep " << criticalTimestep_
       << " s of the stiffest, lightest contact: explicit integration would be unstable (lower"
          " solver.timestep or solver.timestep_safety below 1)";
    throw SimulationError(os.str());
  }
  namingDivergence([&] { solver_->initialize(dt); });
}

void World::step() {
  if (!prepared_) initialize();
  const double dt = timestep();
  namingDivergence([&] { solver_->step(dt, steps_ + 1); });
  ++steps_;
  time_ += dt;
}

bool World::resumable() const { return solver_->resumable(steps_); }

void World::makeResumable() {
  if (prepared_) solver_->makeResumable();
}

void World::persist(StateArchive& a) {
  a.section("world");
  a.require(prepared_, "the world must be initialized before its state is loaded");
  a.same(size(), "the particle count");
  a.same(particles_.walls.size(), "the wall count");
  double massSum = 0;  // the particles' masses, in order: a fingerprint of the specimen
  for (int k = 0; k < size(); ++k) massSum = massSum * 1.000001 + particles_.mass[k];
  a.same(massSum, "the particles' masses");
  a(material_);  // friction changes between stages
  a(timestep_);
  a(steps_);
  a(time_);
  ParticleStore& p = particles_;
  a.bitwise(p.position);
  a.bitwise(p.velocity);
  a.bitwise(p.force);
  a(p.angle);
  a(p.spin);
  a(p.torque);
  a(p.cosAngle);
  a(p.sinAngle);
  a(profile_);
  if (p.cell) a(*p.cell);  // periodic scenes only: other checkpoints keep their layout
  if (a.loading()) {
    const size_t n = static_cast<size_t>(size());
    a.require(p.position.size() == n && p.velocity.size() == n && p.force.size() == n && p.angle.size() == n &&
                  p.spin.size() == n && p.torque.size() == n && p.cosAngle.size() == n && p.sinAngle.size() == n,
              "a per-particle array's length differs from the particle count");
  }
  solver_->persist(a, timestep());
}

void World::contacts(std::vector<ContactRecord>& out) const {
  out.clear();
  if (prepared_) solver_->contacts(out);
}

StressTensor World::contactStress(std::span<const unsigned char> inside, double area) const {
  if (!prepared_) return grainlab::contactStress({}, positions(), inside, area, periodicCell());
  return solver_->contactStress(positions(), inside, area, periodicCell());
}

}  // namespace grainlab

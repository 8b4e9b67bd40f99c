#include "dem_solver.hpp"

#include <chrono>
#include <stdexcept>

#include "affine_drift.hpp"
#include "grainlab/simd_path.hpp"
#include "leapfrog.hpp"
#include "timestep_bounds.hpp"
#include "worker_pool.hpp"

namespace grainlab {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

std::unique_ptr<WorkerPool> makePool(int threads) {
  return threads > 1 ? std::make_unique<WorkerPool>(threads) : nullptr;
}

}  // namespace

DemSolver::DemSolver(ParticleStore& particles, const Material& material, int threads, double skinFraction,
                     Profile& profile)
    : particles_(particles),
      material_(material),
      profile_(profile),
      pool_(makePool(threads)),
      contacts_(particles, material, skinFraction, pool_.get(), profile),
      skinFraction_(skinFraction) {}

DemSolver::~DemSolver() = default;

void DemSolver::setThreads(int threads) {
  // The contact solver lets go of the old pool (and replans for the new) before it goes.
  std::unique_ptr<WorkerPool> pool = makePool(threads);
  contacts_.setPool(pool.get());
  pool_ = std::move(pool);
}

void DemSolver::forEachParticleRange(const std::function<void(int, int)>& body) {
  if (pool_) pool_->parallelFor(particles_.size(), body);
  else body(0, particles_.size());
}

void DemSolver::initialize(double dt) {
  members_.reset();
  if (particles_.cell && !particles_.clumps.empty()) {
    throw std::invalid_argument("clumps are not supported in a periodic cell yet: use discs or polygons");
  }
  if (!particles_.clumps.empty()) {
    members_ = std::make_unique<MemberContactSolver>(particles_, material_, skinFraction_, profile_);
    members_->initialize();
  } else {
    contacts_.initialize();
  }
  for (int k = 0; k < particles_.size(); ++k) {
    particles_.force[k] = particles_.bodyForce(k);
    particles_.torque[k] = 0;
  }
  computeForces(dt);
}

void DemSolver::computeForces(double dt) {
  const bool moved = neighborsOutdated_.exchange(false, std::memory_order_relaxed);
  if (members_) members_->computeForces(dt);  // checks its members' moves itself
  else contacts_.computeForces(dt, moved);
}

// The step, as a pipeline: each particle is kicked and drifted by the forces of the last step
// (and checked against the neighbour list's skin while it is in cache), then the contacts
// (neighbour list, narrow phase, force law) give the forces for the next.
void DemSolver::step(double dt, std::int64_t) {
  auto t0 = Clock::now();
  // The wide path advances polygons' and clumps' rotations incrementally; the baseline takes sincos.
  const bool incremental = simdPath() == SimdPath::Wide;
  if (particles_.cell) {
    // The periodic cell's step: its edges, then each particle, by the same map I + L dt.
    particles_.cell->advance(dt);
    contacts_.cellAdvanced();
    const Eigen::Matrix2d L = particles_.cell->velocityGradient();
    forEachParticleRange([&](int begin, int end) {
      leapfrogAdvance(particles_, dt, begin, end, incremental);
      affineDrift(particles_, L, dt, begin, end);
      if (contacts_.movedOutOfSkin(begin, end)) neighborsOutdated_.store(true, std::memory_order_relaxed);
    });
    auto t1 = Clock::now();
    computeForces(dt);
    profile_.integrate += seconds(t0, t1);
    return;
  }
  forEachParticleRange([&](int begin, int end) {
    leapfrogAdvance(particles_, dt, begin, end, incremental);
    if (!members_ && contacts_.movedOutOfSkin(begin, end)) neighborsOutdated_.store(true, std::memory_order_relaxed);
  });
  auto t1 = Clock::now();
  computeForces(dt);
  profile_.integrate += seconds(t0, t1);
}

double DemSolver::packingTimestep(int* particle, int* contacts) const {
  std::vector<int> count;
  members_ ? members_->countContacts(count) : contacts_.countContacts(count);
  return grainlab::packingTimestep(particles_, material_, count, particle, contacts);
}

}  // namespace grainlab

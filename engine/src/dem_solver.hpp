#pragma once
// The dem engine ("solver": {"engine": "dem"}, the default): grainlab's own contact laws
// (ContactSolver) and leapfrog integration in double precision, on one thread or several
// with bit-identical results. A scene with clumps has its contacts between member discs
// (MemberContactSolver) instead of between bodies (ContactSolver).
#include <atomic>
#include <functional>
#include <memory>

#include "contact_solver.hpp"
#include "member_contacts.hpp"
#include "solver.hpp"

namespace grainlab {

class WorkerPool;

class DemSolver final : public Solver {
 public:
  /// `threads` counts the caller's; `skinFraction` is the Verlet skin over the mean
  /// bounding radius (WorldSettings).
  DemSolver(ParticleStore& particles, const Material& material, int threads, double skinFraction, Profile& profile);
  ~DemSolver() override;

  void initialize(double dt) override;
  void step(double dt, std::int64_t step) override;
  void frictionChanged(double) override {
    members_ ? members_->clearTangentialHistory() : contacts_.clearTangentialHistory();
  }
  void setThreads(int threads) override;

  double timestepScale() const override { return 1.0; }
  bool boundedByCriticalTimestep() const override { return true; }
  double packingTimestep(int* particle, int* contacts) const override;
  double contactStiffness(double) const override { return material_.normalStiffness; }
  bool velocitiesLagHalfStep() const override { return true; }

  void contacts(std::vector<ContactRecord>& out) const override {
    members_ ? members_->contacts(out) : contacts_.contacts(out);
  }
  StressTensor contactStress(std::span<const Vec2> centroids, std::span<const unsigned char> inside, double area,
                             const PeriodicCell* cell) const override {
    return members_ ? Solver::contactStress(centroids, inside, area, cell)
                    : contacts_.contactStress(centroids, inside, area, cell);
  }
  double elasticEnergy() const override { return members_ ? members_->elasticEnergy() : contacts_.elasticEnergy(); }
  void checkOverlaps(std::int64_t step, double dt, double criticalDt) const override {
    members_ ? members_->checkOverlaps(step, dt, criticalDt) : contacts_.checkOverlaps(step, dt, criticalDt);
  }

  bool resumable(std::int64_t) const override { return true; }
  void persist(StateArchive& a, double) override { members_ ? members_->persist(a) : contacts_.persist(a); }

 private:
  void forEachParticleRange(const std::function<void(int, int)>& body);
  // The next step's forces, by whichever contact solver the scene has.
  void computeForces(double dt);

  ParticleStore& particles_;
  const Material& material_;
  Profile& profile_;
  std::unique_ptr<WorkerPool> pool_;  // null when serial
  ContactSolver contacts_;
  std::unique_ptr<MemberContactSolver> members_;  // set by initialize() when the store has clumps
  const double skinFraction_;
  // Set by the step's integration pass when some particle moved far enough to need a new
  // neighbour list; each thread checks its own particles, so none reads the others' lines.
  std::atomic<bool> neighborsOutdated_{true};
};

}  // namespace grainlab

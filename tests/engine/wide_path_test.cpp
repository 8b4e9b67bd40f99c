// The wide contact path (disc pairs in batches, several per instruction) rounds differently
// from the baseline (an estimated 1/|d| refined by Newton's method, fused products): it must
// give the same bits on every run and with any number of threads, and the baseline's forces
// to rounding level: each on every instruction set this build compiled, forced in turn
// (vectors of 1 to 8 doubles).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <string>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"
#include "disc_pair_kernel.hpp"
#include "grainlab/simd_path.hpp"
#include "wide_path_support.hpp"

namespace grainlab {
namespace {

constexpr double kEpsilon = 0x1p-52;  // double's unit roundoff ×2: one unit in the last place at 1

// Every series row as text, and the bits of every final position, velocity, spin and contact.
class Recorder : public RunObserver {
 public:
  void onSample(const Sample& s, const World&) override { rows += formatSeriesRow(s) + "\n"; }
  void onFinish(const RunSummary&, const World& world) override {
    for (const Vec2& x : world.positions()) mix(x.data(), 2);
    for (const Vec2& v : world.velocities()) mix(v.data(), 2);
    for (double w : world.spins()) mix(&w, 1);
    std::vector<ContactRecord> contacts;
    world.contacts(contacts);
    this->contacts = contacts.size();
    for (const ContactRecord& c : contacts) {
      const double values[] = {c.fn, c.ft, c.overlap, c.point.x(), c.point.y()};
      mix(values, 5);
    }
  }
  std::string rows;
  std::uint64_t hash = 1469598103934665603ull;
  size_t contacts = 0;

 private:
  void mix(const double* v, int n) {
    for (int k = 0; k < n; ++k) {
      std::uint64_t bits;
      std::memcpy(&bits, v + k, sizeof bits);
      hash = (hash ^ bits) * 1099511628211ull;
    }
  }
};

// A shuffled disc pile pressed 8% closer than its lattice under 50 g: in contact, sliding and
// rebuilding its neighbour list through the run (as in the determinism tests).
Scene pressedPile() {
  Scene scene = pileScene(16, 16, false);
  std::mt19937_64 rng(7);
  std::shuffle(scene.particles.begin(), scene.particles.end(), rng);
  for (ParticleSpec& p : scene.particles) p.position *= 0.92;
  scene.gravity *= 50;
  scene.stages[0].duration = 0.01;  // s
  return scene;
}

// The same with rolling resistance: circular-rolling's μ_r and damping ratio.
Scene rollingPile() {
  Scene scene = pressedPile();
  scene.material.rollingFriction = 0.1;
  scene.material.rollingDamping = 0.3;
  return scene;
}

// A shuffled pile of three-disc clumps (the bench's clump pile) falling under 50 g onto the
// floor: in contact, sliding and rebuilding its member pairs through the run.
Scene clumpPile() {
  Scene scene = clumpPileScene(12, 12);
  std::mt19937_64 rng(7);
  std::shuffle(scene.particles.begin(), scene.particles.end(), rng);
  scene.gravity *= 50;
  scene.stages[0].duration = 0.02;  // s
  return scene;
}

Recorder runOn(SimdPath path, const Scene& scene) {
  overrideSimdPath(path);
  Recorder r;
  const RunStatus status = runScene(scene, r).status;
  overrideSimdPath(std::nullopt);
  EXPECT_EQ(status, RunStatus::Completed);
  return r;
}

class WidePath : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!test::wideSimdBuilt()) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  }
};

TEST_F(WidePath, GivesTheSameBitsWithAnyThreadCount) {
  test::onEveryWideTarget([&](const std::string& target) {
    enum class Law { Friction, Frictionless, Rolling, Clumps };
    for (const Law law : {Law::Friction, Law::Frictionless, Law::Rolling, Law::Clumps}) {
      Scene scene = law == Law::Rolling ? rollingPile() : law == Law::Clumps ? clumpPile() : pressedPile();
      if (law == Law::Frictionless) scene.material.friction = 0;
      else scene.material.localDamping = 0.3;
      const Recorder serial = runOn(SimdPath::Wide, scene);
      ASSERT_GT(serial.contacts, 100u) << target;  // the pile is in contact at the end
      EXPECT_EQ(serial.hash, runOn(SimdPath::Wide, scene).hash) << target << ": a second serial run";
      for (int threads : {2, 3}) {
        scene.solver.threads = threads;
        const Recorder threaded = runOn(SimdPath::Wide, scene);
        EXPECT_EQ(serial.hash, threaded.hash) << target << ", " << threads << " threads (on " << discPairKernelTarget() << ")";
        EXPECT_EQ(serial.rows, threaded.rows) << target << ", " << threads << " threads";
      }
    }
  });
}

// A disc five times the size of the twelve discs pressed onto it all round touches more of
// them than a particle's fixed run of share records holds: the rest go to the overflow, which
// must keep the order. Threaded runs use the records; one thread adds the shares at once.
TEST_F(WidePath, ABigDiscsManyContactsGiveTheSameBitsWithAnyThreadCount) {
  test::onEveryWideTarget([&](const std::string& target) {
    Scene scene = pressedPile();
    const double r = scene.particles[0].radius, big = 5 * r;
    const Vec2 centre(0.03, 0.03);
    std::vector<ParticleSpec> ring;
    for (int k = 0; k < 12; ++k) {
      ParticleSpec p = scene.particles[0];
      p.radius = r;
      const double a = 2 * kPi * k / 12 + 0.1;
      p.position = centre + (big + 0.9 * r) * Vec2(std::cos(a), std::sin(a));  // pressed by 0.1 r
      ring.push_back(p);
    }
    ParticleSpec bigDisc = scene.particles[0];
    bigDisc.position = centre;
    bigDisc.radius = big;
    ring.push_back(bigDisc);
    scene.particles = ring;
    scene.gravity = Vec2::Zero();
    auto run = [&](int threads, int* bigContacts) {
      overrideSimdPath(SimdPath::Wide);
      WorldSettings settings;
      settings.threads = threads;
      World world(scene.material, settings);
      for (const ParticleSpec& p : scene.particles) world.addParticle(p);
      for (const Wall& wall : scene.walls) world.addWall(wall);
      world.setGravity(scene.gravity);
      const int b = world.size() - 1;
      *bigContacts = 0;  // the most at once
      std::vector<ContactRecord> contacts;
      for (int k = 0; k < 200; ++k) {
        world.step();
        contacts.clear();
        world.contacts(contacts);
        *bigContacts = std::max(*bigContacts, static_cast<int>(std::count_if(contacts.begin(), contacts.end(),
                                                                             [&](const ContactRecord& c) {
                                                                               return c.i == b || c.j == b;
                                                                             })));
      }
      overrideSimdPath(std::nullopt);
      std::uint64_t hash = 1469598103934665603ull;
      for (const Vec2& x : world.positions()) {
        for (int c = 0; c < 2; ++c) {
          std::uint64_t bits;
          std::memcpy(&bits, x.data() + c, sizeof bits);
          hash = (hash ^ bits) * 1099511628211ull;
        }
      }
      return hash;
    };
    int bigContacts = 0, unused = 0;
    const std::uint64_t serial = run(1, &bigContacts);
    EXPECT_GT(bigContacts, 8) << target << ": the big disc must touch more neighbours than a run of records holds";
    EXPECT_EQ(serial, run(2, &unused)) << target << ", 2 threads";
    EXPECT_EQ(serial, run(3, &unused)) << target << ", 3 threads";
  });
}

// Two worlds step `scene` in lockstep on the baseline (the same bits), then take one step
// each, one on the wide path; returns the largest gaps between their particles' forces and
// torques, the largest force and torque on the baseline, and the gap between the energies
// stored in their contacts' springs (the pairs' state the step left: what the next step starts
// from), with the baseline's touching contacts and their largest force.
struct ForceGaps {
  double force = 0, torque = 0, largestForce = 0, largestTorque = 0;
  double energy = 0, largestContactForce = 0;
  size_t contacts = 0;
};
ForceGaps oneWideStep(const Scene& scene, int threads, int steps) {
  WorldSettings settings;
  settings.threads = threads;
  const std::unique_ptr<World> baseline = test::worldOf(scene, settings), wide = test::worldOf(scene, settings);
  overrideSimdPath(SimdPath::Baseline);
  for (int k = 0; k < steps; ++k) {  // into contact, with sliding
    baseline->step();
    wide->step();
  }
  baseline->step();
  overrideSimdPath(SimdPath::Wide);
  wide->step();
  overrideSimdPath(std::nullopt);
  ForceGaps g;
  for (int p = 0; p < baseline->size(); ++p) {
    g.force = std::max(g.force, (wide->forces()[p] - baseline->forces()[p]).norm());
    g.torque = std::max(g.torque, std::abs(wide->torques()[p] - baseline->torques()[p]));
    g.largestForce = std::max(g.largestForce, baseline->forces()[p].norm());
    g.largestTorque = std::max(g.largestTorque, std::abs(baseline->torques()[p]));
  }
  g.energy = std::abs(wide->elasticEnergy() - baseline->elasticEnergy());
  std::vector<ContactRecord> contacts;
  baseline->contacts(contacts);
  g.contacts = contacts.size();
  for (const ContactRecord& c : contacts) g.largestContactForce = std::max(g.largestContactForce, std::hypot(c.fn, c.ft));
  return g;
}

// A bound on the stored energies' gap: a spring holding force f (stiffness k) stores f²/2k,
// which a rounding-level gap Δf in that force moves by f Δf / k. Normal and tangential forces
// move by at most the force bound, a rolling couple (k_r = β k_t R*²) by μ_r R* times it; the
// couple is at most μ_r R* f. Summed over the contacts, with f the largest contact force.
double energyBound(const ForceGaps& g, const Material& m, double forceBound) {
  const double rolling = m.rollingFriction * m.rollingFriction / m.rollingStiffnessRatio;
  return static_cast<double>(g.contacts) * g.largestContactForce * forceBound *
         (1 / m.normalStiffness + (1 + rolling) / m.tangentialStiffness);
}

// The pressed pile, one step on each path after 2000 on the baseline. Their forces may differ
// by rounding only: the overlap is r_i + r_j − |d|, so a few units in the last place of |d|
// (ε · 2r) move a normal force by k_n · ε · 2r, and the spring and dashpot terms by less; a
// particle sums at most a few neighbours' worth. 64 k_n ε 2r (×r for a torque) bounds that; a
// term missing or of the wrong sign (a damping, a torque arm) would differ by far more (k_n
// times an overlap, about 1e-3 r, against 1e-14 r).
// With rolling resistance each contact's couple adds to the torques: its cap μ_r R* f_n moves
// with f_n (R* ≤ r/2, so by at most μ_r r/2 times f_n's gap), its spring and damper by a few
// units in their last place (far below: the couple is at most μ_r R* f_n, f_n ≪ k_n 2r), so
// the torque bound grows by (1 + μ_r); a couple missing or of the wrong sign is of order
// μ_r R* f_n, about 1e-4 r · k_n r against 1e-14 r · k_n r. The springs' stored energy checks
// the state the step leaves (a relative rotation not reset to the cap overshoots it by ω_r dt,
// storing about μ_r R* f_n ω_r dt more, far above the bound).
TEST_F(WidePath, GivesTheBaselinesForcesToRounding) {
  test::onEveryWideTarget([&](const std::string& target) {
    for (const bool rolling : {false, true}) {
      for (int threads : {1, 2}) {
        const Scene scene = rolling ? rollingPile() : pressedPile();
        const ForceGaps g = oneWideStep(scene, threads, 2000);
        double largestRadius = 0;
        for (const ParticleSpec& p : scene.particles) largestRadius = std::max(largestRadius, p.radius);
        const double forceBound = 64 * scene.material.normalStiffness * kEpsilon * 2 * largestRadius;
        const double torqueBound = (1 + scene.material.rollingFriction) * forceBound * largestRadius;
        EXPECT_GT(g.force, 0) << target << ": the wide path was not taken: its rounding differs from the baseline's";
        EXPECT_GT(g.largestForce, 1e6 * forceBound) << target << ": the pile is pressed: its forces are far above the bound";
        EXPECT_GT(g.largestTorque, 1e3 * torqueBound) << target << ": the pile's contacts turn its discs";
        EXPECT_LE(g.force, forceBound) << target << ", " << threads << " threads" << (rolling ? ", rolling" : "");
        EXPECT_LE(g.torque, torqueBound) << target << ", " << threads << " threads" << (rolling ? ", rolling" : "");
        EXPECT_LE(g.energy, energyBound(g, scene.material, forceBound)) << target << ", " << threads << " threads" << (rolling ? ", rolling" : "");
      }
    }
  });
}

// The clump pile, one step on each path after 1000 on the baseline: member pairs through the
// kernel with their levers. A member's force moves by rounding as a disc's does, with the
// member's radius r_m for r; a clump sums its members' contacts, at most a few neighbours each
// (64 bounds them, as above), and each torque's lever from the centroid is at most the clump's
// reach ρ (its bounding radius), so the torques differ by at most the force bound × ρ. A lever
// term missing or of the wrong sign would move a torque by ρ f, about 1e-3 r_m · k_n ρ against
// 1e-14.
TEST_F(WidePath, ClumpMemberPairsGiveTheBaselinesForcesToRounding) {
  test::onEveryWideTarget([&](const std::string& target) {
    for (int threads : {1, 2}) {
      const Scene scene = clumpPile();
      const ForceGaps g = oneWideStep(scene, threads, 4000);
      double memberRadius = 0, reach = 0;
      for (const ParticleSpec& p : scene.particles) {
        for (const ClumpMember& m : p.members) {
          memberRadius = std::max(memberRadius, m.radius);
          reach = std::max(reach, m.centre.norm() + m.radius);
        }
      }
      const double forceBound = 64 * scene.material.normalStiffness * kEpsilon * 2 * memberRadius;
      EXPECT_GT(g.force, 0) << target << ": the wide path was not taken: its rounding differs from the baseline's";
      EXPECT_GT(g.largestForce, 1e6 * forceBound) << target << ": the pile is in contact: its forces are far above the bound";
      EXPECT_GT(g.largestTorque, 1e6 * forceBound * reach) << target << ": the members' contacts turn their clumps";
      EXPECT_LE(g.force, forceBound) << target << ", " << threads << " threads";
      EXPECT_LE(g.torque, forceBound * reach) << target << ", " << threads << " threads";
      EXPECT_LE(g.energy, energyBound(g, scene.material, forceBound)) << target << ", " << threads << " threads";
    }
  });
}

}  // namespace
}  // namespace grainlab

// A world's thread count may change between any two steps without changing a bit: a batch
// lends a run the cores its finished runs leave idle (studies/run_batch.hpp), half-way through.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/observer_tee.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

std::unique_ptr<World> pressedPile(const std::string& kind, WorldSettings::Engine engine = WorldSettings::Engine::Dem) {
  Scene scene = pileScene(16, 16, kind == "polygons");
  if (kind == "discs with rolling resistance") {
    scene.material.rollingFriction = 0.1;
    scene.material.rollingDamping = 0.3;
  }
  // Shuffled, neighbours' indices lie far apart: with several threads most particles straddle
  // slices of the pair list, so the plans for the thread count decide where their shares go.
  // Pressed 8% closer than the lattice under 50 g, the pile stays in contact throughout.
  std::mt19937_64 rng(7);
  std::shuffle(scene.particles.begin(), scene.particles.end(), rng);
  for (ParticleSpec& p : scene.particles) p.position *= 0.92;
  WorldSettings settings;
  settings.engine = engine;
  auto world = std::make_unique<World>(scene.material, settings);
  for (const ParticleSpec& p : scene.particles) world->addParticle(p);
  for (const Wall& w : scene.walls) world->addWall(w);
  world->setGravity(50 * scene.gravity);
  return world;
}

// Every bit of the particles' state.
std::string stateBits(const World& w) {
  std::string bits;
  auto add = [&](const auto& span) {
    bits.append(reinterpret_cast<const char*>(span.data()), span.size_bytes());
  };
  add(w.positions());
  add(w.velocities());
  add(w.angles());
  add(w.spins());
  add(w.forces());
  add(w.torques());
  return bits;
}

TEST(ThreadChange, BetweenStepsKeepsEveryBit) {
  for (const char* kind : {"discs", "polygons", "discs with rolling resistance"}) {
    std::unique_ptr<World> serial = pressedPile(kind), changing = pressedPile(kind);
    // Settled a while on one thread, the pile is in contact throughout what follows.
    for (int k = 0; k < 10000; ++k) {
      serial->step();
      changing->step();
    }
    // Then two threads, three, back to one and to two: each change replans the force loop
    // mid-run, with the pairs' state (springs, rolling) carried across.
    int fewestTouching = 1 << 30;
    for (int threads : {2, 3, 1, 2}) {
      changing->setThreads(threads);
      EXPECT_EQ(changing->threads(), threads);
      for (int k = 0; k < 1000; ++k) {
        serial->step();
        changing->step();
      }
      ASSERT_EQ(stateBits(*serial), stateBits(*changing)) << kind << ", after a stretch on " << threads << " threads";
      std::vector<ContactRecord> contacts;
      changing->contacts(contacts);
      fewestTouching = std::min(fewestTouching, static_cast<int>(contacts.size()));
    }
    // The comparison means something only if the pile is in contact throughout.
    EXPECT_GT(fewestTouching, 100) << kind;
  }
}

// An observer that lends the run one thread and notes what it stepped on.
class Lender : public RunObserver {
 public:
  explicit Lender(int lent) : lent_(lent) {}
  int threadsLent() override { return lent_; }
  void onProgress(double, std::string_view, const World& w) override { most = std::max(most, w.threads()); }
  void onFinish(const RunSummary&, const World& w) override { final = stateBits(w); }
  int most = 0;
  std::string final;

 private:
  int lent_;
};

// The run loop takes the threads it is lent, also through a tee (the most any observer was
// lent), and ends with the bits of a serial run.
TEST(ThreadChange, ARunTakesTheThreadsItIsLentThroughATee) {
  Scene scene = pileScene(16, 16, true);
  scene.stages[0].duration = 0.005;  // s: some thousands of steps, a report every 200
  Lender serial(0), quiet(0), lender(1);
  ASSERT_EQ(runScene(scene, serial).status, RunStatus::Completed);
  ObserverTee tee{&quiet, &lender};
  ASSERT_EQ(runScene(scene, tee).status, RunStatus::Completed);
  EXPECT_EQ(serial.most, 1);
  EXPECT_EQ(lender.most, 2);
  EXPECT_EQ(serial.final, lender.final);
}

TEST(ThreadChange, TheRigidBodySolverTakesAnyCountAndStaysSerial) {
  std::unique_ptr<World> serial = pressedPile("discs", WorldSettings::Engine::Box2d);
  std::unique_ptr<World> changing = pressedPile("discs", WorldSettings::Engine::Box2d);
  changing->setThreads(2);
  for (int k = 0; k < 50; ++k) {
    serial->step();
    changing->step();
  }
  EXPECT_EQ(stateBits(*serial), stateBits(*changing));
}

TEST(ThreadChange, FewerThanOneThreadIsRefusedAndChangesNothing) {
  std::unique_ptr<World> world = pressedPile("discs");
  world->setThreads(2);
  try {
    world->setThreads(0);
    FAIL() << "0 threads accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("threads"), std::string::npos) << e.what();
  }
  EXPECT_EQ(world->threads(), 2);
}

}  // namespace
}  // namespace grainlab

#include "run_manager.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <thread>

namespace grainlab::server {
namespace {

using namespace std::chrono_literals;

TEST(RunManager, RunsInArrivalOrderOneAtATime) {
  RunManager manager(1, 10);
  std::mutex m;
  std::vector<std::int64_t> order;
  std::promise<void> release;
  auto gate = release.get_future().share();
  EXPECT_EQ(manager.submit(1, [&, gate] {
              gate.wait();
              std::lock_guard l(m);
              order.push_back(1);
            }),
            RunManager::Submit::Started);
  for (std::int64_t id = 2; id <= 5; ++id)
    EXPECT_EQ(manager.submit(id, [&, id] {
                std::lock_guard l(m);
                order.push_back(id);
              }),
              RunManager::Submit::Queued);
  EXPECT_EQ(manager.queuedIds(), (std::vector<std::int64_t>{2, 3, 4, 5}));
  release.set_value();
  for (int i = 0; i < 500 && (manager.running() > 0 || manager.queued() > 0); ++i) std::this_thread::sleep_for(5ms);
  std::lock_guard l(m);
  EXPECT_EQ(order, (std::vector<std::int64_t>{1, 2, 3, 4, 5}));
}

TEST(RunManager, NeverRunsMoreThanItsLimit) {
  RunManager manager(2, 100);
  std::atomic<int> now{0}, peak{0}, done{0};
  for (int id = 1; id <= 8; ++id)
    manager.submit(id, [&] {
      const int n = ++now;
      int p = peak.load();
      while (n > p && !peak.compare_exchange_weak(p, n)) {
      }
      std::this_thread::sleep_for(10ms);
      --now;
      ++done;
    });
  for (int i = 0; i < 500 && done < 8; ++i) std::this_thread::sleep_for(5ms);
  EXPECT_EQ(done, 8);
  EXPECT_EQ(peak, 2);
}

TEST(RunManager, RefusesPastAFullQueueAndTakesQueuedWorkBack) {
  RunManager manager(1, 2);
  std::promise<void> release;
  auto gate = release.get_future().share();
  std::atomic<bool> ranRemoved{false};
  manager.submit(1, [gate] { gate.wait(); });
  EXPECT_EQ(manager.submit(2, [&] { ranRemoved = true; }), RunManager::Submit::Queued);
  EXPECT_EQ(manager.submit(3, [] {}), RunManager::Submit::Queued);
  EXPECT_EQ(manager.submit(4, [] {}), RunManager::Submit::QueueFull);
  EXPECT_TRUE(manager.removeQueued(2));
  EXPECT_FALSE(manager.removeQueued(2));
  EXPECT_FALSE(manager.removeQueued(1));  // running, not queued
  release.set_value();
  for (int i = 0; i < 500 && (manager.running() > 0 || manager.queued() > 0); ++i) std::this_thread::sleep_for(5ms);
  EXPECT_FALSE(ranRemoved);
}

TEST(RunManager, ShutdownReturnsWhatNeverStartedAndWaitsForTheRest) {
  RunManager manager(1, 10);
  std::atomic<bool> stop{false}, finished{false};
  manager.submit(1, [&] {
    while (!stop) std::this_thread::sleep_for(1ms);
    finished = true;
  });
  manager.submit(2, [] {});
  manager.submit(3, [] {});
  std::thread stopper([&] {
    std::this_thread::sleep_for(20ms);
    stop = true;
  });
  EXPECT_EQ(manager.shutdown(), (std::vector<std::int64_t>{2, 3}));
  EXPECT_TRUE(finished);
  EXPECT_EQ(manager.submit(4, [] {}), RunManager::Submit::ShuttingDown);
  stopper.join();
}

}  // namespace
}  // namespace grainlab::server

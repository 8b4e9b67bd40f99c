#pragma once
// The run queue: first in, first out, with at most `maxConcurrent` runs at once, each on its
// own worker thread. It knows nothing of scenes or storage: a run is a piece of work with an
// id, so it can be tested with plain lambdas.
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace grainlab::server {

class RunManager {
 public:
  using Work = std::function<void()>;

  /// maxConcurrent <= 0 means the machine's core count.
  RunManager(int maxConcurrent, std::size_t maxQueued);
  /// Waits for running work (see shutdown()).
  ~RunManager();
  RunManager(const RunManager&) = delete;
  RunManager& operator=(const RunManager&) = delete;

  enum class Submit { Started, Queued, QueueFull, ShuttingDown };
  /// Starts the work now if a slot is free, else queues it (unless the queue is full).
  Submit submit(std::int64_t id, Work work);
  /// Takes a queued run out of the queue; false if it is not waiting (running or unknown).
  bool removeQueued(std::int64_t id);
  /// Takes no more work and returns the ids that were still queued (they will not run), then
  /// waits for running work to return. The caller stops that work first (cancellation).
  std::vector<std::int64_t> shutdown();

  int maxConcurrent() const { return maxConcurrent_; }
  std::size_t queued() const;
  int running() const;
  /// Ids in the queue, next first.
  std::vector<std::int64_t> queuedIds() const;

 private:
  struct Job {
    std::int64_t id;
    Work work;
  };
  void startLocked(Job job);
  void finished(std::int64_t id);
  void reapLocked();

  const int maxConcurrent_;
  const std::size_t maxQueued_;
  mutable std::mutex mutex_;
  std::deque<Job> queue_;
  int running_ = 0;
  bool stopping_ = false;
  std::vector<std::pair<std::int64_t, std::thread>> threads_;
  std::vector<std::int64_t> done_;
};

}  // namespace grainlab::server

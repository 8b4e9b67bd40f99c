#pragma once
// The in-memory state of a run that is queued or running: what GET /api/runs/{id} shows
// before the database has caught up, and the flag its worker polls to stop.
#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>

#include "run_record.hpp"

namespace grainlab::server {

/// Why a run is asked to stop; it decides the status the run ends with.
enum class StopReason : int {
  None = 0,
  Cancel = 1,    ///< POST /cancel: ends `cancelled`
  Shutdown = 2,  ///< the server is stopping: ends `interrupted`
};

class LiveRun {
 public:
  explicit LiveRun(std::int64_t id) : id_(id) {}
  std::int64_t id() const { return id_; }

  /// The first reason wins: a cancelled run stays cancelled when the server then stops.
  void requestStop(StopReason reason) {
    int expected = 0;
    reason_.compare_exchange_strong(expected, static_cast<int>(reason));
    stop_.store(true, std::memory_order_relaxed);
  }
  bool stopRequested() const { return stop_.load(std::memory_order_relaxed); }
  /// DELETE: stop, and whoever ends the run removes its records instead of finishing it.
  /// Set under the service's live-runs lock, so it cannot slip past the end of the run.
  void markDeleted() {
    deleted_.store(true);
    stop_.store(true, std::memory_order_relaxed);
  }
  bool deleted() const { return deleted_.load(); }
  StopReason stopReason() const { return static_cast<StopReason>(reason_.load()); }

  struct State {
    RunStatus status = RunStatus::Queued;
    std::string stage;
    double progress = 0;
    std::int64_t steps = 0;
    int particles = 0;
    std::optional<double> startedAt;
    std::string error;  ///< why it ended failed or interrupted (once it has ended)
  };
  State state() const {
    std::lock_guard lock(mutex_);
    return state_;
  }
  template <class F>
  void update(F&& change) {
    std::lock_guard lock(mutex_);
    change(state_);
  }

 private:
  const std::int64_t id_;
  std::atomic<bool> stop_{false};
  std::atomic<int> reason_{0};
  std::atomic<bool> deleted_{false};
  mutable std::mutex mutex_;
  State state_;
};

}  // namespace grainlab::server

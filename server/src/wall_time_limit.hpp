#pragma once
// Observers that stop a run for the server, watched beside the run's other observers; each
// remembers that it did, so the run can end `failed` with the reason. The wall-time limit
// (grainlab serve --max-run-seconds) asks the run to stop once it has gone on longer than the
// limit (a clean stop: its checkpoint is written, so it can be resumed by someone who means
// it); DatabaseWatch cancels it once its outputs can no longer be stored.
#include <chrono>
#include <cstdint>

#include "grainlab/run.hpp"
#include "repository.hpp"

namespace grainlab::server {

class WallTimeLimit : public RunObserver {
 public:
  explicit WallTimeLimit(double seconds) : seconds_(seconds) {}
  void onStart(const Scene&, const World&) override { start_ = Clock::now(); }
  bool stopRequested() override {
    if (std::chrono::duration<double>(Clock::now() - start_).count() > seconds_) exceeded_ = true;
    return exceeded_;
  }
  bool exceeded() const { return exceeded_; }
  double seconds() const { return seconds_; }

 private:
  using Clock = std::chrono::steady_clock;
  double seconds_;
  Clock::time_point start_ = Clock::now();
  bool exceeded_ = false;
};

/// Stops a run once a write to the database has failed since it started (a full disk): it
/// would go on computing what can no longer be stored, and its end would not be stored
/// either. The run then ends `failed` with the database's reason.
class DatabaseWatch : public RunObserver {
 public:
  explicit DatabaseWatch(const Repository& repo) : repo_(repo), before_(repo.writeFailures()) {}
  bool cancelRequested() override { return failed(); }
  bool failed() const { return repo_.writeFailures() != before_; }

 private:
  const Repository& repo_;
  std::uint64_t before_;
};

}  // namespace grainlab::server

#pragma once
// The server's wall-time limit on a run (grainlab serve --max-run-seconds): watched beside the
// run's other observers, it asks the run to stop once the run has gone on longer than the
// limit (a clean stop: its checkpoint is written, so it can be resumed by someone who means
// it), and remembers that it did, so the run can end `failed` with the reason.
#include <chrono>

#include "grainlab/run.hpp"

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

}  // namespace grainlab::server

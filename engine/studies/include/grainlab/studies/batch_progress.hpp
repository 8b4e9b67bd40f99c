#pragma once
// Progress of a batch on one line per event: runs done / total, running, failed, and the
// time left, estimated from the work done so far (finished runs plus the finished fraction
// of the runs in this process) at the rate it was done.
#include <chrono>
#include <mutex>
#include <ostream>
#include <string>

#include "grainlab/run_status.hpp"
#include <vector>

namespace grainlab::studies {

class BatchProgress {
 public:
  /// `toRun` runs will run now; `reused` were completed before and are counted as done.
  BatchProgress(std::ostream* out, std::string label, size_t toRun, size_t reused);
  void started(const std::string& id);
  /// A running run's own progress in [0, 1]; lines for these are at most every few seconds.
  void advanced(const std::string& id, double fraction);
  /// `threadsLent`: the most threads it ran on beyond its own (cores lent once the queue emptied).
  void finished(const std::string& id, RunStatus status, double wallSeconds, int threadsLent = 0);

 private:
  void print(const std::string& event);  // with mutex_ held
  std::ostream* out_;
  std::string label_;
  size_t toRun_, reused_;
  size_t done_ = 0, failed_ = 0;
  std::vector<std::pair<std::string, double>> running_;  // id, fraction
  std::chrono::steady_clock::time_point start_, lastLine_;
  std::mutex mutex_;
};

/// "3 min", "42 s", "1.5 h".
std::string formatDuration(double seconds);

}  // namespace grainlab::studies

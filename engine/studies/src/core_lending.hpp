#pragma once
// Inside runBatch: the batch's cores once it has no run left to start. A worker that finds the
// queue empty gives up its core, and a run that ends gives up its own and those it borrowed;
// each idle core goes, at a running run's next progress report, to the run expected to finish
// last. A run's results do not depend on its thread count (World::setThreads), so lending
// changes only how soon the batch ends: without it, the last run of a batch of six on two
// cores runs alone on one while the other idles.
#include <chrono>
#include <map>
#include <mutex>
#include <string>

namespace grainlab::studies {

class CoreLending {
 public:
  using Clock = std::chrono::steady_clock;

  /// `id` began on its worker's core.
  void started(const std::string& id);
  /// `id` has done `fraction` of its work; it may be lent an idle core now (see threadsLent).
  void advanced(const std::string& id, double fraction);
  /// The extra threads `id` holds now (0 if none, or if it is not running).
  int threadsLent(const std::string& id) const;
  /// `id` ended: returns how many cores it held at most beyond its own. Its own core goes back
  /// to its worker; the ones it held now go to the other runs.
  int finished(const std::string& id);
  /// `cores` cores that no run will start on (a worker with an empty queue, or more jobs
  /// than runs), for the running runs.
  void release(int cores);
  /// Cores waiting for a running run to take them.
  int idleCores() const;

 private:
  struct Running {
    Clock::time_point start;
    double fraction = 0;
    int lent = 0;     // held now
    int mostLent = 0;
  };
  // The running run expected to finish last at its pace so far: its time left, elapsed ×
  // (1 − f) / f, divided among the threads it holds. A run that has not yet reported comes
  // first: all of its work is ahead of it. Null if none runs.
  const std::string* neediest() const;

  mutable std::mutex mutex_;
  std::map<std::string, Running> running_;
  int idle_ = 0;
};

}  // namespace grainlab::studies

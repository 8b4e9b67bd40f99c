#pragma once
// Progress of several runs going on at once, as lines on one stream (stderr): each run's
// name, percentage and stage every 10 %, and a line when it ends. Safe to call from any thread.
#include <chrono>
#include <mutex>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab::report {

class ProgressBoard {
 public:
  /// `out` may be null (silent). `names` are the runs, in the order of their indices.
  ProgressBoard(std::ostream* out, std::vector<std::string> names);
  /// Run `index` is at `fraction` (0..1) of its work, in stage `stage`.
  void update(size_t index, double fraction, std::string_view stage);
  /// Run `index` ended with `status` after `wallSeconds` (s).
  void finished(size_t index, std::string_view status, double wallSeconds);
  /// A free line (e.g. "writing the report").
  void note(std::string_view text);

 private:
  std::ostream* out_;
  std::vector<std::string> names_;
  std::vector<int> lastDecile_;
  size_t done_ = 0;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double elapsed() const;
};

}  // namespace grainlab::report

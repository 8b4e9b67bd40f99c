#pragma once
// Slows a guesser: after `maxFailures` wrong tokens from one address within a window of
// `window`, that address is answered 429 until the window ends (counted from its first
// failure). An absent token is no failure: only guesses count.
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>

namespace grainlab::server {

struct FailureLimits {
  int maxFailures = 10;
  std::chrono::seconds window{60};
  std::size_t maxAddresses = 4096;  ///< addresses remembered at once; the oldest windows go first
};

class FailureLimiter {
 public:
  using Clock = std::chrono::steady_clock;
  using Limits = FailureLimits;

  explicit FailureLimiter(Limits limits = {}) : limits_(limits) {}

  /// Seconds until `address` may try again; 0 if it may now.
  long blockedFor(std::string_view address, Clock::time_point now);
  void recordFailure(std::string_view address, Clock::time_point now);

 private:
  struct Window {
    Clock::time_point start;
    int failures = 0;
  };
  void forgetExpired(Clock::time_point now);

  Limits limits_;
  std::mutex mutex_;
  std::unordered_map<std::string, Window> windows_;
};

}  // namespace grainlab::server

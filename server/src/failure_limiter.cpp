#include "failure_limiter.hpp"

#include <algorithm>

namespace grainlab::server {

long FailureLimiter::blockedFor(std::string_view address, Clock::time_point now) {
  std::lock_guard lock(mutex_);
  const auto it = windows_.find(std::string(address));
  if (it == windows_.end()) return 0;
  const auto end = it->second.start + limits_.window;
  if (now >= end) {
    windows_.erase(it);
    return 0;
  }
  if (it->second.failures < limits_.maxFailures) return 0;
  const auto left = std::chrono::ceil<std::chrono::seconds>(end - now).count();
  return std::max<long>(1, static_cast<long>(left));
}

void FailureLimiter::recordFailure(std::string_view address, Clock::time_point now) {
  std::lock_guard lock(mutex_);
  auto it = windows_.find(std::string(address));
  if (it != windows_.end() && now >= it->second.start + limits_.window) {
    windows_.erase(it);
    it = windows_.end();
  }
  if (it == windows_.end()) {
    if (windows_.size() >= limits_.maxAddresses) forgetExpired(now);
    // Still full of live windows: drop the oldest, so memory stays bounded under a flood of
    // addresses (a flood that can only lose its own windows early).
    if (windows_.size() >= limits_.maxAddresses) {
      windows_.erase(std::min_element(windows_.begin(), windows_.end(), [](const auto& a, const auto& b) {
        return a.second.start < b.second.start;
      }));
    }
    it = windows_.emplace(std::string(address), Window{now, 0}).first;
  }
  ++it->second.failures;
}

void FailureLimiter::forgetExpired(Clock::time_point now) {
  std::erase_if(windows_, [&](const auto& entry) { return now >= entry.second.start + limits_.window; });
}

}  // namespace grainlab::server

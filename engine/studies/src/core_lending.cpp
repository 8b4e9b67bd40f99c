#include "core_lending.hpp"

#include <algorithm>
#include <limits>

namespace grainlab::studies {

void CoreLending::started(const std::string& id) {
  std::lock_guard lock(mutex_);
  running_[id] = Running{Clock::now(), 0, 0, 0};
}

void CoreLending::advanced(const std::string& id, double fraction) {
  std::lock_guard lock(mutex_);
  const auto it = running_.find(id);
  if (it == running_.end()) return;
  it->second.fraction = fraction;
  // One core per report: each lands where the time left is longest as the loans change it.
  if (idle_ == 0) return;
  if (const std::string* target = neediest(); target && *target == id) {
    Running& r = it->second;
    ++r.lent;
    r.mostLent = std::max(r.mostLent, r.lent);
    --idle_;
  }
}

int CoreLending::threadsLent(const std::string& id) const {
  std::lock_guard lock(mutex_);
  const auto it = running_.find(id);
  return it == running_.end() ? 0 : it->second.lent;
}

int CoreLending::finished(const std::string& id) {
  std::lock_guard lock(mutex_);
  const auto it = running_.find(id);
  if (it == running_.end()) return 0;
  const Running r = it->second;
  running_.erase(it);
  idle_ += r.lent;
  return r.mostLent;
}

void CoreLending::release(int cores) {
  std::lock_guard lock(mutex_);
  idle_ += std::max(0, cores);
}

int CoreLending::idleCores() const {
  std::lock_guard lock(mutex_);
  return idle_;
}

const std::string* CoreLending::neediest() const {
  const std::string* best = nullptr;
  double longest = -1;
  const Clock::time_point now = Clock::now();
  for (const auto& [id, r] : running_) {
    const double elapsed = std::chrono::duration<double>(now - r.start).count();
    const double left = r.fraction > 0 ? elapsed * (1 - r.fraction) / r.fraction / (1 + r.lent)
                                       : std::numeric_limits<double>::infinity();
    if (left > longest) {
      longest = left;
      best = &id;
    }
  }
  return best;
}

}  // namespace grainlab::studies

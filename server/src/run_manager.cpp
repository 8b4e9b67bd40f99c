#include "run_manager.hpp"

#include <algorithm>

namespace grainlab::server {

RunManager::RunManager(int maxConcurrent, std::size_t maxQueued)
    : maxConcurrent_(maxConcurrent > 0
                         ? maxConcurrent
                         : std::max(1, static_cast<int>(std::thread::hardware_concurrency()))),
      maxQueued_(maxQueued) {}

RunManager::~RunManager() { shutdown(); }

RunManager::Submit RunManager::submit(std::int64_t id, Work work) {
  std::lock_guard lock(mutex_);
  if (stopping_) return Submit::ShuttingDown;
  reapLocked();
  if (running_ < maxConcurrent_ && queue_.empty()) {
    startLocked({id, std::move(work)});
    return Submit::Started;
  }
  if (queue_.size() >= maxQueued_) return Submit::QueueFull;
  queue_.push_back({id, std::move(work)});
  return Submit::Queued;
}

bool RunManager::removeQueued(std::int64_t id) {
  std::lock_guard lock(mutex_);
  auto it = std::find_if(queue_.begin(), queue_.end(), [id](const Job& j) { return j.id == id; });
  if (it == queue_.end()) return false;
  queue_.erase(it);
  return true;
}

void RunManager::startLocked(Job job) {
  ++running_;
  const auto id = job.id;
  threads_.emplace_back(id, std::thread([this, job = std::move(job)] {
                          job.work();
                          finished(job.id);
                        }));
}

void RunManager::finished(std::int64_t id) {
  std::lock_guard lock(mutex_);
  --running_;
  // A thread cannot join itself: the next submit or shutdown joins it.
  done_.push_back(id);
  if (!stopping_ && !queue_.empty()) {
    Job next = std::move(queue_.front());
    queue_.pop_front();
    startLocked(std::move(next));
  }
}

void RunManager::reapLocked() {
  for (auto id : done_) {
    auto it = std::find_if(threads_.begin(), threads_.end(),
                           [id](const auto& t) { return t.first == id; });
    if (it != threads_.end()) {
      it->second.join();
      threads_.erase(it);
    }
  }
  done_.clear();
}

std::vector<std::int64_t> RunManager::shutdown() {
  std::vector<std::int64_t> dropped;
  std::vector<std::pair<std::int64_t, std::thread>> threads;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    for (auto& job : queue_) dropped.push_back(job.id);
    queue_.clear();
    threads = std::move(threads_);
    threads_.clear();
    done_.clear();
  }
  for (auto& [id, thread] : threads) thread.join();
  return dropped;
}

std::size_t RunManager::queued() const {
  std::lock_guard lock(mutex_);
  return queue_.size();
}

int RunManager::running() const {
  std::lock_guard lock(mutex_);
  return running_;
}

std::vector<std::int64_t> RunManager::queuedIds() const {
  std::lock_guard lock(mutex_);
  std::vector<std::int64_t> ids;
  for (const auto& job : queue_) ids.push_back(job.id);
  return ids;
}

}  // namespace grainlab::server

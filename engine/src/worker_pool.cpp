#include "worker_pool.hpp"

namespace grainlab {

WorkerPool::WorkerPool(int threads) {
  for (int k = 1; k < threads; ++k) workers_.emplace_back([this, k] { work(k); });
}

WorkerPool::~WorkerPool() {
  stop_.store(true);
  generation_.fetch_add(1);
  generation_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void WorkerPool::parallelFor(int n, const std::function<void(int, int)>& body) {
  const int t = threads();
  if (t == 1) {
    body(0, n);
    return;
  }
  body_ = &body;
  n_ = n;
  pending_.store(t - 1);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  body(0, n / t);  // the caller's slice
  int left;
  while ((left = pending_.load(std::memory_order_acquire)) != 0) pending_.wait(left);
}

void WorkerPool::work(int index) {
  unsigned seen = 0;
  while (true) {
    generation_.wait(seen);
    seen = generation_.load(std::memory_order_acquire);
    if (stop_.load()) return;
    const int t = threads();
    const int begin = static_cast<int>(static_cast<long long>(n_) * index / t);
    const int end = static_cast<int>(static_cast<long long>(n_) * (index + 1) / t);
    (*body_)(begin, end);
    if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) pending_.notify_one();
  }
}

}  // namespace grainlab

#include "worker_pool.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace grainlab {
namespace {

// A step's parallel phases last tens of µs, and waking a sleeping thread costs about as
// much. So a thread that waits first spins for a while (about 10-100 µs), and only then
// sleeps on the futex: on an idle core the hand-over is then a cache-line transfer; on an
// oversubscribed machine the spin ends soon and gives the core back.
constexpr int kSpins = 2000;  // a pause is 10-140 cycles, depending on the CPU

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

template <class T, class Done>
void spinThenWait(const std::atomic<T>& value, T old, Done done) {
  for (int k = 0; k < kSpins; ++k) {
    if (done()) return;
    relax();
  }
  while (!done()) value.wait(old, std::memory_order_acquire);
}

}  // namespace

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
  pending_.store(t - 1, std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  body(0, sliceBegin(n, 1, t));  // the caller's slice
  for (;;) {
    const int left = pending_.load(std::memory_order_acquire);
    if (left == 0) break;
    spinThenWait(pending_, left, [&] { return pending_.load(std::memory_order_acquire) != left; });
  }
}

void WorkerPool::work(int index) {
  unsigned seen = 0;
  while (true) {
    spinThenWait(generation_, seen, [&] { return generation_.load(std::memory_order_acquire) != seen; });
    seen = generation_.load(std::memory_order_acquire);
    if (stop_.load()) return;
    const int t = threads();
    (*body_)(sliceBegin(n_, index, t), sliceBegin(n_, index + 1, t));
    if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) pending_.notify_one();
  }
}

}  // namespace grainlab

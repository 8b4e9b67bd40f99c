#pragma once
// A fixed set of worker threads that run one parallel loop at a time: the step's phases are
// short (tens of µs), so threads are kept, not spawned, and wait on an atomic generation.
#include <atomic>
#include <functional>
#include <thread>
#include <vector>

namespace grainlab {

class WorkerPool {
 public:
  /// `threads` counts the calling thread: 1 runs everything inline.
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }
  /// Calls body(begin, end) on `threads()` contiguous slices of [0, n) and returns when all
  /// are done. The slicing depends only on n and threads(), never on timing.
  void parallelFor(int n, const std::function<void(int, int)>& body);
  /// Where parallelFor's slice `index` of [0, n) begins (slice `slices` begins at n), so a
  /// caller can plan around the slicing before the loop runs.
  static int sliceBegin(int n, int index, int slices) {
    return static_cast<int>(static_cast<long long>(n) * index / slices);
  }

 private:
  void work(int index);
  std::vector<std::thread> workers_;
  const std::function<void(int, int)>* body_ = nullptr;
  int n_ = 0;
  std::atomic<unsigned> generation_{0};
  std::atomic<int> pending_{0};
  std::atomic<bool> stop_{false};
};

}  // namespace grainlab

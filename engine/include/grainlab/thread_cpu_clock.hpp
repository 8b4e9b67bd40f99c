#pragma once
// CPU time of the calling thread: unlike wall time, not inflated by other programs on a
// shared machine, nor by waiting. A run's wall time over it shows what waiting cost it.
#include <ctime>

namespace grainlab {

inline double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace grainlab

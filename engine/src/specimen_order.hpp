#pragma once
// The order in which a specimen numbers its particles: along space, in horizontal bands two
// mean spacings tall, each band read in the direction the last one ended (a serpentine), so
// that particles near each other get nearby indices. The neighbour list keeps its pairs in
// index order and threads take contiguous slices of it, so with this order a thread's pairs
// mostly touch its own particles; numbered in the random order of placement, every phase of
// a step moved the particles' lines between the cores, and a second thread gained little or
// lost (docs/benchmarks.md, "Particles numbered along space").
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

#include "grainlab/math.hpp"

namespace grainlab::specimen {

/// The indices of `centres` (m) in the order to number them; `spacing` (m) is the particles'
/// mean distance, which sets the bands' height. Depends only on the centres: the same
/// specimen is numbered the same way on any machine.
inline std::vector<std::size_t> orderAlongSpace(const std::vector<Vec2>& centres, double spacing) {
  const double band = 2 * spacing;
  std::vector<long> row(centres.size());
  for (std::size_t i = 0; i < centres.size(); ++i) row[i] = std::lround(std::floor(centres[i].y() / band));
  std::vector<std::size_t> order(centres.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (row[a] != row[b]) return row[a] < row[b];
    const bool rightward = row[a] % 2 == 0;
    return rightward ? centres[a].x() < centres[b].x() : centres[a].x() > centres[b].x();
  });
  return order;
}

}  // namespace grainlab::specimen

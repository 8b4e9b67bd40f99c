// How far apart in index each particle of a specimen is from its nearest neighbour in space:
// what a numbering along space keeps small (engine/src/specimen_order.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "grainlab/specimen.hpp"

namespace grainlab::test {

/// |i − j| for each particle i and its nearest neighbour j (the straight distance between
/// centres, not across a periodic cell's edges), sorted ascending.
inline std::vector<double> sortedNeighbourIndexGaps(std::span<const ParticleSpec> particles) {
  const size_t n = particles.size();
  std::vector<double> gaps;
  for (size_t i = 0; i < n; ++i) {
    size_t nearest = i;
    double best = 1e300;
    for (size_t j = 0; j < n; ++j) {
      const double d = (particles[j].position - particles[i].position).squaredNorm();
      if (j != i && d < best) {
        best = d;
        nearest = j;
      }
    }
    gaps.push_back(std::abs(static_cast<double>(nearest) - static_cast<double>(i)));
  }
  std::sort(gaps.begin(), gaps.end());
  return gaps;
}

}  // namespace grainlab::test

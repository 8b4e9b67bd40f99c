#pragma once
// How many specimen particles lie outside the polygon of the ring's centres (ray casting):
// a loading boundary must hold its specimen in, whatever path it follows.
#include <algorithm>
#include <cmath>
#include <vector>

#include "grainlab/world.hpp"

namespace grainlab::testing {

inline int particlesOutsideRing(const World& world) {
  std::vector<Vec2> ring;
  Vec2 centre = Vec2::Zero();
  for (int k = 0; k < world.size(); ++k) {
    if (world.boundaryFlags()[k]) ring.push_back(world.positions()[k]), centre += world.positions()[k];
  }
  centre /= static_cast<double>(ring.size());
  std::sort(ring.begin(), ring.end(), [&](const Vec2& a, const Vec2& b) {
    return std::atan2(a.y() - centre.y(), a.x() - centre.x()) < std::atan2(b.y() - centre.y(), b.x() - centre.x());
  });
  int outside = 0;
  for (int k = 0; k < world.size(); ++k) {
    if (world.boundaryFlags()[k]) continue;
    const Vec2& p = world.positions()[k];
    bool inside = false;
    for (size_t a = 0, b = ring.size() - 1; a < ring.size(); b = a++) {
      if ((ring[a].y() > p.y()) != (ring[b].y() > p.y()) &&
          p.x() < (ring[b].x() - ring[a].x()) * (p.y() - ring[a].y()) / (ring[b].y() - ring[a].y()) + ring[a].x()) {
        inside = !inside;
      }
    }
    outside += inside ? 0 : 1;
  }
  return outside;
}

}  // namespace grainlab::testing

#include "specimen_ring.hpp"

#include <algorithm>
#include <cmath>

namespace grainlab::specimen {

double ringWidestStretch(double initialRadius, const RingPath& path) {
  const double shrink = path.consolidatedRadius / initialRadius;
  return std::max(1.0, shrink * (1 + path.lateralExtension));
}

int ringDiscCount(double initialRadius, double discRadius, const RingPath& path) {
  // Neighbouring centres are a chord 2R·sin(π/M) apart; stretched by S it must stay within
  // (1 − overlap)·2r.
  const double widest = ringWidestStretch(initialRadius, path) * initialRadius;
  const double allowed = (1 - kRingOverlap) * discRadius;
  int count = 8;
  if (allowed < widest) count = std::max(count, static_cast<int>(std::ceil(kPi / std::asin(allowed / widest))));
  // The ceiling can be one short after rounding: step up until the chord really fits.
  while (2 * widest * std::sin(kPi / count) > 2 * allowed) ++count;
  return count;
}

double largestRingGap(std::span<const ParticleSpec> ring, const Eigen::Matrix2d& deformation) {
  double gap = -INFINITY;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const ParticleSpec& a = ring[k];
    const ParticleSpec& b = ring[(k + 1) % ring.size()];
    const Vec2 chord = deformation * (b.position - a.position);
    gap = std::max(gap, chord.norm() - a.radius - b.radius);
  }
  return gap;
}

bool ringRetains(std::span<const ParticleSpec> ring, const Eigen::Matrix2d& deformation, double smallestWidth) {
  return largestRingGap(ring, deformation) < smallestWidth;
}

}  // namespace grainlab::specimen

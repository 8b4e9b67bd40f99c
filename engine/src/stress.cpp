// Contact (Love-Weber) stress: σ_ab = (1/A) Σ_ends f_a l_b, force index first (micromechanics.md).
#include "grainlab/stress.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace grainlab {

double StressTensor::q() const {
  // Symmetric part only: the antisymmetric σ12 − σ21 is a moment imbalance, not a deviator.
  return std::hypot(0.5 * (s11 - s22), 0.5 * (s12 + s21));
}

StressTensor contactStress(std::span<const ContactRecord> contacts,
                           std::span<const Vec2> centroids,
                           std::span<const unsigned char> inside, double area, const PeriodicCell* cell) {
  if (!(area > 0) || !std::isfinite(area))
    throw std::invalid_argument("contactStress: area must be positive and finite, got " +
                                std::to_string(area));
  if (inside.size() != centroids.size())
    throw std::invalid_argument("contactStress: inside has " + std::to_string(inside.size()) +
                                " entries but centroids has " + std::to_string(centroids.size()));
  const auto n = static_cast<long long>(centroids.size());

  double s11 = 0, s12 = 0, s21 = 0, s22 = 0;
  auto add = [&](const Vec2& f, const Vec2& branch) {
    const Vec2 l = cell ? cell->minimumImage(branch) : branch;
    s11 += f.x() * l.x();
    s12 += f.x() * l.y();
    s21 += f.y() * l.x();
    s22 += f.y() * l.y();
  };
  for (const ContactRecord& c : contacts) {
    if (c.i < 0 || c.i >= n || c.j >= n)
      throw std::out_of_range("contactStress: contact (" + std::to_string(c.i) + ", " +
                              std::to_string(c.j) + ") names a particle outside 0.." +
                              std::to_string(n - 1));
    // The force particle i exerts on its neighbour; j exerts the opposite one on i.
    const Vec2 f = c.fn * c.normal + c.ft * perp(c.normal);
    if (inside[static_cast<size_t>(c.i)] != 0) add(f, c.point - centroids[static_cast<size_t>(c.i)]);
    // A wall has no centroid and is not part of the specimen: only particle i's end counts.
    if (!c.isWall() && inside[static_cast<size_t>(c.j)] != 0)
      add(-f, c.point - centroids[static_cast<size_t>(c.j)]);
  }
  const double inv = 1.0 / area;
  return StressTensor{s11 * inv, s12 * inv, s21 * inv, s22 * inv};
}

}  // namespace grainlab

// What the wide-path tests share: whether this build has the wide path, and the polygons
// the polygon kernels' tests measure.
#pragma once

#include <cmath>
#include <vector>

#include "grainlab/math.hpp"
#include "grainlab/shape.hpp"
#include "grainlab/simd_path.hpp"

namespace grainlab::test {

/// True when this build has the wide path (not GRAINLAB_SIMD=OFF); leaves the choice as it was.
inline bool wideSimdBuilt() {
  overrideSimdPath(SimdPath::Wide);
  const bool built = simdPath() == SimdPath::Wide;
  overrideSimdPath(std::nullopt);
  return built;
}

/// A hexagon inscribed in an ellipse of aspect ratio 1.5, as the specimens' particles are.
inline Polygon ellipseHexagon(double longAxis) {
  std::vector<Vec2> v;
  const double a = 0.5 * longAxis, b = a / 1.5;
  for (int k = 0; k < 6; ++k) v.emplace_back(a * std::cos(k * kPi / 3), b * std::sin(k * kPi / 3));
  return makePolygon(v);
}

/// A regular polygon of `corners` corners on a circle of `radius`.
inline Polygon regularPolygon(int corners, double radius) {
  std::vector<Vec2> v;
  for (int k = 0; k < corners; ++k)
    v.emplace_back(radius * std::cos(2 * kPi * k / corners), radius * std::sin(2 * kPi * k / corners));
  return makePolygon(v);
}

}  // namespace grainlab::test

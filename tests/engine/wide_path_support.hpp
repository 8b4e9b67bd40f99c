// What the wide-path tests share: whether this build has the wide path, each of its
// instruction sets in turn, a bitwise comparison, a world built from a scene, and the polygons
// the polygon kernels' tests measure.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#ifdef GRAINLAB_TEST_EVERY_HWY_TARGET  // tests/CMakeLists.txt: tests that link Highway
#include <hwy/targets.h>
#endif

#include "grainlab/math.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/shape.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/world.hpp"

namespace grainlab::test {

/// True when this build has the wide path (not GRAINLAB_SIMD=OFF); leaves the choice as it was.
inline bool wideSimdBuilt() {
  overrideSimdPath(SimdPath::Wide);
  const bool built = simdPath() == SimdPath::Wide;
  overrideSimdPath(std::nullopt);
  return built;
}

/// Calls f(target name) on the wide path with every instruction set this build compiled that
/// the CPU has (HWY_SCALAR to AVX-512: vectors of 1, 2, 4 and 8 doubles), each forced in turn,
/// where the test links Highway; otherwise with the one dispatch picks. Leaves the choice as it was.
template <class F>
void onEveryWideTarget(const F& f) {
  overrideSimdPath(SimdPath::Wide);
#ifdef GRAINLAB_TEST_EVERY_HWY_TARGET
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    const std::string name = simdTargetName();
    if (name != hwy::TargetName(target)) ADD_FAILURE() << "dispatch chose " << name << ", not the forced " << hwy::TargetName(target);
    f(name);
  }
  hwy::SetSupportedTargetsForTest(0);
#else
  f(simdTargetName());
#endif
  overrideSimdPath(std::nullopt);
}

/// True when the two arrays hold the same bits (not only equal values: −0 is not +0).
template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

/// A world of the scene's particles and walls under its gravity (the tests build one per path).
inline std::unique_ptr<World> worldOf(const Scene& scene, const WorldSettings& settings) {
  auto w = std::make_unique<World>(scene.material, settings);
  for (const ParticleSpec& p : scene.particles) w->addParticle(p);
  for (const Wall& wall : scene.walls) w->addWall(wall);
  w->setGravity(scene.gravity);
  return w;
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

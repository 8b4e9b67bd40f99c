#pragma once
// Small builders shared by the engine tests.
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/world.hpp"

namespace grainlab::test {

/// A pile of columns × rows discs or polygons (pileScene), shuffled with `seed` so that no
/// particle order follows space, its positions drawn together by 0.85 so that neighbours
/// overlap from the start, and pressed under 50 g.
inline Scene pressedPile(int columns, int rows, bool polygons, std::uint64_t seed) {
  Scene scene = pileScene(columns, rows, polygons);
  std::mt19937_64 rng(seed);
  std::shuffle(scene.particles.begin(), scene.particles.end(), rng);
  for (ParticleSpec& p : scene.particles) p.position *= 0.85;
  scene.gravity *= 50;
  return scene;
}

inline ParticleSpec disc(double r, Vec2 x, Vec2 v = Vec2::Zero(), double spin = 0) {
  ParticleSpec p;
  p.shape = ShapeKind::Disc;
  p.radius = r;
  p.position = x;
  p.velocity = v;
  p.spin = spin;
  return p;
}

/// A w × h rectangle centred on x.
inline ParticleSpec box(double w, double h, Vec2 x, double angle = 0) {
  ParticleSpec p;
  p.shape = ShapeKind::Polygon;
  p.vertices = {{-w / 2, -h / 2}, {w / 2, -h / 2}, {w / 2, h / 2}, {-w / 2, h / 2}};
  p.position = x;
  p.angle = angle;
  return p;
}

inline Material material(double kn, double e, double mu, double kt = -1) {
  Material m;
  m.density = 2650;
  m.normalStiffness = kn;
  m.tangentialStiffness = kt < 0 ? 0.5 * kn : kt;
  m.restitution = e;
  m.friction = mu;
  m.localDamping = 0;
  return m;
}

/// n × n discs on a square lattice 2% tighter than their diameters (every neighbour
/// overlaps), boxed by four walls, with seeded random velocities up to ±0.025 m/s: a dense,
/// jammed, vibrating packing.
inline std::vector<ParticleSpec> jammedLattice(int n, std::vector<Wall>& walls) {
  const double r = 0.002, spacing = 2 * r * 0.98;
  std::uint64_t state = 7;
  auto uniform = [&] {  // splitmix64: the same numbers with any standard library
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53 - 0.5;
  };
  std::vector<ParticleSpec> particles;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      particles.push_back(disc(r * (1 + 0.02 * uniform()), {i * spacing, j * spacing},
                               {0.05 * uniform(), 0.05 * uniform()}));
    }
  }
  const double lo = -r * 0.98, hi = (n - 1) * spacing + r * 0.98;
  walls = {Wall{Vec2(lo, 0), Vec2(1, 0)}, Wall{Vec2(hi, 0), Vec2(-1, 0)}, Wall{Vec2(0, lo), Vec2(0, 1)},
           Wall{Vec2(0, hi), Vec2(0, -1)}};
  return particles;
}

}  // namespace grainlab::test

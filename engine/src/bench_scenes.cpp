#include "grainlab/bench_scenes.hpp"

#include <cmath>
#include <random>

namespace grainlab {

Scene pileScene(int columns, int rows, bool polygons, std::uint64_t seed) {
  Scene scene;
  scene.name = polygons ? "polygon-pile" : "disc-pile";
  scene.seed = seed;
  scene.material.normalStiffness = 3e8;
  scene.material.tangentialStiffness = 1.5e8;
  scene.material.restitution = 0.5;
  scene.material.friction = 0.5;
  scene.gravity = Vec2(0, -9.81);
  std::mt19937_64 rng(seed);
  auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const double r = 0.002, spacing = 2.25 * r * (polygons ? 1.25 : 1.0);
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col < columns; ++col) {
      ParticleSpec p;
      p.position = Vec2((col + 0.5 * (row % 2)) * spacing, (row + 0.6) * spacing);
      const double size = r * (0.9 + 0.2 * uniform());
      if (polygons) {
        p.shape = ShapeKind::Polygon;
        const double a = 1.25 * size, b = a / 1.5;
        for (int k = 0; k < 6; ++k) {
          const double t = k * kPi / 3;
          p.vertices.emplace_back(a * std::cos(t), b * std::sin(t));
        }
        p.angle = kPi * uniform();
      } else {
        p.radius = size;
      }
      scene.particles.push_back(p);
    }
  }
  const double width = (columns + 0.5) * spacing;
  scene.walls = {Wall{Vec2(0, 0), Vec2(0, 1)}, Wall{Vec2(-0.5 * spacing, 0), Vec2(1, 0)},
                 Wall{Vec2(width, 0), Vec2(-1, 0)}};
  StageSpec settle;
  settle.name = "settling";
  settle.duration = 0.3;  // s: long enough for both piles to come to rest
  scene.stages = {settle};
  return scene;
}

Scene clumpPileScene(int columns, int rows, std::uint64_t seed) {
  Scene scene = pileScene(columns, rows, true, seed);
  scene.name = "clump-pile";
  std::mt19937_64 rng(seed + 1);
  auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  for (ParticleSpec& p : scene.particles) {
    const double size = 0.002 * (0.9 + 0.2 * uniform());
    p.shape = ShapeKind::Clump;
    p.vertices.clear();
    p.members = {{Vec2(-0.75 * size, 0), 0.5 * size}, {Vec2(0, 0), 0.5 * size}, {Vec2(0.75 * size, 0), 0.5 * size}};
  }
  return scene;
}

Scene periodicPileScene(int columns, int rows, std::uint64_t seed) {
  Scene scene = pileScene(columns, rows, false, seed);
  scene.name = "periodic-pile";
  const double spacing = 2.25 * 0.002;  // pileScene's
  scene.walls.clear();
  scene.gravity = Vec2::Zero();
  scene.boundary.type = BoundarySpec::Type::Periodic;
  scene.boundary.cellSize = Vec2(columns * spacing, rows * spacing);
  return scene;
}

}  // namespace grainlab

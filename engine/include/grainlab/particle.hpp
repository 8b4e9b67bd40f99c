#pragma once
// What a scene says about one particle, before it enters the World.
#include <vector>

#include "grainlab/clump.hpp"
#include "grainlab/math.hpp"
#include "grainlab/shape.hpp"

namespace grainlab {

/// How a particle moves.
enum class Motion : unsigned char {
  Dynamic = 0,    ///< integrated from the forces on it
  Fixed = 1,      ///< never moves
  Kinematic = 2,  ///< moves with a prescribed velocity and spin; forces do not move it
};

struct ParticleSpec {
  ShapeKind shape = ShapeKind::Disc;
  double radius = 0;              ///< disc radius, m (discs only)
  std::vector<Vec2> vertices;     ///< polygon vertices relative to `position`, m (polygons only)
  std::vector<ClumpMember> members;  ///< member discs relative to `position`, m (clumps only)
  Vec2 position = Vec2::Zero();   ///< m; for polygons the reference point of `vertices`
  double angle = 0;               ///< rad, counter-clockwise
  Vec2 velocity = Vec2::Zero();   ///< m/s
  double spin = 0;                ///< rad/s
  Motion motion = Motion::Dynamic;
  bool boundary = false;          ///< part of the loading boundary (membrane ring), not the specimen
};

}  // namespace grainlab

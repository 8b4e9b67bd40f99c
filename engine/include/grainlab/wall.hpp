#pragma once
#include "grainlab/math.hpp"

namespace grainlab {

/// A static half-plane: solid on the side opposite to `normal`.
struct Wall {
  Vec2 point = Vec2::Zero();     ///< any point on the wall's surface, m
  Vec2 normal{0.0, 1.0};         ///< unit normal pointing into the free space
};

}  // namespace grainlab

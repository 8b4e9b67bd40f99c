#pragma once
// The one owner of particle state: every particle's position, motion, forces, mass and shape,
// in contiguous arrays indexed by particle (structure of arrays), and the walls. The World
// holds one; its solver (DEM or Box2D) reads and writes these arrays, analysis sees them only
// through the World's const views.
#include <optional>
#include <span>
#include <vector>

#include "grainlab/clump.hpp"
#include "grainlab/material.hpp"
#include "grainlab/math.hpp"
#include "grainlab/particle.hpp"
#include "grainlab/periodic_cell.hpp"
#include "grainlab/shape.hpp"
#include "grainlab/wall.hpp"

namespace grainlab {

struct ParticleStore {
  /// Appends a particle built from `spec` with the material's density; returns its index
  /// (indices are dense and stable, in creation order). Throws std::invalid_argument for a
  /// malformed shape.
  int add(const ParticleSpec& spec, const Material& material);
  /// Appends a wall with its normal made unit; throws std::invalid_argument for a zero normal.
  int addWall(const Wall& wall);

  int size() const { return static_cast<int>(position.size()); }
  /// The force on particle k before its contacts: its weight (none on a particle that does
  /// not move by forces).
  Vec2 bodyForce(int k) const { return motion[k] == Motion::Dynamic ? Vec2(mass[k] * gravity) : Vec2::Zero(); }
  const Polygon& polygonOf(int k) const { return polygons[static_cast<size_t>(shapeIndex[k])]; }
  const Clump& clumpOf(int k) const { return clumps[static_cast<size_t>(shapeIndex[k])]; }
  /// Solid area of particle k, m².
  double area(int k) const;

  Vec2 gravity = Vec2::Zero();  // m/s²

  // Hot state, one entry per particle.
  std::vector<Vec2> position, velocity, force;
  std::vector<double> angle, spin, torque;
  std::vector<double> cosAngle, sinAngle;  // of angle, kept current for polygons and clumps only
  std::vector<double> invMass, invInertia;  // 0 for particles that forces do not move
  // Cold data.
  std::vector<double> mass, inertia, boundingRadius;
  std::vector<ShapeKind> shape;
  std::vector<Motion> motion;
  std::vector<unsigned char> boundary;
  std::vector<int> shapeIndex;  // index into polygons or clumps (by shape), or -1 for discs
  std::vector<Polygon> polygons;  // body frame
  std::vector<Clump> clumps;      // body frame
  std::vector<Wall> walls;
  /// The periodic cell the particles live in, if any (docs/periodic-cell.md). With a cell,
  /// `velocity` is each particle's fluctuation about the cell's affine field L x, and the
  /// positions move with both.
  std::optional<PeriodicCell> cell;
};

}  // namespace grainlab

#pragma once
// The specimen a run of a scene starts stepping from, as plain values: built from the scene's
// particles and assembly, or, with the scene's start_from, loaded from the prepared specimen
// another run kept (grainlab/prepared_specimen.hpp). For tools that hand the specimen to
// another program (grainlab export lammps); it runs nothing.
#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "grainlab/material.hpp"
#include "grainlab/math.hpp"
#include "grainlab/particle.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/shape.hpp"
#include "grainlab/wall.hpp"

namespace grainlab {

struct StartingSpecimen {
  std::vector<ShapeKind> shapes;
  std::vector<double> radii;          ///< m: disc radius (bounding radius for polygons)
  std::vector<double> masses;         ///< kg per metre of thickness
  std::vector<double> inertias;       ///< kg m² per metre
  std::vector<Vec2> positions;        ///< m
  std::vector<Vec2> velocities;       ///< m/s
  std::vector<double> spins;          ///< rad/s
  std::vector<Motion> motions;
  std::vector<unsigned char> boundary;  ///< 1: part of the loading boundary (the ring)
  std::vector<Wall> walls;
  /// A periodic cell's edge vectors (the columns, m) and the velocity gradient it follows (1/s).
  std::optional<Eigen::Matrix2d> cell, cellVelocityGradient;
  Material material;
  double timestep = 0;                ///< s: the one the run would step with
  double time = 0;                    ///< s: the clock at the start (non-zero after start_from)
  std::size_t firstStage = 0;         ///< the index of the first of the scene's stages still to run
};

/// Throws SceneError as a run of the scene would (start_from missing or not fitting, a timestep
/// over the critical one).
StartingSpecimen startingSpecimen(const Scene& scene);

}  // namespace grainlab

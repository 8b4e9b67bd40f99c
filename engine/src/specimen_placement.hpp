#pragma once
// Random sequential placement: each grain in turn goes to a uniformly random spot wholly
// inside a circle where it overlaps none of those already placed (exact tests), found
// through a uniform cell grid so each try looks only at nearby grains.
#include <optional>
#include <vector>

#include "grainlab/clump.hpp"
#include "grainlab/math.hpp"
#include "grainlab/shape.hpp"
#include "specimen_random.hpp"

namespace grainlab::specimen {

/// One grain to place, already turned to its final orientation.
struct Grain {
  ShapeKind shape = ShapeKind::Disc;
  double radius = 0;            ///< m, discs
  std::vector<Vec2> vertices;   ///< m, polygons: counter-clockwise about the grain's centre
  std::vector<ClumpMember> members;  ///< m, clumps: member discs about the grain's centre
  double reach = 0;             ///< m, largest distance of the grain's outline from its centre
};

/// Tries before a grain is declared unplaceable: far more than a placement at the
/// generator's area fractions (0.40-0.45, against the ~0.55 at which random sequential
/// placement jams) ever needs; only a handful of grains in a tight circle runs out.
inline constexpr int kMaxPlacementTries = 200'000;

/// Centres (m) for `grains`, placed in order inside the circle of radius `containerRadius`
/// (m) about the origin, drawing two uniforms per try; nullopt if a grain finds no place
/// in kMaxPlacementTries.
std::optional<std::vector<Vec2>> placeWithoutOverlap(const std::vector<Grain>& grains, double containerRadius,
                                                     SpecimenRandom& random);

/// The same in a periodic square cell [0, side)² (m): grains may cross its edges, and each is
/// tested against the nearest image of every placed grain. Centres are inside the cell.
std::optional<std::vector<Vec2>> placeInPeriodicSquare(const std::vector<Grain>& grains, double side,
                                                       SpecimenRandom& random);

}  // namespace grainlab::specimen

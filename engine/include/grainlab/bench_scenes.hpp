#pragma once
// Scenes shared by the benchmarks and the tests: settled piles in a box.
#include "grainlab/scene.hpp"

namespace grainlab {

/// A box of `columns` × `rows` particles on a staggered lattice under gravity, 2 mm in size
/// with ±10% polydispersity; polygons are hexagons elongated 1.5:1 at seeded random angles.
Scene pileScene(int columns, int rows, bool polygons, std::uint64_t seed = 1);

/// The polygon pile's box and angles with each hexagon a clump of three discs in a line, as
/// long as the hexagon (2.5 sizes; discs of half a size, 0.75 of a size apart).
Scene clumpPileScene(int columns, int rows, std::uint64_t seed = 1);

/// The disc pile's discs (the same count, sizes and seed) in a periodic cell instead of a box:
/// no walls, no gravity, the cell the lattice's own rectangle (`boundary.cellSize`), in which
/// they do not touch yet; the bench compresses it to the settled pile's solid fraction.
Scene periodicPileScene(int columns, int rows, std::uint64_t seed = 1);

}  // namespace grainlab

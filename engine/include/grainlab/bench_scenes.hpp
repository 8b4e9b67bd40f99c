#pragma once
// Scenes shared by the benchmarks and the tests: settled piles in a box.
#include "grainlab/scene.hpp"

namespace grainlab {

/// A box of `columns` × `rows` particles on a staggered lattice under gravity, 2 mm in size
/// with ±10% polydispersity; polygons are hexagons elongated 1.5:1 at seeded random angles.
Scene pileScene(int columns, int rows, bool polygons, std::uint64_t seed = 1);

}  // namespace grainlab

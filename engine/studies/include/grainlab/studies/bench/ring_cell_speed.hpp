#pragma once
// The periodic cell against the ring specimen it stands in for, in one process: the same
// particles (the same recipe and seed make the same grains), each prepared as its own scene
// prepares them (compaction, consolidation), then both timed in turn while they shear.
#include <ostream>
#include <string>

#include "grainlab/scene.hpp"
#include "grainlab/studies/bench/pile_speed.hpp"

namespace grainlab::bench {

/// One side, prepared: `speed` counts every particle the world steps (for the ring, its
/// specimen and its ring of boundary particles, which are stepped and touched like any other).
struct ShearingSpeed {
  PileSpeed speed;
  int specimenParticles = 0;   ///< of speed.particles, the specimen's (the ring's: not its ring)
  double voidRatio = 0;        ///< after the preparation, as series.csv has it
  double axialStrainTimed = 0; ///< the shearing stage's axial strain over the timed steps
};

struct RingCellSpeeds {
  ShearingSpeed ring, cell;
};

/// `ring` and `cell` are scenes of the same disc assembly (recipe and seed): a membrane scene
/// and a periodic one, each ending in a shearing stage. Each is prepared through its stages
/// before the first shearing stage, exactly as a run of it would (untimed); then the shearing
/// stage begins and each steps `repeats` × `steps` steps in turn (ring, cell, ring, …: both see
/// the same load), the stage's servo and boundary included in the time, on `threads` threads.
/// Throws SceneError if a scene does not fit (not discs, no shearing stage, wrong boundary,
/// not the same particles) and SimulationError if the shearing would end inside the timing.
RingCellSpeeds measureCellAgainstRing(const Scene& ring, const Scene& cell, int steps, int repeats, int threads,
                                      std::ostream* progress);

}  // namespace grainlab::bench

#pragma once
// `grainlab bench`'s measure: the engine's speed on a settled pile, in particle-steps per
// second. The pile settles first, untimed, so it is dense with a realistic number of
// contacts; then it steps `steps` times per timed repeat. It steps a World directly: through
// runScene the stages' checks and the sampling would be timed too.
#include <ostream>
#include <string>
#include <vector>

#include "grainlab/scene.hpp"
#include "grainlab/world.hpp"

namespace grainlab::bench {

/// The median of `values` (the mean of the middle two for an even count).
double median(std::vector<double> values);

struct PileSpeed {
  std::string name;
  int particles = 0;
  double coordination = 0;    ///< contacts per particle (×2) when timing starts
  std::vector<double> rates;  ///< particle-steps per second, one per repeat
  double timestep = 0;        ///< s
  /// The same per second of the stepping thread's CPU time: on a shared machine, far less
  /// moved by other programs than the wall-time rates (one thread only; empty otherwise).
  std::vector<double> cpuRates;
  double medianRate() const;
  double medianCpuRate() const;
};

/// The bench's piles, by name: "disc-pile", "disc-pile+1poly" (the same discs and one
/// far-away polygon: the general path, shape dispatch per pair, instead of the discs-only
/// one), "polygon-pile", "disc-pile-rolling" (the disc pile with rolling resistance) and
/// "clump-pile" (each disc of the disc pile a clump of three discs).
std::vector<Scene> benchPiles();

/// Settles `scene`'s pile (its first stage's duration), then times `repeats` × `steps` steps
/// on `threads` threads. Progress lines go to `progress` (may be null).
PileSpeed measurePileSpeed(const Scene& scene, int steps, int repeats, int threads,
                           WorldSettings::Engine engine, std::ostream* progress);

/// The same pile timed on the wide and the baseline contact path in turn (wide, baseline,
/// wide, …: both see the same pile and the same load on the machine), `repeats` × `steps`
/// steps each. In a build without the wide path both are the baseline. Each repeat is timed
/// by the wall clock and, on one thread, by the stepping thread's CPU time, as measurePileSpeed.
struct PathSpeeds {
  PileSpeed wide, baseline;
};
PathSpeeds measurePathSpeeds(const Scene& scene, int steps, int repeats, int threads, std::ostream* progress);

/// Several piles, each settled, then timed in turn (the first, the second, …, the first
/// again: all see the same load on the machine), `repeats` × `steps` steps each, on the
/// default contact path. Their ratios are what one model costs against another.
std::vector<PileSpeed> measureInTurn(const std::vector<Scene>& scenes, int steps, int repeats, int threads,
                                     std::ostream* progress);

/// The periodic pile (periodicPileScene) against the disc pile it copies, in one process: the
/// pile settles, its bulk solid fraction is measured (the discs whose centres lie in the
/// middle half of its width and the 15-65 % of its height, over that window's area); the
/// cell's discs are compressed isotropically to that fraction and left to rest; then the cell
/// shears steadily at `shearRate` (1/s, v₁ = γ̇ x₂) while the two are timed in turn, `repeats`
/// × `steps` steps each, on the default contact path.
struct CellSpeeds {
  PileSpeed pile, cell;
  double solidFraction = 0;  ///< the settled pile's bulk fraction, and the cell's
};
CellSpeeds measureCellAgainstPile(const Scene& pile, const Scene& cell, double shearRate, int steps, int repeats,
                                  int threads, std::ostream* progress);

/// One settled pile timed on one thread and on `threads` in turn (1, N, 1, …: both see the same
/// load): the pile settles once on `threads` threads and is copied, state and contact history,
/// into a one-thread world (the two then step the same bits), `repeats` × `steps` steps each.
struct ThreadSpeeds {
  PileSpeed serial, threaded;
};
ThreadSpeeds measureThreadScaling(const Scene& scene, int threads, int steps, int repeats, std::ostream* progress);

}  // namespace grainlab::bench

#pragma once
// Verlet neighbour list built on a cell grid: every pair whose bounding circles come within
// a skin of each other, plus every particle-wall pair within the skin. It is rebuilt only
// when some particle has moved more than half the skin since the last build, and each
// pair's contact history is carried over to the new list while the pair persists.
#include <span>
#include <vector>

#include "grainlab/math.hpp"
#include "grainlab/state_archive.hpp"
#include "grainlab/particle.hpp"
#include "grainlab/periodic_cell.hpp"
#include "grainlab/wall.hpp"

namespace grainlab {

/// What a touching contact's law remembers from step to step, one slot per sub-model that
/// keeps history (contact_law.hpp). It moves as one block: the neighbour list carries it over
/// a rebuild, a pair that parts clears it, and checkpoints copy it whole, so a slot added
/// here needs no other change to survive any of them. All zero when not touching.
struct ContactHistory {
  double tangential = 0;  ///< Cundall-Strack spring elongation, m
  double rolling = 0;     ///< rolling spring's relative rotation, rad (rolling_resistance.hpp)
};

/// One candidate pair and the state its contact keeps (hot data: 64 bytes, a cache line).
struct PairState {
  int i = 0;
  int j = 0;                 ///< particle index, or -1 - wall index
  double dampN = 0;          ///< normal viscous coefficient, N·s/m
  double dampT = 0;          ///< tangential viscous coefficient, N·s/m
  ContactHistory history;    ///< the law's memory (0 when not touching)
  double fn = 0, ft = 0;     ///< forces of the last step, N (0 when not touching)
  double overlap = 0;        ///< m, of the last step (<= 0 when not touching)
};

class NeighborList {
 public:
  /// True if some particle in [begin, end) has moved more than half the skin since the last
  /// build, or the list was built for another number of particles. Reads only that range, so
  /// each thread can check the particles it has just moved while they are in its cache.
  /// `widePath`: several particles per instruction (skin_check_kernel.hpp; the same answer).
  bool outdated(std::span<const Vec2> positions, int begin, int end, bool widePath = false) const;
  /// Rebuilds if `moved` (some range was outdated()), if invalidated, or if the skin changed;
  /// returns true if it did.
  bool update(std::span<const Vec2> positions, std::span<const double> boundingRadii,
              std::span<const Motion> motions, std::span<const Wall> walls, double skin, bool moved);
  /// The same in a periodic cell (no walls): each pair is one particle and the other's image
  /// in reach, shifts()[k] naming that image. The positions must be inside the cell (wrapped)
  /// and no pair may have two images in reach: the cell's widths must exceed twice the largest
  /// reach (std::invalid_argument otherwise). Carried-over state follows the pair (i, j)
  /// whatever its image, so a contact keeps its history when a particle wraps.
  bool update(std::span<const Vec2> positions, std::span<const double> boundingRadii,
              std::span<const Motion> motions, const PeriodicCell& cell, double skin, bool moved);
  /// Whether the next update() rebuilds, given `moved`.
  bool rebuildDue(size_t particles, double skin, bool moved) const {
    return !valid_ || moved || skin != skin_ || reference_.size() != particles;
  }
  /// In a periodic cell, how far the images of particles can have moved since the build beyond
  /// the particles' own displacements (the cell's deformation, |Δh₁| + |Δh₂|, m): the skin
  /// left to the particles is reduced by it.
  void setImageDrift(double drift) { imageDrift_ = drift; }
  /// The list as it stands (the pairs with their history, and where it was built): enough
  /// for the next update to rebuild, or not, exactly as this one would.
  /// Checkpoints. Loading refuses (CheckpointError) a list that does not fit a world of
  /// `particles` particles and `walls` walls.
  void persist(StateArchive& a, int particles, int walls);
  /// Forces a rebuild at the next update (particles or walls were added).
  void invalidate() { valid_ = false; }

  std::vector<PairState>& pairs() { return pairs_; }
  /// For each particle k, entries [adjacencyStart()[k], adjacencyStart()[k+1]) of
  /// adjacency() name its pairs in pair order: pair index × 2, plus 1 where k is the pair's j.
  const std::vector<int>& adjacencyStart() const { return adjacencyStart_; }
  const std::vector<int>& adjacency() const { return adjacency_; }
  const std::vector<PairState>& pairs() const { return pairs_; }
  /// After a rebuild, each pair's index in the list before it, or -1 for a new pair: lets
  /// per-pair state kept elsewhere follow its pair.
  const std::vector<int>& carriedFrom() const { return carriedFrom_; }
  /// In a periodic cell, each pair's image of j (same order as pairs()); empty otherwise.
  const std::vector<ImageShift>& shifts() const { return shifts_; }
  /// Checkpoints of the shifts (periodic scenes only: other checkpoints keep their layout).
  void persistShifts(StateArchive& a);

 private:
  void build(std::span<const Vec2> positions, std::span<const double> boundingRadii,
             std::span<const Motion> motions, std::span<const Wall> walls, double skin);
  // The same in a periodic cell (neighbor_list_periodic.cpp): pairs with an image shift each.
  void buildPeriodic(std::span<const Vec2> positions, std::span<const double> boundingRadii,
                     std::span<const Motion> motions, const PeriodicCell& cell, double skin);
  // Carries each persisting pair's state over from previous_ (both sorted by (i, j)), then
  // indexes the new list.
  void carryOver(int particles);
  // Each particle's pairs (adjacency) from the pair list.
  void index(int particles);

  bool valid_ = false;
  double skin_ = 0;
  std::vector<Vec2> reference_;      // positions at the last build
  std::vector<PairState> pairs_;
  std::vector<PairState> previous_;  // scratch for carrying history over
  std::vector<int> cellStart_, cellItems_, candidates_;
  std::vector<int> adjacencyStart_, adjacency_;
  std::vector<int> carriedFrom_;
  std::vector<ImageShift> shifts_;   // periodic only
  double imageDrift_ = 0;            // m, periodic only
};

}  // namespace grainlab

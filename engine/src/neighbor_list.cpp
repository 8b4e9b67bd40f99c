#include "neighbor_list.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "skin_check_kernel.hpp"

namespace grainlab {

bool NeighborList::outdated(std::span<const Vec2> positions, int begin, int end, bool widePath) const {
  if (reference_.size() != positions.size()) return true;
  // Half the skin, squared; in a periodic cell, half of what the cell's own motion left of it.
  const double free = skin_ - imageDrift_;
  if (free <= 0) return true;
  const double limit2 = 0.25 * free * free;
  if (widePath) return movedBeyondWide(positions.data()->data(), reference_.data()->data(), begin, end, limit2);
  for (int k = begin; k < end; ++k) {
    if ((positions[k] - reference_[k]).squaredNorm() > limit2) return true;
  }
  return false;
}

bool NeighborList::update(std::span<const Vec2> positions, std::span<const double> boundingRadii,
                          std::span<const Motion> motions, std::span<const Wall> walls, double skin, bool moved) {
  if (valid_ && !moved && skin == skin_ && reference_.size() == positions.size()) return false;
  build(positions, boundingRadii, motions, walls, skin);
  return true;
}

bool NeighborList::update(std::span<const Vec2> positions, std::span<const double> boundingRadii,
                          std::span<const Motion> motions, const PeriodicCell& cell, double skin, bool moved) {
  if (!rebuildDue(positions.size(), skin, moved)) return false;
  buildPeriodic(positions, boundingRadii, motions, cell, skin);
  return true;
}

void NeighborList::build(std::span<const Vec2> positions, std::span<const double> boundingRadii,
                         std::span<const Motion> motions, std::span<const Wall> walls, double skin) {
  const int n = static_cast<int>(positions.size());
  skin_ = skin;
  reference_.assign(positions.begin(), positions.end());
  previous_.swap(pairs_);
  pairs_.clear();

  // Cell grid over the particles' bounding box; a cell is as wide as the largest pair reach,
  // so every candidate of a particle lies in its own or the eight surrounding cells.
  double rmax = 0;
  Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
  bool finite = true;
  for (int k = 0; k < n; ++k) {
    rmax = std::max(rmax, boundingRadii[k]);
    lo = lo.cwiseMin(positions[k]);
    hi = hi.cwiseMax(positions[k]);
    finite = finite && positions[k].allFinite();  // (min and max pass a NaN over: lo and hi cannot tell)
  }
  if (n && !(finite && std::isfinite(lo.x()) && std::isfinite(lo.y()) && std::isfinite(hi.x()) && std::isfinite(hi.y()))) {
    throw std::domain_error("non-finite particle position");
  }
  // Finite positions 1e308 apart span an infinite box, which no cell size divides. Both
  // reached a float-to-int conversion of NaN below (fuzz_checkpoint, with a loaded state).
  if (n && !(std::isfinite(hi.x() - lo.x()) && std::isfinite(hi.y() - lo.y()))) {
    throw std::domain_error("particle positions too far apart to be a packing");
  }
  double cell = std::max(2 * rmax + skin, 1e-12);
  // A sparse scene (a particle flung far away) must not allocate a huge grid: widen the
  // cells until there are at most a few per particle.
  const double maxCells = 4.0 * n + 16;
  while (((hi.x() - lo.x()) / cell + 1) * ((hi.y() - lo.y()) / cell + 1) > maxCells) cell *= 2;
  const int nx = n ? std::max(1, static_cast<int>((hi.x() - lo.x()) / cell) + 1) : 1;
  const int ny = n ? std::max(1, static_cast<int>((hi.y() - lo.y()) / cell) + 1) : 1;
  auto cellOf = [&](const Vec2& x, int& cx, int& cy) {
    cx = std::clamp(static_cast<int>((x.x() - lo.x()) / cell), 0, nx - 1);
    cy = std::clamp(static_cast<int>((x.y() - lo.y()) / cell), 0, ny - 1);
  };
  // Counting sort of particles into cells keeps each cell's list in index order.
  cellStart_.assign(static_cast<size_t>(nx) * ny + 1, 0);
  cellItems_.resize(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    int cx, cy;
    cellOf(positions[k], cx, cy);
    ++cellStart_[static_cast<size_t>(cy) * nx + cx + 1];
  }
  for (size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  {
    std::vector<int> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (int k = 0; k < n; ++k) {
      int cx, cy;
      cellOf(positions[k], cx, cy);
      cellItems_[static_cast<size_t>(fill[static_cast<size_t>(cy) * nx + cx]++)] = k;
    }
  }

  for (int i = 0; i < n; ++i) {
    const bool iMoves = motions[i] == Motion::Dynamic;
    // Walls first (j < 0), in wall order: pairs stay sorted by (i, j).
    if (iMoves) {
      for (int w = static_cast<int>(walls.size()) - 1; w >= 0; --w) {
        const double s = (positions[i] - walls[w].point).dot(walls[w].normal);
        if (s < boundingRadii[i] + skin) pairs_.push_back({i, -1 - w});
      }
    }
    candidates_.clear();
    int cx, cy;
    cellOf(positions[i], cx, cy);
    for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, ny - 1); ++y) {
      for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, nx - 1); ++x) {
        const size_t c = static_cast<size_t>(y) * nx + x;
        for (int k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
          const int j = cellItems_[static_cast<size_t>(k)];
          if (j <= i) continue;
          // Two particles that cannot be moved by forces need no contact.
          if (!iMoves && motions[j] != Motion::Dynamic) continue;
          const double reach = boundingRadii[i] + boundingRadii[j] + skin;
          if ((positions[j] - positions[i]).squaredNorm() < reach * reach) candidates_.push_back(j);
        }
      }
    }
    std::sort(candidates_.begin(), candidates_.end());
    for (int j : candidates_) pairs_.push_back({i, j});
  }

  carryOver(n);
}

void NeighborList::carryOver(int n) {
  // Carry each persisting pair's contact state over: both lists are sorted by (i, j).
  auto less = [](const PairState& a, const PairState& b) { return a.i < b.i || (a.i == b.i && a.j < b.j); };
  size_t o = 0;
  carriedFrom_.assign(pairs_.size(), -1);
  for (size_t k = 0; k < pairs_.size(); ++k) {
    PairState& p = pairs_[k];
    while (o < previous_.size() && less(previous_[o], p)) ++o;
    if (o < previous_.size() && previous_[o].i == p.i && previous_[o].j == p.j) {
      // The whole pair, so that state added to PairState or to its history block later
      // carries over without a change here (its damping is the solver's to reassign).
      p = previous_[o];
      carriedFrom_[k] = static_cast<int>(o);
    }
  }
  index(n);
  valid_ = true;
}

void NeighborList::persist(StateArchive& a, int particles, int walls) {
  a(valid_);
  a(skin_);
  a.bitwise(reference_);
  a(pairs_);
  if (a.loading()) {
    // What the list's users index with must be in range, and the pairs sorted as a build
    // leaves them (carrying history over relies on it): a checkpoint is refused otherwise.
    // (A list not valid is rebuilt before it is read; its reference may be of another size.)
    a.require(!valid_ || reference_.size() == static_cast<size_t>(particles), "the neighbour list's particle count differs");
    for (size_t k = 0; k < pairs_.size(); ++k) {
      const PairState& p = pairs_[k];
      // A wall is j = -1 - w; a particle pair has i < j (build() lists each pair once).
      const bool inRange = p.i >= 0 && p.i < particles && (p.j < 0 ? p.j >= -walls : p.j > p.i && p.j < particles);
      const bool sorted = k == 0 || pairs_[k - 1].i < p.i || (pairs_[k - 1].i == p.i && pairs_[k - 1].j < p.j);
      a.require(inRange && sorted, "neighbour pair " + std::to_string(k) + " (" + std::to_string(p.i) + ", " +
                                       std::to_string(p.j) + ") is out of range or out of order");
    }
    carriedFrom_.clear();  // read only right after a rebuild, which sets it
    index(particles);
  }
}

void NeighborList::index(int n) {
  // Each particle's pairs, in pair order (a counting sort over the sorted pair list).
  adjacencyStart_.assign(static_cast<size_t>(n) + 1, 0);
  for (const PairState& p : pairs_) {
    ++adjacencyStart_[static_cast<size_t>(p.i) + 1];
    if (p.j >= 0) ++adjacencyStart_[static_cast<size_t>(p.j) + 1];
  }
  for (int k = 0; k < n; ++k) adjacencyStart_[k + 1] += adjacencyStart_[k];
  adjacency_.resize(static_cast<size_t>(adjacencyStart_[n]));
  std::vector<int> fill(adjacencyStart_.begin(), adjacencyStart_.end() - 1);
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const PairState& p = pairs_[k];
    adjacency_[static_cast<size_t>(fill[p.i]++)] = static_cast<int>(2 * k);
    if (p.j >= 0) adjacency_[static_cast<size_t>(fill[p.j]++)] = static_cast<int>(2 * k + 1);
  }
}

}  // namespace grainlab

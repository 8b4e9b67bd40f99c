// The neighbour list in a periodic cell: a grid in the cell's own (fractional) coordinates,
// wrapping around its edges, so a tilted cell is binned as well as a square one. A particle's
// candidates are in its own and the eight surrounding bins; a bin across an edge is the same
// bin with the image shift of that edge.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "grainlab/state_archive.hpp"
#include "neighbor_list.hpp"

namespace grainlab {
namespace {

struct ImageCandidate {
  int j;
  ImageShift shift;
};

}  // namespace

void NeighborList::buildPeriodic(std::span<const Vec2> positions, std::span<const double> boundingRadii,
                                 std::span<const Motion> motions, const PeriodicCell& cell, double skin) {
  const int n = static_cast<int>(positions.size());
  skin_ = skin;
  reference_.assign(positions.begin(), positions.end());
  previous_.swap(pairs_);
  pairs_.clear();
  shifts_.clear();

  double rmax = 0;
  for (int k = 0; k < n; ++k) {
    rmax = std::max(rmax, boundingRadii[k]);
    if (!positions[k].allFinite()) throw std::domain_error("non-finite particle position");
  }
  // One image in reach at most: then a pair is (i, j) whatever the image, and its history
  // can follow it by that name across a wrap.
  const double cutoff = std::max(2 * rmax + skin, 1e-12);
  if (!(cell.minWidth() > 2 * cutoff)) {
    std::ostringstream os;
    os << "the periodic cell is too narrow: its smaller width " << cell.minWidth()
       << " m must exceed twice the largest pair reach, 2 × " << cutoff
       << " m (two largest radii and the neighbour skin), or a particle would touch two images of another";
    throw std::invalid_argument(os.str());
  }
  // Bins: the lines s1 = const are width(1) apart per unit of s1 (and s2: width(0)); each bin
  // at least the cutoff across, and at most a few bins per particle in a sparse cell.
  int nb1 = std::max(1, static_cast<int>(cell.width(1) / cutoff));
  int nb2 = std::max(1, static_cast<int>(cell.width(0) / cutoff));
  const double maxBins = 4.0 * n + 16;
  while (static_cast<double>(nb1) * nb2 > maxBins) {
    if (nb1 >= nb2) nb1 = std::max(1, nb1 / 2);
    else nb2 = std::max(1, nb2 / 2);
  }

  // Each particle's bin, from its fractional coordinates wrapped into [0, 1); `whole` keeps
  // the whole part, so an image found through the bins is named for the actual position.
  std::vector<int> bin1(static_cast<size_t>(n)), bin2(static_cast<size_t>(n));
  std::vector<ImageShift> whole(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const Vec2 s = cell.fractional(positions[k]);
    const double f1 = std::floor(s.x()), f2 = std::floor(s.y());
    whole[k] = {static_cast<int>(f1), static_cast<int>(f2)};
    bin1[k] = std::clamp(static_cast<int>((s.x() - f1) * nb1), 0, nb1 - 1);
    bin2[k] = std::clamp(static_cast<int>((s.y() - f2) * nb2), 0, nb2 - 1);
  }
  cellStart_.assign(static_cast<size_t>(nb1) * nb2 + 1, 0);
  cellItems_.resize(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) ++cellStart_[static_cast<size_t>(bin2[k]) * nb1 + bin1[k] + 1];
  for (size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  {
    std::vector<int> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (int k = 0; k < n; ++k) cellItems_[static_cast<size_t>(fill[static_cast<size_t>(bin2[k]) * nb1 + bin1[k]]++)] = k;
  }

  std::vector<ImageCandidate> found;
  for (int i = 0; i < n; ++i) {
    const bool iMoves = motions[i] == Motion::Dynamic;
    found.clear();
    for (int d2 = -1; d2 <= 1; ++d2) {
      // The neighbouring bin, wrapped, and the edge crossed to reach it (m).
      int c2 = bin2[i] + d2, m2 = 0;
      if (c2 < 0) c2 += nb2, m2 = -1;
      else if (c2 >= nb2) c2 -= nb2, m2 = 1;
      for (int d1 = -1; d1 <= 1; ++d1) {
        int c1 = bin1[i] + d1, m1 = 0;
        if (c1 < 0) c1 += nb1, m1 = -1;
        else if (c1 >= nb1) c1 -= nb1, m1 = 1;
        const size_t c = static_cast<size_t>(c2) * nb1 + c1;
        for (int e = cellStart_[c]; e < cellStart_[c + 1]; ++e) {
          const int j = cellItems_[static_cast<size_t>(e)];
          if (j <= i) continue;
          if (!iMoves && motions[j] != Motion::Dynamic) continue;
          // j's wrapped image at u_j + m sits beside u_i: for the actual positions,
          // x_j + h n − x_i with n = m − whole_j + whole_i.
          const ImageShift shift{m1 - whole[j].n1 + whole[i].n1, m2 - whole[j].n2 + whole[i].n2};
          const double reach = boundingRadii[i] + boundingRadii[j] + skin;
          if ((positions[j] + cell.shift(shift) - positions[i]).squaredNorm() < reach * reach) found.push_back({j, shift});
        }
      }
    }
    std::sort(found.begin(), found.end(), [](const ImageCandidate& a, const ImageCandidate& b) { return a.j < b.j; });
    for (const ImageCandidate& f : found) {
      pairs_.push_back({i, f.j});
      shifts_.push_back(f.shift);
    }
  }
  carryOver(n);
}

void NeighborList::persistShifts(StateArchive& a) {
  a.section("image shifts");
  a.bitwise(shifts_);
  if (a.loading()) a.require(shifts_.size() == pairs_.size(), "the image shifts' count differs from the pair count");
}

}  // namespace grainlab

// The contact stress summed from the solver's own pair state: what a servo measures every few
// steps. It is grainlab::contactStress over contacts(), term for term and in the same order,
// so the bits are the same; it skips what that route pays for each measure: the wide path's
// state written back to the list, a record per contact, a nearest-image search call per
// branch vector where the branch is plainly its own nearest image, and, on the wide path with
// polygons, the contacts' measure (the force pass kept it, with the same bits).
#include <cmath>
#include <stdexcept>
#include <string>

#include "contact_solver.hpp"

namespace grainlab {
namespace {

[[gnu::noinline]] Vec2 minimumImageOutOfLine(const PeriodicCell& cell, const Vec2& branch) {
  return cell.minimumImage(branch);
}

}  // namespace

StressTensor ContactSolver::contactStress(std::span<const Vec2> centroids, std::span<const unsigned char> inside,
                                          double area, const PeriodicCell* cell) const {
  if (!(area > 0) || !std::isfinite(area))
    throw std::invalid_argument("contactStress: area must be positive and finite, got " + std::to_string(area));
  if (inside.size() != centroids.size())
    throw std::invalid_argument("contactStress: inside has " + std::to_string(inside.size()) +
                                " entries but centroids has " + std::to_string(centroids.size()));
  if (centroids.size() != static_cast<size_t>(particles_.size()))
    throw std::invalid_argument("contactStress: centroids has " + std::to_string(centroids.size()) +
                                " entries but the world has " + std::to_string(particles_.size()) + " particles");
  // A branch shorter than half the cell's smaller width is its own nearest image
  // (PeriodicCell::nearestImage returns n = 0 for it without a search); a margin against
  // rounding, as there.
  const double shortBranch = cell ? 0.49 * cell->minWidth() : 0;
  const double shortBranch2 = shortBranch * shortBranch;
  double s11 = 0, s12 = 0, s21 = 0, s22 = 0;
  // minimumImage(branch) is branch + h·0 for a short one: the same value (adding a zero changes
  // at most the sign of a zero component, which no sum below can show). Only a branch across an
  // edge takes the search, out of line, so the sums stay in registers through the loop.
  auto imageOf = [&](const Vec2& branch) {
    return !cell || branch.squaredNorm() < shortBranch2 ? branch : minimumImageOutOfLine(*cell, branch);
  };
  // After a wide step the disc-disc pairs' last forces are the batch's slots, one per such pair
  // in pair order (DiscPairBatch::build); the wall pairs' are the list's own.
  const bool fromSlots = wideStateAhead_;
  const double* slotFn = discBatch_.fn();
  const double* slotFt = discBatch_.ft();
  const double* slotOverlap = discBatch_.overlap();
  int slot = 0;
  const bool discsOnly = particles_.polygons.empty();
  const Vec2* x = particles_.position.data();
  const double* radius = particles_.boundingRadius.data();
  const std::vector<PairState>& pairs = neighbors_.pairs();
  for (size_t k = 0; k < pairs.size(); ++k) {
    const PairState& p = pairs[k];
    double fn = p.fn, ft = p.ft, overlap = p.overlap;
    if (fromSlots && p.j >= 0) {
      fn = slotFn[slot];
      ft = slotFt[slot];
      overlap = slotOverlap[slot];
      ++slot;
    }
    if (overlap <= 0) continue;
    // The geometry as contacts() gives it (positions have not moved since the forces).
    const Vec2 shift = particles_.cell ? imageShift(k) : Vec2::Zero();
    ContactGeometry g;
    if (discsOnly && p.j >= 0) {
      g = collideDiscs(x[p.i], radius[p.i], particles_.cell ? Vec2(x[p.j] + shift) : x[p.j], radius[p.j]);
    } else if (batchContactsCurrent_) {
      g = polygonBatch_.contact(static_cast<int>(k));  // the force pass's measure, at these positions
    } else {
      CachedContact cache = k < polygonCache_.size() ? polygonCache_[k] : CachedContact{};
      g = pairGeometry(p, &cache, particles_.cell ? &shift : nullptr);
    }
    // The force particle i exerts on its neighbour; j exerts the opposite one on i.
    const Vec2 f = fn * g.normal + ft * perp(g.normal);
    if (inside[static_cast<size_t>(p.i)] != 0) {
      const Vec2 l = imageOf(g.point - centroids[static_cast<size_t>(p.i)]);
      s11 += f.x() * l.x();
      s12 += f.x() * l.y();
      s21 += f.y() * l.x();
      s22 += f.y() * l.y();
    }
    // A wall has no centroid and is not part of the specimen: only particle i's end counts.
    if (p.j >= 0 && inside[static_cast<size_t>(p.j)] != 0) {
      const Vec2 l = imageOf(g.point - centroids[static_cast<size_t>(p.j)]);
      const Vec2 onJ = -f;
      s11 += onJ.x() * l.x();
      s12 += onJ.x() * l.y();
      s21 += onJ.y() * l.x();
      s22 += onJ.y() * l.y();
    }
  }
  const double inv = 1.0 / area;
  return StressTensor{s11 * inv, s12 * inv, s21 * inv, s22 * inv};
}

}  // namespace grainlab

#include "specimen_placement.hpp"

#include <algorithm>
#include <cmath>

#include "specimen_overlap.hpp"

namespace grainlab::specimen {
namespace {

// Placed grains in a uniform grid of cells at least as wide as the largest grain's
// diameter, so two grains can overlap only if their centres are in neighbouring cells.
// Each cell is a singly linked list through `next_`.
class CellGrid {
 public:
  CellGrid(double halfWidth, double cellSize)
      : origin_(-halfWidth), cell_(cellSize),
        side_(std::max(1, static_cast<int>(std::ceil(2 * halfWidth / cellSize)))),
        head_(static_cast<std::size_t>(side_) * static_cast<std::size_t>(side_), -1) {}

  void insert(int index, const Vec2& p) {
    if (next_.size() <= static_cast<std::size_t>(index)) next_.resize(static_cast<std::size_t>(index) + 1, -1);
    int& head = head_[cellOf(column(p.x()), column(p.y()))];
    next_[static_cast<std::size_t>(index)] = head;
    head = index;
  }

  /// Calls visit(index) for the grains in the 3×3 cells around p until it returns true.
  template <class Visit>
  bool any(const Vec2& p, Visit visit) const {
    const int cx = column(p.x()), cy = column(p.y());
    for (int y = std::max(0, cy - 1); y <= std::min(side_ - 1, cy + 1); ++y) {
      for (int x = std::max(0, cx - 1); x <= std::min(side_ - 1, cx + 1); ++x) {
        for (int i = head_[cellOf(x, y)]; i >= 0; i = next_[static_cast<std::size_t>(i)]) {
          if (visit(i)) return true;
        }
      }
    }
    return false;
  }

 private:
  int column(double coordinate) const {
    return std::clamp(static_cast<int>(std::floor((coordinate - origin_) / cell_)), 0, side_ - 1);
  }
  std::size_t cellOf(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(side_) + static_cast<std::size_t>(x); }

  double origin_;
  double cell_;
  int side_;
  std::vector<int> head_;
  std::vector<int> next_;
};

std::vector<Vec2> translated(const std::vector<Vec2>& vertices, const Vec2& by) {
  std::vector<Vec2> out(vertices.size());
  for (std::size_t k = 0; k < vertices.size(); ++k) out[k] = vertices[k] + by;
  return out;
}

bool overlaps(const Grain& a, const Vec2& pa, const std::vector<Vec2>& worldA, const Grain& b, const Vec2& pb,
              const std::vector<Vec2>& worldB) {
  // Bounding circles first: cheap, and exact as a rejection (apart circles cannot overlap).
  const double reach = a.reach + b.reach;
  if ((pa - pb).squaredNorm() >= reach * reach) return false;
  // A clump overlaps where one of its discs does (clumps are placed among clumps and discs).
  if (a.shape == ShapeKind::Clump || b.shape == ShapeKind::Clump) {
    const bool aIsClump = a.shape == ShapeKind::Clump;
    const Grain& clump = aIsClump ? a : b;
    const Grain& other = aIsClump ? b : a;
    const Vec2& pc = aIsClump ? pa : pb;
    const Vec2& po = aIsClump ? pb : pa;
    const std::vector<Vec2>& worldOther = aIsClump ? worldB : worldA;
    for (const ClumpMember& m : clump.members) {
      Grain disc;
      disc.radius = disc.reach = m.radius;
      if (overlaps(disc, pc + m.centre, {}, other, po, worldOther)) return true;
    }
    return false;
  }
  const bool discA = a.shape == ShapeKind::Disc, discB = b.shape == ShapeKind::Disc;
  if (discA && discB) return discsOverlap(pa, a.radius, pb, b.radius);
  if (discA) return discPolygonOverlap(pa, a.radius, worldB);
  if (discB) return discPolygonOverlap(pb, b.radius, worldA);
  return polygonsOverlap(worldA, worldB);
}

}  // namespace

std::optional<std::vector<Vec2>> placeWithoutOverlap(const std::vector<Grain>& grains, double containerRadius,
                                                     SpecimenRandom& random) {
  double largestReach = 0;
  for (const Grain& g : grains) largestReach = std::max(largestReach, g.reach);
  CellGrid grid(containerRadius, std::max(2 * largestReach, 1e-12));

  std::vector<Vec2> centres;
  std::vector<std::vector<Vec2>> outlines;  // world vertices of placed polygons
  centres.reserve(grains.size());
  outlines.reserve(grains.size());
  for (std::size_t n = 0; n < grains.size(); ++n) {
    const Grain& grain = grains[n];
    // The centre stays within this radius so the whole grain is inside the container.
    const double free = containerRadius - grain.reach;
    if (!(free >= 0)) return std::nullopt;
    bool placed = false;
    for (int attempt = 0; attempt < kMaxPlacementTries && !placed; ++attempt) {
      // Uniform in the disc by rejection from the square: no trigonometry, so the same
      // bits on every standard library.
      const Vec2 p(random.uniform(-free, free), random.uniform(-free, free));
      if (p.squaredNorm() > free * free) continue;
      const std::vector<Vec2> outline = translated(grain.vertices, p);
      const bool blocked = grid.any(p, [&](int other) {
        const std::size_t o = static_cast<std::size_t>(other);
        return overlaps(grain, p, outline, grains[o], centres[o], outlines[o]);
      });
      if (blocked) continue;
      grid.insert(static_cast<int>(n), p);
      centres.push_back(p);
      outlines.push_back(outline);
      placed = true;
    }
    if (!placed) return std::nullopt;
  }
  return centres;
}

std::optional<std::vector<Vec2>> placeInPeriodicSquare(const std::vector<Grain>& grains, double side,
                                                       SpecimenRandom& random) {
  double largestReach = 0;
  for (const Grain& g : grains) largestReach = std::max(largestReach, g.reach);
  // Only the nearest image of a grain can overlap another: no two images within 2 reaches.
  if (!(side > 4 * largestReach)) return std::nullopt;
  // Two grains overlap only if their centres are in neighbouring bins (wrapping round).
  const int bins = std::max(1, static_cast<int>(side / std::max(2 * largestReach, 1e-12)));
  std::vector<std::vector<int>> binned(static_cast<std::size_t>(bins) * bins);
  auto binOf = [&](double x) { return std::clamp(static_cast<int>(x / side * bins), 0, bins - 1); };

  std::vector<Vec2> centres;
  std::vector<std::vector<Vec2>> outlines;  // world vertices of placed polygons, at their centres
  centres.reserve(grains.size());
  outlines.reserve(grains.size());
  for (std::size_t n = 0; n < grains.size(); ++n) {
    const Grain& grain = grains[n];
    bool placed = false;
    for (int attempt = 0; attempt < kMaxPlacementTries && !placed; ++attempt) {
      const Vec2 p(random.uniform(0, side), random.uniform(0, side));
      const std::vector<Vec2> outline = translated(grain.vertices, p);
      const int bx = binOf(p.x()), by = binOf(p.y());
      bool blocked = false;
      for (int dy = -1; dy <= 1 && !blocked; ++dy) {
        for (int dx = -1; dx <= 1 && !blocked; ++dx) {
          const int cx = ((bx + dx) % bins + bins) % bins, cy = ((by + dy) % bins + bins) % bins;
          for (int other : binned[static_cast<std::size_t>(cy) * bins + cx]) {
            const std::size_t o = static_cast<std::size_t>(other);
            // The placed grain's image nearest p (a square cell: round each coordinate).
            const Vec2 shift = side * Vec2(std::round((p.x() - centres[o].x()) / side), std::round((p.y() - centres[o].y()) / side));
            if (overlaps(grain, p, outline, grains[o], centres[o] + shift, translated(outlines[o], shift))) {
              blocked = true;
              break;
            }
          }
        }
      }
      if (blocked) continue;
      binned[static_cast<std::size_t>(binOf(p.y())) * bins + binOf(p.x())].push_back(static_cast<int>(n));
      centres.push_back(p);
      outlines.push_back(outline);
      placed = true;
    }
    if (!placed) return std::nullopt;
  }
  return centres;
}

}  // namespace grainlab::specimen

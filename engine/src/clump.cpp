#include "grainlab/clump.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "grainlab/shape.hpp"

namespace grainlab {
namespace {

// Moments of a region accumulated from pieces of its boundary (Green's theorem).
struct Moments {
  double area = 0;
  Vec2 first = Vec2::Zero();
  double polar = 0;
};

// The straight edge a → b: the polygon (shoelace) terms, the exact integrals over the
// triangle (origin, a, b).
void addEdge(Moments& m, const Vec2& a, const Vec2& b) {
  const double w = cross(a, b);
  m.area += 0.5 * w;
  m.first += (w / 6.0) * (a + b);
  m.polar += (w / 12.0) * (a.squaredNorm() + a.dot(b) + b.squaredNorm());
}

// The arc of circle (c, r) from angle t1 to t2 (counter-clockwise, t2 > t1): the sector it
// spans from c, plus the edges from its start to c and from c to its end (the sector's
// boundary is edge c → start, the arc, edge end → c; adding the reverse edges leaves the arc).
void addArc(Moments& m, const Vec2& c, double r, double t1, double t2) {
  const double span = t2 - t1;
  const double area = 0.5 * r * r * span;
  // ∫ (x − c) dA over the sector, and ∫ |x − c|² dA.
  const Vec2 aboutCentre = (r * r * r / 3.0) * Vec2(std::sin(t2) - std::sin(t1), std::cos(t1) - std::cos(t2));
  m.area += area;
  m.first += aboutCentre + area * c;
  m.polar += 0.25 * r * r * r * r * span + 2 * c.dot(aboutCentre) + c.squaredNorm() * area;
  const Vec2 start = c + r * Vec2(std::cos(t1), std::sin(t1));
  const Vec2 end = c + r * Vec2(std::cos(t2), std::sin(t2));
  addEdge(m, start, c);
  addEdge(m, c, end);
}

bool sameDisc(const ClumpMember& a, const ClumpMember& b) {
  return a.centre == b.centre && a.radius == b.radius;
}

// Moments of the union of discs whose centres are given relative to the origin.
Moments unionMoments(std::span<const ClumpMember> discs) {
  Moments m;
  const size_t n = discs.size();
  std::vector<std::pair<double, double>> covered;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 ci = discs[i].centre;
    const double ri = discs[i].radius;
    bool hidden = false;
    covered.clear();
    for (size_t j = 0; j < n && !hidden; ++j) {
      if (j == i) continue;
      if (sameDisc(discs[i], discs[j])) {
        hidden = j < i;  // a repeated disc counts once, as its first copy
        continue;
      }
      const Vec2 d = discs[j].centre - ci;
      const double dist = d.norm(), rj = discs[j].radius;
      if (dist >= ri + rj || dist + rj <= ri) continue;  // apart, or j inside i
      if (dist + ri <= rj) {
        hidden = true;  // i inside j
        continue;
      }
      // The part of circle i inside disc j: angles within α of the direction to j's centre.
      const double cosHalf = std::clamp((dist * dist + ri * ri - rj * rj) / (2 * dist * ri), -1.0, 1.0);
      const double half = std::acos(cosHalf);
      double from = std::atan2(d.y(), d.x()) - half;
      from -= 2 * kPi * std::floor(from / (2 * kPi));  // into [0, 2π)
      const double to = from + 2 * half;
      if (to <= 2 * kPi) {
        covered.emplace_back(from, to);
      } else {
        covered.emplace_back(from, 2 * kPi);
        covered.emplace_back(0.0, to - 2 * kPi);
      }
    }
    if (hidden) continue;
    if (covered.empty()) {
      // The whole circle: its sector terms in closed form (the arc's edges would cancel).
      const double area = discArea(ri);
      m.area += area;
      m.first += area * ci;
      m.polar += 0.5 * area * ri * ri + ci.squaredNorm() * area;
      continue;
    }
    // The arcs between the merged covered intervals.
    std::sort(covered.begin(), covered.end());
    double reached = 0;  // end of the covered stretch so far
    for (const auto& [from, to] : covered) {
      if (from > reached) addArc(m, ci, ri, reached, from);
      reached = std::max(reached, to);
    }
    if (reached < 2 * kPi) addArc(m, ci, ri, reached, 2 * kPi);
  }
  return m;
}

}  // namespace

DiscUnionMoments discUnionMoments(std::span<const ClumpMember> members) {
  DiscUnionMoments out;
  if (members.empty()) return out;
  // About the first centre: the terms are then of the clump's size, not its position's.
  const Vec2 reference = members.front().centre;
  std::vector<ClumpMember> local(members.begin(), members.end());
  for (ClumpMember& m : local) m.centre -= reference;
  const Moments m = unionMoments(local);
  out.area = m.area;
  out.firstMoment = m.first + m.area * reference;
  out.polarMoment = m.polar + 2 * reference.dot(m.first) + reference.squaredNorm() * m.area;
  return out;
}

Clump makeClump(std::span<const ClumpMember> members, Vec2* centroidOffset) {
  const int n = static_cast<int>(members.size());
  if (n < 1 || n > kMaxClumpMembers) {
    throw std::invalid_argument("a clump needs 1 to " + std::to_string(kMaxClumpMembers) + " members, got " +
                                std::to_string(n));
  }
  for (int k = 0; k < n; ++k) {
    const ClumpMember& m = members[static_cast<size_t>(k)];
    if (!(m.radius > 0) || !std::isfinite(m.radius)) {
      throw std::invalid_argument("member " + std::to_string(k) + ": radius must be positive and finite");
    }
    if (!m.centre.allFinite()) throw std::invalid_argument("member " + std::to_string(k) + ": centre must be finite");
  }
  // Connected: every member reached from the first through overlapping members.
  std::vector<int> reached{0};
  std::vector<bool> seen(static_cast<size_t>(n), false);
  seen[0] = true;
  for (size_t q = 0; q < reached.size(); ++q) {
    const ClumpMember& a = members[static_cast<size_t>(reached[q])];
    for (int k = 0; k < n; ++k) {
      const ClumpMember& b = members[static_cast<size_t>(k)];
      if (seen[static_cast<size_t>(k)] || (b.centre - a.centre).norm() >= a.radius + b.radius) continue;
      seen[static_cast<size_t>(k)] = true;
      reached.push_back(k);
    }
  }
  if (static_cast<int>(reached.size()) < n) {
    const int apart = static_cast<int>(std::find(seen.begin(), seen.end(), false) - seen.begin());
    throw std::invalid_argument("member " + std::to_string(apart) +
                                " does not overlap the others: a clump's discs must form one connected body");
  }

  Clump clump;
  Vec2 centroid = members.front().centre;
  if (n == 1) {
    // A lone disc's own formulas, so that a one-member clump is that disc bit for bit.
    const double r = members.front().radius;
    clump.area = discArea(r);
    clump.polarMoment = 0.5 * clump.area * r * r;
  } else {
    // Moments about the first centre, then moved to the centroid (parallel axis).
    std::vector<ClumpMember> local(members.begin(), members.end());
    for (ClumpMember& m : local) m.centre -= centroid;
    const Moments m = unionMoments(local);
    const Vec2 shift = m.first / m.area;
    clump.area = m.area;
    clump.polarMoment = m.polar - m.area * shift.squaredNorm();
    centroid += shift;
  }
  clump.members.assign(members.begin(), members.end());
  for (ClumpMember& m : clump.members) {
    m.centre = n == 1 ? Vec2::Zero() : Vec2(m.centre - centroid);
    clump.circumradius = std::max(clump.circumradius, m.centre.norm() + m.radius);
  }
  if (centroidOffset) *centroidOffset = centroid;
  return clump;
}

}  // namespace grainlab

#pragma once
// Clumps: rigid bodies made of overlapping discs (PFC's and YADE's clumps). A clump is one
// body (one position, angle, mass and inertia in the ParticleStore); its member discs are its
// shape. Mass properties are of the union of the members, exact (no double-counted overlap).
#include <span>
#include <vector>

#include "grainlab/math.hpp"

namespace grainlab {

/// One member disc of a clump: its centre (relative to some reference point, or in the
/// body frame about the centroid once in a Clump) and radius, m.
struct ClumpMember {
  Vec2 centre = Vec2::Zero();
  double radius = 0;
};

/// Area, first and second moments of a union of discs, about the coordinate origin of the
/// member centres.
struct DiscUnionMoments {
  double area = 0;             ///< m²
  Vec2 firstMoment = Vec2::Zero();  ///< ∫ x dA, m³
  double polarMoment = 0;      ///< ∫ |x|² dA about the origin, m⁴
};

/// The union's moments, exact to rounding: the union's boundary is circular arcs (each
/// member's circle less the parts inside another member), and Green's theorem turns each
/// moment into a sum of closed-form arc integrals (a circular sector from the arc's centre
/// plus the two straight edges from the arc's ends to that centre). Members wholly inside
/// another, or repeated, add nothing.
DiscUnionMoments discUnionMoments(std::span<const ClumpMember> members);

/// A clump in its body frame: members about the union's centroid (the origin).
struct Clump {
  std::vector<ClumpMember> members;
  double area = 0;          ///< of the union, m²
  double polarMoment = 0;   ///< ∫ r² dA of the union about the centroid, m⁴
  double circumradius = 0;  ///< largest member reach |centre| + radius, m
};

/// Builds a Clump from 1..kMaxClumpMembers members given relative to a reference point.
/// Throws std::invalid_argument naming the member if a radius is not positive and finite, a
/// centre is not finite, or the union is not connected (a rigid clump of apart discs is
/// refused: it is almost always a typo). `centroidOffset` receives the centroid relative to
/// the reference point. One member gives the disc's own area and ½ m r² exactly.
Clump makeClump(std::span<const ClumpMember> members, Vec2* centroidOffset = nullptr);

inline constexpr int kMaxClumpMembers = 64;

}  // namespace grainlab

#pragma once
// The boundary ring: kinematic discs on a circle around the specimen, moved later by a
// homogeneous velocity field v = L·x, so that their centres follow x → F·x with
// F = diag(λ1, λ2). Its one job is to keep every particle inside along the whole loading
// path: the surface gap between neighbouring ring discs must stay below the smallest width
// of the smallest particle.
#include <span>

#include <Eigen/Core>

#include "grainlab/particle.hpp"

namespace grainlab::specimen {

/// The deformations the ring must survive (paper, Section 4): an isotropic shrink from its
/// initial radius to the consolidated one, then biaxial shearing to 20 % axial strain
/// (compression along 2) while the specimen widens along 1, allowed up to 30 %.
struct RingPath {
  double consolidatedRadius = 0;  ///< m, ring-centre radius after consolidation
  double axialStrain = 0.20;      ///< largest compression ε22 (1 − λ2)
  double lateralExtension = 0.30; ///< largest widening λ1 − 1
};

/// The largest factor by which any chord of the initial ring is stretched along the path:
/// max(1, s·(1 + lateral)) with s = consolidated / initial radius (|F·c| ≤ max(λ1, λ2)·|c|).
double ringWidestStretch(double initialRadius, const RingPath& path);

/// Neighbouring ring discs overlap by at least this fraction of their diameter even at the
/// widest state of the path (centre spacing ≤ (1 − it)·2r).
inline constexpr double kRingOverlap = 0.1;

/// The fewest discs of radius `discRadius` (m) on a circle of `initialRadius` (m) whose
/// neighbours still overlap by kRingOverlap of a diameter at the widest state of `path`
/// (and at least 8).
int ringDiscCount(double initialRadius, double discRadius, const RingPath& path);

/// The largest surface gap (m; negative when all neighbours overlap) between neighbouring
/// discs of `ring` (in order around the circle, the last next to the first) once their
/// centres are moved by x → F·x.
double largestRingGap(std::span<const ParticleSpec> ring, const Eigen::Matrix2d& deformation);

/// The ring keeps particles in: every neighbour gap under F is below `smallestWidth` (m),
/// the smallest width of the smallest particle.
bool ringRetains(std::span<const ParticleSpec> ring, const Eigen::Matrix2d& deformation, double smallestWidth);

}  // namespace grainlab::specimen

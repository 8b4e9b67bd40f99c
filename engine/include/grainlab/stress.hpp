#pragma once
// The contact (Love-Weber) stress of a set of particles: σ_ij = (1/A) Σ_ends f_i l_j, force
// index first, compression positive (see shared docs/micromechanics.md).
#include <span>

#include "grainlab/contact.hpp"
#include "grainlab/math.hpp"
#include "grainlab/periodic_cell.hpp"

namespace grainlab {

struct StressTensor {
  double s11 = 0, s12 = 0, s21 = 0, s22 = 0;  ///< Pa (N/m² per metre of thickness)
  double p() const { return 0.5 * (s11 + s22); }
  /// Deviator measure q = √(((σ11 − σ22)/2)² + ((σ12 + σ21)/2)²): the radius of Mohr's circle.
  double q() const;
};

/// Sums over the contact ends that belong to particles with inside[i] != 0 (the specimen),
/// each end with its own branch vector from that particle's centroid to the contact point,
/// divided by `area` (m²). Wall contacts count for the particle's end only. In a periodic
/// `cell` (area its own, det h), each branch vector runs from the nearest image of the
/// particle's centroid, so a contact across an edge counts with the branch it acts through.
StressTensor contactStress(std::span<const ContactRecord> contacts,
                           std::span<const Vec2> centroids,
                           std::span<const unsigned char> inside, double area,
                           const PeriodicCell* cell = nullptr);

}  // namespace grainlab

#pragma once
// What the sampler reads of the specimen's boundary: the membrane ring's or the periodic
// cell's area, stretches and velocity gradient, and which particles are the specimen. One
// seam, so series.csv's columns mean the same in both (docs/series-columns.md).
#include <memory>
#include <vector>

#include <Eigen/Core>

namespace grainlab {

class Membrane;
class PeriodicCell;
class World;

class SampledBoundary {
 public:
  virtual ~SampledBoundary() = default;
  /// The specimen's area (inside the ring, or the cell's det h), m².
  virtual double area() const = 0;
  /// The particles' area inside it, m².
  virtual double solidArea() const = 0;
  /// Stretches along axis 1 and axis 2 since the boundary was built: strains are measured as
  /// 1 − stretch / (stretch at the reference).
  virtual double stretch1() const = 0;
  virtual double stretch2() const = 0;
  /// The boundary's velocity gradient, 1/s.
  virtual Eigen::Matrix2d velocityGradient() const = 0;
  /// The magnitude of its strain rate, 1/s (for the inertial number).
  virtual double rateMagnitude() const = 0;
  /// 1 for the specimen's particles, 0 for the boundary's own.
  virtual const std::vector<unsigned char>& inside() const = 0;
  /// The periodic cell the branch vectors cross, or null.
  virtual const PeriodicCell* cell() const = 0;
};

/// The ring's view.
std::unique_ptr<SampledBoundary> sampleMembrane(const Membrane& membrane);
/// The world's periodic cell's view: every particle is the specimen; the stretches are the
/// diagonal of the cell's deformation gradient F.
std::unique_ptr<SampledBoundary> sampleCell(const World& world);

}  // namespace grainlab

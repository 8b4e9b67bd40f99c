#include "sampled_boundary.hpp"

#include <cmath>

#include "grainlab/membrane.hpp"
#include "grainlab/periodic_cell.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

class MembraneBoundary : public SampledBoundary {
 public:
  explicit MembraneBoundary(const Membrane& m) : m_(m) {}
  double area() const override { return m_.enclosedArea(); }
  double solidArea() const override { return m_.solidArea(); }
  double stretch1() const override { return m_.stretch1(); }
  double stretch2() const override { return m_.stretch2(); }
  Eigen::Matrix2d velocityGradient() const override { return m_.measuredVelocityGradient(); }
  double rateMagnitude() const override { return m_.rateMagnitude(); }
  const std::vector<unsigned char>& inside() const override { return m_.inside(); }
  const PeriodicCell* cell() const override { return nullptr; }

 private:
  const Membrane& m_;
};

class CellBoundary : public SampledBoundary {
 public:
  explicit CellBoundary(const World& world) : world_(world), inside_(static_cast<size_t>(world.size()), 1) {
    for (int k = 0; k < world.size(); ++k) solidArea_ += world.area(k);
  }
  double area() const override { return own().area(); }
  double solidArea() const override { return solidArea_; }
  double stretch1() const override { return own().deformation()(0, 0); }
  double stretch2() const override { return own().deformation()(1, 1); }
  Eigen::Matrix2d velocityGradient() const override { return own().velocityGradient(); }
  double rateMagnitude() const override {
    // As the membrane's: |mean| + the radius of the strain rate's Mohr circle.
    const Eigen::Matrix2d& l = own().velocityGradient();
    const double d11 = -l(0, 0), d22 = -l(1, 1), d12 = -0.5 * (l(0, 1) + l(1, 0));
    return std::abs(0.5 * (d11 + d22)) + std::hypot(0.5 * (d11 - d22), d12);
  }
  const std::vector<unsigned char>& inside() const override { return inside_; }
  const PeriodicCell* cell() const override { return world_.periodicCell(); }

 private:
  const PeriodicCell& own() const { return *world_.periodicCell(); }
  const World& world_;
  std::vector<unsigned char> inside_;
  double solidArea_ = 0;
};

}  // namespace

std::unique_ptr<SampledBoundary> sampleMembrane(const Membrane& membrane) {
  return std::make_unique<MembraneBoundary>(membrane);
}

std::unique_ptr<SampledBoundary> sampleCell(const World& world) { return std::make_unique<CellBoundary>(world); }

}  // namespace grainlab

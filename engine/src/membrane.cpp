#include "grainlab/membrane.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

namespace grainlab {

Membrane::Membrane(World& world) : world_(world) {
  const auto boundary = world.boundaryFlags();
  const auto x = world.positions();
  inside_.assign(boundary.begin(), boundary.end());
  for (auto& flag : inside_) flag = flag ? 0 : 1;
  for (int k = 0; k < world.size(); ++k) {
    if (boundary[k]) {
      ring_.push_back(k);
      centre_ += x[k];
      ringRadius_ += world.boundingRadii()[k];
    } else {
      solidArea_ += world.area(k);
      ++specimenCount_;
    }
  }
  if (ring_.size() < 3) throw std::invalid_argument("a membrane needs at least 3 boundary particles");
  centre_ /= static_cast<double>(ring_.size());
  ringRadius_ /= static_cast<double>(ring_.size());
  // Angular order makes the ring a simple polygon for the area.
  std::sort(ring_.begin(), ring_.end(), [&](int a, int b) {
    return std::atan2(x[a].y() - centre_.y(), x[a].x() - centre_.x()) <
           std::atan2(x[b].y() - centre_.y(), x[b].x() - centre_.x());
  });
}

void Membrane::setStrainRates(double rate11, double rate22) {
  rate11_ = rate11;
  rate22_ = rate22;
  rate12_ = 0;
  spin_ = 0;
}

void Membrane::setStrainRate(double rate11, double rate22, double rate12, double spin) {
  rate11_ = rate11;
  rate22_ = rate22;
  rate12_ = rate12;
  spin_ = spin;
}

double Membrane::rateMagnitude() const {
  // On the axes, the rates themselves (the paper's path keeps its arithmetic exactly).
  if (rate12_ == 0) return std::max(std::abs(rate11_), std::abs(rate22_));
  const double mean = 0.5 * (rate11_ + rate22_);
  const double radius = std::hypot(0.5 * (rate11_ - rate22_), rate12_);
  return std::abs(mean) + radius;
}

Eigen::Matrix2d Membrane::velocityGradient() const {
  Eigen::Matrix2d l;
  l << -rate11_, -rate12_ + spin_, -rate12_ - spin_, -rate22_;
  return l;
}

void Membrane::applyVelocities() {
  const auto x = world_.positions();
  if (rate12_ == 0 && spin_ == 0) {
    for (int k : ring_) {
      const Vec2 d = x[k] - centre_;
      world_.setKinematicVelocity(k, Vec2(-rate11_ * d.x(), -rate22_ * d.y()), 0.0);
    }
    return;
  }
  const Eigen::Matrix2d l = velocityGradient();
  // The ring discs turn with the material (ω_z = (L21 − L12)/2 = −w), so under a spin their
  // surfaces move with the specimen they touch instead of rubbing against it.
  for (int k : ring_) world_.setKinematicVelocity(k, l * (x[k] - centre_), -spin_);
}

void Membrane::advance(double dt) {
  // Positions moved by x += v dt with v = −ε̇ (x − c): lengths scale by (1 − ε̇ dt) exactly.
  stretch1_ *= 1.0 - rate11_ * dt;
  stretch2_ *= 1.0 - rate22_ * dt;
  deformation_ = (Eigen::Matrix2d::Identity() + velocityGradient() * dt) * deformation_;
}

Eigen::Matrix2d Membrane::measuredVelocityGradient() const {
  const auto x = world_.positions();
  const auto v = world_.velocities();
  Vec2 xm = Vec2::Zero(), vm = Vec2::Zero();
  for (int k : ring_) {
    xm += x[k];
    vm += v[k];
  }
  xm /= static_cast<double>(ring_.size());
  vm /= static_cast<double>(ring_.size());
  Eigen::Matrix2d xx = Eigen::Matrix2d::Zero(), vx = Eigen::Matrix2d::Zero();
  for (int k : ring_) {
    const Vec2 dx = x[k] - xm;
    xx += dx * dx.transpose();
    vx += (v[k] - vm) * dx.transpose();
  }
  return vx * xx.inverse();
}

double Membrane::enclosedArea() const {
  const auto x = world_.positions();
  double area2 = 0, perimeter = 0;
  for (size_t k = 0; k < ring_.size(); ++k) {
    const Vec2& a = x[ring_[k]];
    const Vec2& b = x[ring_[(k + 1) % ring_.size()]];
    area2 += cross(a - centre_, b - centre_);
    perimeter += (b - a).norm();
  }
  const double r = ringRadius_;
  return 0.5 * std::abs(area2) - perimeter * r + kPi * r * r;
}

StressTensor Membrane::boundaryStress(std::span<const ContactRecord> contacts) const {
  StressTensor s;
  for (const ContactRecord& c : contacts) {
    if (c.isWall()) continue;
    const bool iRing = !inside_[c.i], jRing = !inside_[c.j];
    if (iRing == jRing) continue;  // specimen-specimen (ring-ring pairs have no contact)
    const Vec2 onJ = c.fn * c.normal + c.ft * perp(c.normal);
    const Vec2 onSpecimen = iRing ? onJ : Vec2(-onJ);
    const Vec2 x = c.point - centre_;
    s.s11 -= onSpecimen.x() * x.x();
    s.s12 -= onSpecimen.x() * x.y();
    s.s21 -= onSpecimen.y() * x.x();
    s.s22 -= onSpecimen.y() * x.y();
  }
  const double area = enclosedArea();
  s.s11 /= area;
  s.s12 /= area;
  s.s21 /= area;
  s.s22 /= area;
  return s;
}

StressTensor Membrane::measureStress() const {
  // The servo measures every few steps: no records built, no wide state written back.
  return world_.contactStress(inside_, enclosedArea());
}

}  // namespace grainlab

#include "periodic_stages.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "grainlab/state_archive.hpp"

namespace grainlab {
namespace {

// A sampled PI loop needs its samples well inside its response time (as the membrane's).
constexpr double kMeasuresPerResponse = 4;

}  // namespace

double CellServo::rate(double stress, double dt) {
  const double error = target - stress;
  const double unclamped = kp * error + ki * (integral + error * dt);
  const double r = std::clamp(unclamped, -cap, cap);
  if (r == unclamped) integral += error * dt;  // anti-windup: integrate only while not capped
  return r;
}

CellStage::CellStage(std::string name, const CellLoading& loading, World& world, double duration, double sampleInterval)
    : name_(std::move(name)), loading_(loading), world_(world), duration_(duration),
      sampleInterval_(sampleInterval > 0 ? sampleInterval : 0.005), startTime_(world.time()), turnStart_(startTime_) {
  if (!world_.periodicCell()) throw std::invalid_argument("a cell stage needs a world with a periodic cell");
  if (!(loading_.rateCap > 0) || !(loading_.crossings > 0)) {
    throw std::invalid_argument("a cell stage's rate cap and servo crossings must be positive");
  }
  if (loading_.rotation.q > 0) loading_.d11 = loading_.d22 = loading_.d12 = CellComponent::holding(0);
  // The servos' response time: `crossings` elastic-wave crossings of the cell, against the
  // packing's modulus M = k_n / 2.
  const double modulus = 0.5 * world_.contactStiffness();
  const double crossing = std::sqrt(world_.periodicCell()->area()) / std::sqrt(modulus / world_.material().density);
  const double tau = loading_.crossings * crossing;
  measureEvery_ = std::max(1, static_cast<int>(tau / (kMeasuresPerResponse * world_.timestep())));
  dtControl_ = measureEvery_ * world_.timestep();
  for (CellServo* s : {&servo11_, &servo22_, &servo12_}) {
    s->kp = 1 / (modulus * tau);
    s->ki = s->kp / (4 * tau);
    s->cap = loading_.rateCap;
  }
  servo11_.target = loading_.d11.stress;
  servo22_.target = loading_.d22.stress;
  servo12_.target = loading_.d12.stress;
  inside_.assign(static_cast<size_t>(world_.size()), 1);
  measureStress();
}

const StressTensor& CellStage::measureStress() {
  // The same sum as contactStress over world_.contacts(), without the records (same bits).
  stress_ = world_.contactStress(inside_, world_.periodicCell()->area());
  return stress_;
}

void CellStage::control() {
  measureStress();
  if (const CellLoading::Rotation& r = loading_.rotation; r.q > 0) {
    const double theta = r.angle0 + r.rate * std::max(0.0, world_.time() - turnStart_);
    servo11_.target = r.p + r.q * std::cos(2 * theta);
    servo22_.target = r.p - r.q * std::cos(2 * theta);
    servo12_.target = r.q * std::sin(2 * theta);
  }
  const double shear = 0.5 * (stress_.s12 + stress_.s21);
  const double d11 = loading_.d11.held ? servo11_.rate(stress_.s11, dtControl_) : loading_.d11.rate;
  const double d22 = loading_.d22.held ? servo22_.rate(stress_.s22, dtControl_) : loading_.d22.rate;
  const double d12 = loading_.d12.held ? servo12_.rate(shear, dtControl_) : loading_.d12.rate;
  D_ << d11, d12, d12, d22;
  Eigen::Matrix2d L;
  L << -d11, -d12 + loading_.spin, -d12 - loading_.spin, -d22;
  world_.setCellVelocityGradient(L);
}

void CellStage::beforeStep() {
  if (stepsDone_ % measureEvery_ == 0) control();
}

void CellStage::afterStep() { ++stepsDone_; }

double CellStage::progress() const {
  return duration_ > 0 ? std::clamp((world_.time() - startTime_) / duration_, 0.0, 1.0) : 1.0;
}

void CellStage::persist(StateArchive& a) {
  a.section("cell stage");
  a(startTime_);
  if (a.loading()) turnStart_ = startTime_;  // the default; a caller that moved it says so again
  a(measureEvery_);
  a(dtControl_);
  a(stepsDone_);
  a(servo11_);
  a(servo22_);
  a(servo12_);
  a(stress_);
  a.bitwise(D_);
}

}  // namespace grainlab

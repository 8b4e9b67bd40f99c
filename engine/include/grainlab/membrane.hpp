#pragma once
// The loading boundary: a ring of kinematic boundary particles moved by a homogeneous
// velocity field v = L·(x − c) about the specimen centre c. L = −D + W: D the symmetric
// strain-rate tensor (compression positive), W the spin. The paper's biaxial test uses
// D = diag(ε̇11, ε̇22), W = 0 (principal axes fixed, θ_ε̇ = 90°) while σ12 develops freely
// inside; the loading paths of docs/loading-paths.md rotate D or add a spin (simple shear).
#include <vector>

#include <Eigen/Core>

#include "grainlab/contact.hpp"
#include "grainlab/state_archive.hpp"
#include "grainlab/stress.hpp"
#include "grainlab/world.hpp"

namespace grainlab {

class Membrane {
 public:
  /// The ring is every particle with the boundary flag; the centre is their mean position.
  explicit Membrane(World& world);

  /// Strain rates, 1/s, compression positive, along the axes (no shear, no spin).
  void setStrainRates(double rate11, double rate22);
  /// The general field: D = [[rate11, rate12], [rate12, rate22]] (1/s, compression positive)
  /// and spin w = (L12 − L21)/2, so L = [[−rate11, −rate12 + w], [−rate12 − w, −rate22]].
  /// Simple shear v1 = γ̇ (x2 − c2) is rate12 = −γ̇/2, w = γ̇/2.
  void setStrainRate(double rate11, double rate22, double rate12, double spin);
  double rate11() const { return rate11_; }
  double rate22() const { return rate22_; }
  double rate12() const { return rate12_; }
  double spin() const { return spin_; }
  /// The largest |principal strain rate| of D, 1/s (the inertial number's rate).
  double rateMagnitude() const;
  /// The prescribed velocity gradient L.
  Eigen::Matrix2d velocityGradient() const;
  /// Sets the ring particles' velocities from the field; call before each step.
  void applyVelocities();
  /// Advances the ring's stretches and deformation gradient by one step of dt (call after
  /// each step).
  void advance(double dt);

  /// Checkpoints: the strain rates, stretches and deformation gradient (the ring itself is
  /// the world's).
  void persist(StateArchive& a) {
    a.section("membrane");
    a.bitwise(centre_);  // found from the initial positions, as when the run began
    a(rate11_);
    a(rate22_);
    a(rate12_);
    a(spin_);
    a(stretch1_);
    a(stretch2_);
    a.bitwise(deformation_);
  }

  /// Current length over initial length of the ring along each axis.
  double stretch1() const { return stretch1_; }
  double stretch2() const { return stretch2_; }
  /// The ring's deformation gradient since construction: x − c = F (X − c), with F advanced
  /// by F ← (I + L dt) F each step, as the ring particles move.
  const Eigen::Matrix2d& deformation() const { return deformation_; }
  /// The velocity gradient measured from the boundary's motion: the least-squares fit of
  /// v = v0 + L (x − x̄) to the ring particles' current velocities and positions.
  Eigen::Matrix2d measuredVelocityGradient() const;

  /// Area inside the ring's inner envelope, m²: the polygon of ring centres shrunk by the
  /// ring particles' radius (A − P·r + π r² for a convex ring).
  double enclosedArea() const;
  /// Solid area of the specimen (non-boundary) particles, m².
  double solidArea() const { return solidArea_; }
  /// Void ratio of the specimen: (enclosed area − solid area) / solid area. The ring's
  /// particles are not the specimen's and lie outside the enclosed area.
  double voidRatio() const { return (enclosedArea() - solidArea_) / solidArea_; }
  int specimenCount() const { return specimenCount_; }
  /// inside[i] = 1 for specimen particles, 0 for the ring.
  const std::vector<unsigned char>& inside() const { return inside_; }

  /// The contact stress of the specimen over the enclosed area (contactStress over the
  /// world's current contacts, summed by the solver from its own pair state: same bits).
  StressTensor measureStress() const;
  /// The stress the ring applies, from the forces on its particles alone:
  /// σ_ab = −(1/A) Σ F_a (x − c)_b over the ring's contacts with the specimen, F the force on
  /// the specimen at contact point x. In equilibrium it equals the contact stress.
  StressTensor boundaryStress(std::span<const ContactRecord> contacts) const;

 private:
  World& world_;
  std::vector<int> ring_;            // indices, in angular order about the centre
  std::vector<unsigned char> inside_;
  Vec2 centre_ = Vec2::Zero();
  double ringRadius_ = 0;            // m, mean radius of the ring particles
  double solidArea_ = 0;
  int specimenCount_ = 0;
  double rate11_ = 0, rate22_ = 0;
  double rate12_ = 0, spin_ = 0;     // zero on the paper's path, which then runs as before
  double stretch1_ = 1, stretch2_ = 1;
  Eigen::Matrix2d deformation_ = Eigen::Matrix2d::Identity();
};

}  // namespace grainlab

#pragma once
// The loading boundary of the paper's biaxial test: a ring of kinematic boundary particles
// moved by the homogeneous velocity field v = −diag(ε̇11, ε̇22)·(x − c) about the specimen
// centre c (strain rates compression positive, no shear: the principal strain-rate axes stay
// fixed, θ_ε̇ = 90°), while σ12 is free to develop inside.
#include <vector>

#include "grainlab/contact.hpp"
#include "grainlab/state_archive.hpp"
#include "grainlab/stress.hpp"
#include "grainlab/world.hpp"

namespace grainlab {

class Membrane {
 public:
  /// The ring is every particle with the boundary flag; the centre is their mean position.
  explicit Membrane(World& world);

  /// Strain rates, 1/s, compression positive.
  void setStrainRates(double rate11, double rate22);
  double rate11() const { return rate11_; }
  double rate22() const { return rate22_; }
  /// Sets the ring particles' velocities from the field; call before each step.
  void applyVelocities();
  /// Advances the ring's stretches by one step of dt (call after each step).
  void advance(double dt);

  /// Checkpoints: the strain rates and stretches (the ring itself is the world's).
  void persist(StateArchive& a) {
    a.section("membrane");
    a.bitwise(centre_);  // found from the initial positions, as when the run began
    a(rate11_);
    a(rate22_);
    a(stretch1_);
    a(stretch2_);
  }

  /// Current length over initial length of the ring along each axis.
  double stretch1() const { return stretch1_; }
  double stretch2() const { return stretch2_; }

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

  /// The contact stress of the specimen over the enclosed area; `contacts` is filled with
  /// the world's current contacts.
  StressTensor measureStress(std::vector<ContactRecord>& contacts) const;
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
  double stretch1_ = 1, stretch2_ = 1;
};

}  // namespace grainlab

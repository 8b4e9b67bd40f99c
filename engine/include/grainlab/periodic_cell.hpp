#pragma once
// The periodic cell: a parallelogram with one corner at the origin and edge vectors the columns
// of h (2×2, det h > 0). Space is tiled by its images x + h n, n a pair of integers; a particle
// meets the others' images across the edges. The cell deforms with a velocity gradient L
// (ḣ = L h) and remembers its deformation gradient F since it was built (x = F X for a point
// carried by the affine field).
//
// Its basis may be exchanged for an equivalent one (the same lattice of images) when it tilts
// far: reduce() replaces h by h M, M an integer matrix of determinant 1, until each edge's
// projection on the other is at most half that edge (Lagrange-Gauss reduction; LAMMPS's
// box flip generalised to a cell that is not upper-triangular). F is not changed by it.
#include <Eigen/Core>

#include "grainlab/math.hpp"

namespace grainlab {

class StateArchive;

/// An image of the cell: the integers n1, n2 of the shift h n.
struct ImageShift {
  int n1 = 0, n2 = 0;
  bool operator==(const ImageShift&) const = default;
};

class PeriodicCell {
 public:
  using Mat2 = Eigen::Matrix2d;

  /// A cell with edges the columns of h, m. Throws std::invalid_argument unless h is finite and
  /// det h > 0 (edges counter-clockwise, non-degenerate).
  explicit PeriodicCell(const Mat2& h);

  /// The edge vectors (columns), m.
  const Mat2& edges() const { return h_; }
  /// det h, m².
  double area() const { return h_(0, 0) * h_(1, 1) - h_(0, 1) * h_(1, 0); }
  /// Distance between the two edges parallel to edge `k` (0 or 1): area / |h_k|, m.
  double width(int k) const;
  /// The smaller of the two widths, m: any pair nearer than half of it has one image in reach.
  double minWidth() const { return std::min(width(0), width(1)); }

  /// h⁻¹ x: the fractional coordinates of x (the cell is [0, 1)²).
  Vec2 fractional(const Vec2& x) const;
  /// h n, m.
  Vec2 shift(const ImageShift& n) const {
    return {h_(0, 0) * n.n1 + h_(0, 1) * n.n2, h_(1, 0) * n.n1 + h_(1, 1) * n.n2};
  }
  /// The n with x + h n inside the cell (fractional coordinates in [0, 1)).
  ImageShift wrapShift(const Vec2& x) const;
  /// x moved into the cell by a whole image shift.
  Vec2 wrap(const Vec2& x) const;
  /// The shift n that makes d + h n the shortest of all d + h m (the true nearest image, also
  /// in a strongly tilted cell). Ties go to the first found.
  ImageShift nearestImage(const Vec2& d) const;
  /// d + h n for that n: the minimum-image separation.
  Vec2 minimumImage(const Vec2& d) const { return d + shift(nearestImage(d)); }

  /// Exchanges h for the most orthogonal basis of the same lattice (see the file comment).
  /// Returns true if h changed.
  bool reduce();
  /// Whether reduce() would change h: some edge's projection on the other exceeds half of it.
  bool needsReduction() const;

  /// The velocity gradient the cell follows, 1/s.
  const Mat2& velocityGradient() const { return L_; }
  void setVelocityGradient(const Mat2& L) { L_ = L; }
  /// The affine velocity of the point x, L x, m/s.
  Vec2 affineVelocity(const Vec2& x) const { return L_ * x; }
  /// One step of dt: h ← h + (L h) dt and F ← F + (L F) dt, as every point x ← x + (L x) dt.
  void advance(double dt);
  /// The deformation gradient since the cell was built.
  const Mat2& deformation() const { return F_; }

  /// Checkpoints: h, L and F bit for bit.
  void persist(StateArchive& a);

 private:
  Mat2 h_;
  Mat2 L_ = Mat2::Zero();
  Mat2 F_ = Mat2::Identity();
};

}  // namespace grainlab

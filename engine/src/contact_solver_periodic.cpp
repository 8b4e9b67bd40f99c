// The contact solver's part in a periodic cell: the neighbour list rebuilt in the cell (after
// remapping a far-tilted cell and wrapping the positions into it), each pair's image shift, and
// the image's affine velocity, and what the wide kernel reads of the cell.
#include "contact_solver.hpp"

namespace grainlab {

Vec2 ContactSolver::affineRelativeVelocity(const PairState& p, size_t k) const {
  // The image of j moves with the cell: its velocity is j's plus ḣ n = L h n, so the pair's
  // affine relative velocity is L times the branch vector to the image.
  const Vec2* x = particles_.position.data();
  return particles_.cell->affineVelocity(x[p.j] + imageShift(k) - x[p.i]);
}

void ContactSolver::setWideCell(DiscPairKernelInput& in) const {
  const PeriodicCell& cell = *particles_.cell;
  in.imageN1 = discBatch_.imageN1();
  in.imageN2 = discBatch_.imageN2();
  const Eigen::Matrix2d& h = cell.edges();
  const Eigen::Matrix2d& L = cell.velocityGradient();
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 2; ++c) {
      in.cellEdges[2 * r + c] = h(r, c);
      in.velocityGradient[2 * r + c] = L(r, c);
    }
  }
}

bool ContactSolver::updatePeriodicNeighbors(bool moved) {
  PeriodicCell& cell = *particles_.cell;
  std::vector<Vec2>& x = particles_.position;
  if (!neighbors_.rebuildDue(x.size(), skin_, moved)) return false;
  // Only at a rebuild: the images change their names here, and nowhere else. The history
  // follows the pair (i, j), whichever image it touches.
  cell.reduce();
  for (Vec2& position : x) position = cell.wrap(position);
  neighbors_.update(x, particles_.boundingRadius, particles_.motion, cell, skin_, true);
  cellAtBuild_ = cell.edges();
  neighbors_.setImageDrift(0);
  return true;
}

void ContactSolver::cellAdvanced() {
  // An image's shift h n (|n_k| <= 1: one image in reach, positions wrapped at the build) has
  // moved by at most |Δh₁| + |Δh₂|.
  const Eigen::Matrix2d dh = particles_.cell->edges() - cellAtBuild_;
  neighbors_.setImageDrift(dh.col(0).norm() + dh.col(1).norm());
}

}  // namespace grainlab

#pragma once
// Contact ends: the unit every micromechanical estimator averages over. A contact between two
// particles has two ends, a wall contact one (particle i's); only ends of particles flagged
// inside count, so the averages use the same ends as grainlab::contactStress and the
// stress-force-fabric closed forms hold with m_v = ends / area (docs/micromechanics.md).
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

#include "grainlab/contact.hpp"
#include "grainlab/math.hpp"
#include "grainlab/periodic_cell.hpp"

namespace grainlab::analysis {

/// One contact end, in the frame of the particle it belongs to.
struct ContactEnd {
  int particle = 0;          ///< index of the particle that owns this end
  std::size_t contact = 0;   ///< index of the contact in the input span
  Vec2 normal = Vec2::Zero(); ///< unit normal pointing out of this particle (n for end i, −n for end j)
  double cos2 = 1;           ///< cos 2θ of the outward normal; the same for both ends of a contact
  double sin2 = 0;           ///< sin 2θ of the outward normal
  double fn = 0;             ///< N/m: normal force this particle exerts on its neighbour, > 0 compressive
  double ft = 0;             ///< N/m: tangential force along t_end = normal turned +90°
  Vec2 branch = Vec2::Zero(); ///< m: from this particle's centroid to the contact point
  double ln = 0;             ///< m: branch · normal
  double lt = 0;             ///< m: branch · t_end (end j uses t_j = −t_i, as the doc says)
};

/// Checks that inside and centroids match and returns the particle count. Throws
/// std::invalid_argument otherwise.
inline std::size_t checkedParticleCount(std::span<const Vec2> centroids,
                                        std::span<const unsigned char> inside) {
  if (inside.size() != centroids.size())
    throw std::invalid_argument("analysis: inside has " + std::to_string(inside.size()) +
                                " entries but centroids has " + std::to_string(centroids.size()));
  return centroids.size();
}

/// Calls visit(const ContactEnd&) for every end that belongs to a particle with inside != 0,
/// in contact order, end i before end j. Contacts whose normals are not unit vectors give
/// wrong angles: the engine's ContactRecord guarantees unit normals. Throws std::out_of_range
/// for a contact naming a particle index outside the centroid array. In a periodic `cell`, each
/// branch vector runs to the contact point from the nearest image of its particle's centroid
/// (a contact across an edge is measured to the image the particle touches through).
template <class Visit>
void forEachInsideEnd(std::span<const ContactRecord> contacts, std::span<const Vec2> centroids,
                      std::span<const unsigned char> inside, Visit&& visit, const PeriodicCell* cell = nullptr) {
  const auto n = static_cast<long long>(checkedParticleCount(centroids, inside));
  ContactEnd end;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const ContactRecord& c = contacts[k];
    if (c.i < 0 || c.i >= n || c.j >= n)
      throw std::out_of_range("analysis: contact (" + std::to_string(c.i) + ", " +
                              std::to_string(c.j) + ") names a particle outside 0.." +
                              std::to_string(n - 1));
    const bool iIn = inside[static_cast<std::size_t>(c.i)] != 0;
    const bool jIn = !c.isWall() && inside[static_cast<std::size_t>(c.j)] != 0;
    if (!iIn && !jIn) continue;
    // Both ends share the force components and e^{2iθ}: flipping n and t flips both the
    // force and its frame.
    end.contact = k;
    end.cos2 = c.normal.x() * c.normal.x() - c.normal.y() * c.normal.y();
    end.sin2 = 2.0 * c.normal.x() * c.normal.y();
    end.fn = c.fn;
    end.ft = c.ft;
    const Vec2 t = perp(c.normal);
    if (iIn) {
      end.particle = c.i;
      end.normal = c.normal;
      end.branch = c.point - centroids[static_cast<std::size_t>(c.i)];
      if (cell) end.branch = cell->minimumImage(end.branch);
      end.ln = end.branch.dot(c.normal);
      end.lt = end.branch.dot(t);
      visit(static_cast<const ContactEnd&>(end));
    }
    if (jIn) {
      end.particle = c.j;
      end.normal = -c.normal;
      end.branch = c.point - centroids[static_cast<std::size_t>(c.j)];
      if (cell) end.branch = cell->minimumImage(end.branch);
      end.ln = -end.branch.dot(c.normal);
      end.lt = -end.branch.dot(t);
      visit(static_cast<const ContactEnd&>(end));
    }
  }
}

}  // namespace grainlab::analysis

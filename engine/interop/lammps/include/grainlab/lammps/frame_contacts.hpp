#pragma once
// One instant of a LAMMPS run as grainlab's analysis sees it: the discs of a `dump custom`
// frame and the contacts of the `dump local` frame of the same timestep, turned into
// ContactRecords (normal from i to j, fn and ft of the force on j from i, the contact point
// at r_i − δ/2 along the normal, as grainlab's engine puts it). Across a periodic boundary
// the neighbour's image is appended to the centroids, so each end's branch vector is the
// one that touches.
#include <array>
#include <string>
#include <vector>

#include "grainlab/contact.hpp"
#include "grainlab/lammps/dump_reader.hpp"
#include "grainlab/math.hpp"

namespace grainlab::lammps {

/// Which `dump local` columns hold what; the defaults are those `grainlab export lammps` writes.
struct LocalColumns {
  std::string patom1 = "c_ends[1]", patom2 = "c_ends[2]";
  std::string dist = "c_pairs[1]";  ///< optional: checked against the atoms' distance if present
  std::string fx = "c_pairs[2]", fy = "c_pairs[3]";  ///< the normal force on patom1
  std::string p1 = "c_pairs[4]", p2 = "c_pairs[5]";  ///< the tangential force on patom1
};

struct FrameContacts {
  int particles = 0;                   ///< atoms in the frame
  std::vector<int> ids;                ///< LAMMPS atom id of each particle, ascending
  std::vector<Vec2> centroids;         ///< m: the atoms (ascending id), then the images contacts need
  std::vector<double> radii;           ///< m, per atom
  std::vector<Vec2> velocities;        ///< m/s (zero if the dump has no vx, vy)
  std::vector<double> spins;           ///< rad/s (zero without omegaz)
  std::vector<int> imageOf;            ///< for each image (centroids[particles + k]): its atom's index
  std::vector<ContactRecord> contacts; ///< particle-particle contacts
  double solidArea = 0;                ///< m²: Σ π r²
};

/// Fills `out` (buffers reused) from an atoms frame and the entries frame of the same timestep.
/// Throws DumpError naming the file and line: a missing column (named), an atom id repeated or
/// unknown, frames of different timesteps, or a contact whose atoms are not where its `dist` says
/// (frames that do not belong together).
void frameContacts(const DumpFrame& atoms, const DumpFrame& entries, const LocalColumns& columns, FrameContacts& out);

}  // namespace grainlab::lammps

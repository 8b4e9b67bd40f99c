#include "grainlab/lammps/frame_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace grainlab::lammps {
namespace {

[[noreturn]] void fail(const DumpFrame& f, std::int64_t line, const std::string& reason) {
  throw DumpError(f.file + ":" + std::to_string(line) + ": " + reason);
}

}  // namespace

void frameContacts(const DumpFrame& atoms, const DumpFrame& entries, const LocalColumns& columns, FrameContacts& out) {
  if (atoms.timestep != entries.timestep)
    fail(entries, entries.line,
         "the contacts' frame is of timestep " + std::to_string(entries.timestep) + " but the particles' frame (" +
             atoms.file + ":" + std::to_string(atoms.line) + ") is of timestep " + std::to_string(atoms.timestep) +
             ": the local and atom dumps do not match");
  const int cId = atoms.require("id", "the atom id");
  const int cR = atoms.require("radius", "the disc radius");
  int cX = atoms.find("x"), cY = atoms.find("y");
  bool scaled = false;
  if (cX < 0 || cY < 0) {
    cX = atoms.find("xu");
    cY = atoms.find("yu");
  }
  if (cX < 0 || cY < 0) {
    cX = atoms.find("xs");
    cY = atoms.find("ys");
    scaled = true;
  }
  if (cX < 0) atoms.require("x", "the position; or xu, or xs");
  if (cY < 0) atoms.require("y", "the position; or yu, or ys");
  const int cVx = atoms.find("vx"), cVy = atoms.find("vy"), cW = atoms.find("omegaz");
  const DumpBox& box = atoms.box;

  const std::size_t n = atoms.rows();
  out.particles = static_cast<int>(n);
  out.ids.resize(n);
  // Rows in ascending id order (a dump without `sort id` comes in any order).
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  bool sorted = true;
  for (std::size_t r = 1; r < n && sorted; ++r) sorted = atoms.at(r - 1, cId) < atoms.at(r, cId);
  if (!sorted)
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return atoms.at(a, cId) < atoms.at(b, cId); });
  out.centroids.resize(n);
  out.radii.resize(n);
  out.velocities.assign(n, Vec2::Zero());
  out.spins.assign(n, 0.0);
  out.solidArea = 0;
  int maxId = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t r = order[k];
    const double id = atoms.at(r, cId);
    if (id < 1 || id != std::floor(id)) fail(atoms, atoms.dataLine + static_cast<std::int64_t>(r), "atom id is not a positive integer");
    out.ids[k] = static_cast<int>(id);
    if (k > 0 && out.ids[k] == out.ids[k - 1])
      fail(atoms, atoms.dataLine + static_cast<std::int64_t>(r), "atom id " + std::to_string(out.ids[k]) + " appears twice");
    maxId = std::max(maxId, out.ids[k]);
    double x = atoms.at(r, cX), y = atoms.at(r, cY);
    if (scaled) {
      x = box.xlo + x * box.lx() + y * box.xy;
      y = box.ylo + y * box.ly();
    }
    out.centroids[k] = Vec2(x, y);
    out.radii[k] = atoms.at(r, cR);
    if (!std::isfinite(x) || !std::isfinite(y) || !(out.radii[k] > 0) || !std::isfinite(out.radii[k]))
      fail(atoms, atoms.dataLine + static_cast<std::int64_t>(r),
           "atom " + std::to_string(out.ids[k]) + ": its position must be finite and its radius positive");
    out.solidArea += kPi * out.radii[k] * out.radii[k];
    if (cVx >= 0 && cVy >= 0) out.velocities[k] = Vec2(atoms.at(r, cVx), atoms.at(r, cVy));
    if (cW >= 0) out.spins[k] = atoms.at(r, cW);
  }
  // id → index
  static thread_local std::vector<int> index;
  index.assign(static_cast<std::size_t>(maxId) + 1, -1);
  for (std::size_t k = 0; k < n; ++k) index[static_cast<std::size_t>(out.ids[k])] = static_cast<int>(k);

  const int c1 = entries.require(columns.patom1, "patom1, the first atom of the pair");
  const int c2 = entries.require(columns.patom2, "patom2, the second atom of the pair");
  const int cFx = entries.require(columns.fx, "fx, the normal force on patom1");
  const int cFy = entries.require(columns.fy, "fy, the normal force on patom1");
  const int cP1 = entries.require(columns.p1, "p1, the tangential force on patom1, x");
  const int cP2 = entries.require(columns.p2, "p2, the tangential force on patom1, y");
  const int cDist = entries.find(columns.dist);
  const std::size_t m = entries.rows();
  out.contacts.clear();
  out.contacts.reserve(m);
  out.imageOf.clear();
  const double lx = box.lx(), ly = box.ly();
  for (std::size_t e = 0; e < m; ++e) {
    const std::int64_t line = entries.dataLine + static_cast<std::int64_t>(e);
    const double a = entries.at(e, c1), b = entries.at(e, c2);
    const auto lookup = [&](double id) {
      if (id < 1 || id > maxId || index[static_cast<std::size_t>(id)] < 0)
        fail(entries, line,
             "atom " + std::to_string(static_cast<long long>(id)) + " is not in the particles' frame of timestep " +
                 std::to_string(atoms.timestep) + ": the local and atom dumps do not match");
      return index[static_cast<std::size_t>(id)];
    };
    const int i = lookup(a), j = lookup(b);
    Vec2 d = out.centroids[static_cast<std::size_t>(j)] - out.centroids[static_cast<std::size_t>(i)];
    // The nearest image across periodic boundaries (y first: its shift carries the tilt).
    bool shifted = false;
    if (box.periodicY) {
      const double s = std::round(d.y() / ly);
      if (s != 0) {
        d -= s * Vec2(box.xy, ly);
        shifted = true;
      }
    }
    if (box.periodicX) {
      const double s = std::round(d.x() / lx);
      if (s != 0) {
        d.x() -= s * lx;
        shifted = true;
      }
    }
    const double ri = out.radii[static_cast<std::size_t>(i)], rj = out.radii[static_cast<std::size_t>(j)];
    // The pair's geometry as LAMMPS computed its force: the normal force (fx, fy) lies along
    // x_i − x_j and `dist` is their distance. The positions say the same for pairs inside the
    // cell, but across a boundary of a cell that fix deform has just changed they give the
    // image in the new cell, where the force was computed in the old one.
    const double apart = d.norm();
    const double dist = cDist >= 0 ? entries.at(e, cDist) : apart;
    if (std::abs(dist - apart) > 1e-2 * (ri + rj))
      fail(entries, line,
           "atoms " + std::to_string(out.ids[static_cast<std::size_t>(i)]) + " and " +
               std::to_string(out.ids[static_cast<std::size_t>(j)]) + " are " + std::to_string(apart) +
               " m apart in the particles' frame but the contact says " + std::to_string(dist) + " m at timestep " +
               std::to_string(entries.timestep) + ": the local and atom dumps do not match");
    const double overlap = ri + rj - dist;
    if (!(dist > 0) || overlap <= 0) continue;  // touching pairs only
    const Vec2 fNormal(entries.at(e, cFx), entries.at(e, cFy));
    if (!std::isfinite(fNormal.x()) || !std::isfinite(fNormal.y()) || !std::isfinite(entries.at(e, cP1)) ||
        !std::isfinite(entries.at(e, cP2)))
      fail(entries, line, "the contact's force is not finite (a diverged run?)");
    const double fSize = fNormal.norm();
    Vec2 normal = fSize > 0 ? Vec2(-fNormal / fSize) : Vec2(d / apart);
    if (normal.dot(d) < 0) normal = -normal;  // a pulling dashpot points the force the other way
    d = normal * dist;
    const Vec2 t = perp(normal);
    // Force on i (the pair's normal part plus its tangential part); on j from i it is −F.
    const Vec2 F(fNormal.x() + entries.at(e, cP1), fNormal.y() + entries.at(e, cP2));
    ContactRecord c;
    c.i = i;
    c.j = j;
    if (shifted) {
      c.j = static_cast<int>(out.centroids.size());
      out.centroids.push_back(out.centroids[static_cast<std::size_t>(i)] + d);
      out.imageOf.push_back(j);
    }
    c.normal = normal;
    c.point = out.centroids[static_cast<std::size_t>(i)] + normal * (ri - 0.5 * overlap);
    c.fn = -F.dot(normal);
    c.ft = -F.dot(t);
    c.overlap = overlap;
    out.contacts.push_back(c);
  }
}

}  // namespace grainlab::lammps

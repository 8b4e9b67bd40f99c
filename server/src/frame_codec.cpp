#include "frame_codec.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "grainlab/periodic_cell.hpp"
#include "grainlab/world.hpp"

namespace grainlab::server {
namespace {

static_assert(std::endian::native == std::endian::little,
              "frames and stored series are written in the machine's byte order");

template <class T>
void put(std::string& out, std::size_t& at, T value) {
  std::memcpy(out.data() + at, &value, sizeof value);
  at += sizeof value;
}

template <class T>
T get(const std::string& in, std::size_t at) {
  T value;
  std::memcpy(&value, in.data() + at, sizeof value);
  return value;
}

}  // namespace

std::string encodeFrame(const World& world, std::vector<ContactRecord>& scratch) {
  world.contacts(scratch);
  std::optional<CellEdges> cell;
  if (const PeriodicCell* c = world.periodicCell()) {
    const auto& h = c->edges();
    cell = CellEdges{static_cast<float>(h(0, 0)), static_cast<float>(h(1, 0)), static_cast<float>(h(0, 1)),
                     static_cast<float>(h(1, 1))};
  }
  return encodeFrame(world.stepCount(), world.time(), world.positions(), world.angles(), scratch, cell);
}

std::string encodeFrame(std::int64_t step, double time, std::span<const Vec2> positions,
                        std::span<const double> angles, const std::vector<ContactRecord>& contacts,
                        std::optional<CellEdges> cell) {
  const auto n = positions.size();

  // Colour by the mean contact force magnitude on each particle; walls count for their
  // particle. Drawn chains are the particle-particle contacts in compression.
  std::vector<float> sum(n, 0.0f);
  std::vector<std::uint16_t> count(n, 0);
  std::size_t chains = 0;
  float maxContact = 0;
  for (const auto& c : contacts) {
    const auto magnitude = static_cast<float>(std::hypot(c.fn, c.ft));
    const auto i = static_cast<std::size_t>(c.i);
    if (i < n) {
      sum[i] += magnitude;
      count[i] = static_cast<std::uint16_t>(std::min<int>(count[i] + 1, 65535));
    }
    if (!c.isWall() && static_cast<std::size_t>(c.j) < n) {
      sum[static_cast<std::size_t>(c.j)] += magnitude;
      auto& k = count[static_cast<std::size_t>(c.j)];
      k = static_cast<std::uint16_t>(std::min<int>(k + 1, 65535));
      if (c.fn > 0) {
        ++chains;
        maxContact = std::max(maxContact, static_cast<float>(c.fn));
      }
    }
  }
  float maxMean = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (count[i]) sum[i] /= count[i];
    maxMean = std::max(maxMean, sum[i]);
  }

  const std::size_t header = cell ? frame::kCellHeaderBytes : frame::kHeaderBytes;
  std::string out(header + n * frame::kParticleBytes + chains * frame::kContactBytes,
                  '\0');
  std::size_t at = 0;
  std::memcpy(out.data(), frame::kMagic, 4);
  at = 4;
  put(out, at, frame::kVersion);
  put(out, at, static_cast<std::uint16_t>(header));
  put(out, at, step);
  put(out, at, time);
  put(out, at, static_cast<std::uint32_t>(n));
  put(out, at, static_cast<std::uint32_t>(chains));
  put(out, at, maxMean);
  put(out, at, maxContact);
  if (cell)
    for (float v : *cell) put(out, at, v);

  for (std::size_t i = 0; i < n; ++i) {
    put(out, at, static_cast<float>(positions[i].x()));
    put(out, at, static_cast<float>(positions[i].y()));
    put(out, at, static_cast<float>(angles[i]));
    put(out, at, sum[i]);
  }
  for (const auto& c : contacts) {
    if (c.isWall() || static_cast<std::size_t>(c.j) >= n || !(c.fn > 0)) continue;
    put(out, at, static_cast<std::uint32_t>(c.i));
    put(out, at, static_cast<std::uint32_t>(c.j));
    put(out, at, static_cast<float>(c.fn));
  }
  return out;
}

DecodedFrame decodeFrame(const std::string& bytes) {
  if (bytes.size() < frame::kHeaderBytes || std::memcmp(bytes.data(), frame::kMagic, 4) != 0)
    throw std::invalid_argument("not a grainlab frame");
  if (get<std::uint16_t>(bytes, 4) != frame::kVersion)
    throw std::invalid_argument("unknown frame version");
  const auto header = get<std::uint16_t>(bytes, 6);
  if (header < frame::kHeaderBytes || bytes.size() < header)
    throw std::invalid_argument("frame header size out of range");
  DecodedFrame f;
  f.step = get<std::int64_t>(bytes, 8);
  f.time = get<double>(bytes, 16);
  const auto n = get<std::uint32_t>(bytes, 24);
  const auto m = get<std::uint32_t>(bytes, 28);
  f.maxMeanForce = get<float>(bytes, 32);
  f.maxContactForce = get<float>(bytes, 36);
  if (bytes.size() != header + std::size_t{n} * frame::kParticleBytes +
                          std::size_t{m} * frame::kContactBytes)
    throw std::invalid_argument("frame size does not match its counts");
  if (header >= frame::kCellHeaderBytes) {
    CellEdges h;
    for (std::size_t k = 0; k < 4; ++k) h[k] = get<float>(bytes, 40 + 4 * k);
    f.cell = h;
  }
  std::size_t at = header;
  f.particles.resize(std::size_t{n} * 4);
  for (auto& v : f.particles) v = get<float>(bytes, at), at += 4;
  for (std::uint32_t k = 0; k < m; ++k) {
    f.pairs.push_back(get<std::uint32_t>(bytes, at));
    f.pairs.push_back(get<std::uint32_t>(bytes, at + 4));
    f.forces.push_back(get<float>(bytes, at + 8));
    at += frame::kContactBytes;
  }
  return f;
}

nlohmann::json shapesMessage(const World& world) {
  nlohmann::json shapes = nlohmann::json::array();
  nlohmann::json boundary = nlohmann::json::array();
  const auto kinds = world.shapes();
  const auto radii = world.boundingRadii();
  const auto flags = world.boundaryFlags();
  for (int i = 0; i < world.size(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (kinds[k] == ShapeKind::Disc) {
      shapes.push_back({{"disc", radii[k]}});
    } else if (kinds[k] == ShapeKind::Clump) {
      // Body-frame member discs about the centroid: [x0, y0, r0, x1, y1, r1, ...].
      nlohmann::json m = nlohmann::json::array();
      for (const ClumpMember& d : world.clump(i).members) m.insert(m.end(), {d.centre.x(), d.centre.y(), d.radius});
      shapes.push_back({{"clump", std::move(m)}});
    } else {
      const Polygon& p = world.polygon(i);
      nlohmann::json v = nlohmann::json::array();
      for (int j = 0; j < p.count; ++j) {
        v.push_back(p.vertices[static_cast<std::size_t>(j)].x());
        v.push_back(p.vertices[static_cast<std::size_t>(j)].y());
      }
      shapes.push_back({{"polygon", std::move(v)}});
    }
    if (flags[k]) boundary.push_back(i);
  }
  nlohmann::json walls = nlohmann::json::array();
  for (const auto& w : world.walls())
    walls.push_back({{"point", {w.point.x(), w.point.y()}}, {"normal", {w.normal.x(), w.normal.y()}}});
  return shapesMessage(std::move(shapes), std::move(boundary), std::move(walls));
}

nlohmann::json shapesMessage(nlohmann::json shapes, nlohmann::json boundary, nlohmann::json walls) {
  const auto count = shapes.size();
  return {{"type", "shapes"},
          {"count", count},
          {"shapes", std::move(shapes)},
          {"boundary", std::move(boundary)},
          {"walls", std::move(walls)}};
}

}  // namespace grainlab::server

#pragma once
// The stream's binary particle frame and the static "shapes" message (docs/stream-protocol.md).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/contact.hpp"

namespace grainlab {
class World;
}

namespace grainlab::server {

/// Layout constants of frame version 1. All fields little-endian, every offset a multiple of
/// 4 so a browser can lay Float32Array/Uint32Array views over the buffer.
namespace frame {
inline constexpr char kMagic[4] = {'G', 'L', 'F', '1'};
inline constexpr std::uint16_t kVersion = 1;
inline constexpr std::size_t kHeaderBytes = 40;
/// A run in a periodic cell writes a longer header: the cell's edge vectors h₁ (x, y) and
/// h₂ (x, y) as four f32 at offset 40. Old readers skip them (particles start at the header
/// size the frame states).
inline constexpr std::size_t kCellHeaderBytes = 56;
inline constexpr std::size_t kParticleBytes = 16;  ///< f32 x, y, angle, meanForce
inline constexpr std::size_t kContactBytes = 12;   ///< u32 i, u32 j, f32 fn
}  // namespace frame

/// Encodes the world's current state. `scratch` is reused between calls to avoid allocating
/// a contact list per frame on the simulation thread.
std::string encodeFrame(const World& world, std::vector<ContactRecord>& scratch);

/// The cell's edges as a frame carries them: h₁x, h₁y, h₂x, h₂y (m).
using CellEdges = std::array<float, 4>;

/// Encodes particles given as arrays (an imported run's frame). A contact whose j is not one of
/// the particles (a periodic image's index) colours i but draws no chain. With `cell`, the
/// frame carries the periodic cell's edges.
std::string encodeFrame(std::int64_t step, double time, std::span<const Vec2> positions,
                        std::span<const double> angles, const std::vector<ContactRecord>& contacts,
                        std::optional<CellEdges> cell = std::nullopt);

/// What a decoder reads back (tests and tools).
struct DecodedFrame {
  std::int64_t step = 0;
  double time = 0;
  float maxMeanForce = 0, maxContactForce = 0;
  std::vector<float> particles;       ///< 4 per particle
  std::vector<std::uint32_t> pairs;   ///< 2 per contact
  std::vector<float> forces;          ///< 1 per contact
  std::optional<CellEdges> cell;      ///< the periodic cell's edges, if the run has one
};
/// Throws std::invalid_argument for bytes that are not a version-1 frame.
DecodedFrame decodeFrame(const std::string& bytes);

/// The particles' shapes in their body frames, sent once per client:
/// {"type":"shapes","count":N,"shapes":[{"disc":r} | {"polygon":[x0,y0,x1,y1,...]}],
///  "boundary":[indices],"walls":[{"point":[x,y],"normal":[x,y]}]}.
nlohmann::json shapesMessage(const World& world);
/// The same message from its parts, for a run that has no World (an imported one).
nlohmann::json shapesMessage(nlohmann::json shapes, nlohmann::json boundary, nlohmann::json walls);

}  // namespace grainlab::server

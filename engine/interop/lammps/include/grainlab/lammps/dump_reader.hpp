#pragma once
// A LAMMPS text dump read one frame at a time (memory bounded by one frame): `dump custom`
// frames (ITEM: ATOMS ...) and `dump local` frames (ITEM: ENTRIES ...), any column order,
// orthogonal or triclinic boxes, gzip-compressed or plain (zlib reads both).
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace grainlab::lammps {

/// Malformed input, its what() "FILE:LINE: reason". `truncated` when the file ends inside a
/// frame (the frames before it are whole).
class DumpError : public std::runtime_error {
 public:
  DumpError(const std::string& what, bool truncated = false) : std::runtime_error(what), truncated_(truncated) {}
  bool truncated() const { return truncated_; }

 private:
  bool truncated_;
};

/// The simulation cell of a frame, 2D part: edge vectors a = (lx, 0) and b = (xy, ly).
struct DumpBox {
  double xlo = 0, xhi = 0, ylo = 0, yhi = 0;  ///< m (the cell's, not the bounding box's, for a triclinic one)
  double xy = 0;                              ///< m: tilt
  bool triclinic = false;
  bool periodicX = false, periodicY = false;
  double lx() const { return xhi - xlo; }
  double ly() const { return yhi - ylo; }
  double area() const { return lx() * ly(); }
};

struct DumpFrame {
  enum class Kind { Atoms, Entries };
  Kind kind = Kind::Atoms;
  std::int64_t timestep = 0;
  DumpBox box;
  std::vector<std::string> columns;
  std::vector<double> values;  ///< row-major: rows() × columns.size()
  std::string file;
  std::int64_t line = 0;       ///< where its ITEM: TIMESTEP is (1-based)
  std::int64_t dataLine = 0;   ///< where its first row is
  std::size_t rows() const { return columns.empty() ? 0 : values.size() / columns.size(); }
  /// The index of column `name`, or -1.
  int find(std::string_view name) const;
  /// The index of column `name`; DumpError "FILE:LINE: no column NAME (what) in ..." if absent.
  int require(std::string_view name, std::string_view what) const;
  double at(std::size_t row, int column) const { return values[row * columns.size() + static_cast<std::size_t>(column)]; }
};

/// The kind of the first frame of the dump at `path`, from its first lines only (no rows read).
/// Throws DumpError if the file has no ITEM: ATOMS or ITEM: ENTRIES line where a first frame's
/// header ends, std::runtime_error if it cannot be read.
DumpFrame::Kind dumpKind(const std::string& path);

class DumpReader {
 public:
  /// Opens `path` (gzip or plain); std::runtime_error naming it if it cannot.
  explicit DumpReader(std::string path);
  ~DumpReader();
  DumpReader(const DumpReader&) = delete;
  DumpReader& operator=(const DumpReader&) = delete;
  /// The next frame into `frame` (its buffers reused); false at the end of the file.
  /// Throws DumpError for malformed input.
  bool next(DumpFrame& frame);
  const std::string& path() const { return path_; }

 private:
  bool readLine(std::string_view& line);
  [[noreturn]] void fail(const std::string& reason, bool truncated = false) const;
  std::string path_;
  void* gz_ = nullptr;  // gzFile
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0;
  bool eof_ = false;
  std::string lineBuf_;
  std::int64_t line_ = 0;
};

}  // namespace grainlab::lammps

#include "grainlab/lammps/dump_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>

#include <zlib.h>

namespace grainlab::lammps {
namespace {

constexpr std::size_t kChunk = 1 << 20;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r' || s.back() == '\n'))
    s.remove_suffix(1);
  return s;
}

// Whitespace-separated words of `s`, into `out` (cleared).
void words(std::string_view s, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t k = 0;
  while (k < s.size()) {
    while (k < s.size() && (s[k] == ' ' || s[k] == '\t' || s[k] == '\r')) ++k;
    const std::size_t start = k;
    while (k < s.size() && s[k] != ' ' && s[k] != '\t' && s[k] != '\r') ++k;
    if (k > start) out.push_back(s.substr(start, k - start));
  }
}

bool parseDouble(std::string_view w, double& v) {
  const auto r = std::from_chars(w.data(), w.data() + w.size(), v);
  return r.ec == std::errc() && r.ptr == w.data() + w.size();
}

bool parseInt(std::string_view w, std::int64_t& v) {
  const auto r = std::from_chars(w.data(), w.data() + w.size(), v);
  return r.ec == std::errc() && r.ptr == w.data() + w.size();
}

}  // namespace

int DumpFrame::find(std::string_view name) const {
  for (std::size_t k = 0; k < columns.size(); ++k)
    if (columns[k] == name) return static_cast<int>(k);
  return -1;
}

int DumpFrame::require(std::string_view name, std::string_view what) const {
  const int k = find(name);
  if (k >= 0) return k;
  std::string have;
  for (const auto& c : columns) have += (have.empty() ? "" : " ") + c;
  throw DumpError(file + ":" + std::to_string(dataLine - 1) + ": no column " + std::string(name) + " (" +
                  std::string(what) + ") in the frame of timestep " + std::to_string(timestep) + " (its columns: " +
                  have + ")");
}

DumpFrame::Kind dumpKind(const std::string& path) {
  gzFile f = gzopen(path.c_str(), "rb");
  if (!f) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  char line[4096];
  // A frame's header is a dozen lines (TIMESTEP, TIME, UNITS, NUMBER OF, BOX BOUNDS + 3).
  for (int k = 1; k <= 16 && gzgets(f, line, sizeof line); ++k) {
    const std::string_view text = trim(line);
    const bool atoms = text.rfind("ITEM: ATOMS", 0) == 0, entries = text.rfind("ITEM: ENTRIES", 0) == 0;
    if (atoms || entries) {
      gzclose(f);
      return atoms ? DumpFrame::Kind::Atoms : DumpFrame::Kind::Entries;
    }
  }
  gzclose(f);
  throw DumpError(path + ":1: no ITEM: ATOMS or ITEM: ENTRIES line in the first frame's header: not a LAMMPS text dump");
}

DumpReader::DumpReader(std::string path) : path_(std::move(path)), buffer_(kChunk) {
  gzFile f = gzopen(path_.c_str(), "rb");
  if (!f) throw std::runtime_error("cannot read " + path_ + ": " + std::strerror(errno));
  gzbuffer(f, 1 << 18);
  gz_ = f;
}

DumpReader::~DumpReader() {
  if (gz_) gzclose(static_cast<gzFile>(gz_));
}

void DumpReader::fail(const std::string& reason, bool truncated) const {
  throw DumpError(path_ + ":" + std::to_string(line_) + ": " + reason, truncated);
}

bool DumpReader::readLine(std::string_view& line) {
  // A line inside the buffer is handed out in place; one that straddles a refill is gathered
  // in lineBuf_. Either stays valid until the next call.
  lineBuf_.clear();
  for (;;) {
    if (begin_ < end_) {
      const char* start = buffer_.data() + begin_;
      const void* nl = std::memchr(start, '\n', end_ - begin_);
      if (nl) {
        const std::size_t len = static_cast<std::size_t>(static_cast<const char*>(nl) - start);
        begin_ += len + 1;
        ++line_;
        if (lineBuf_.empty()) {
          line = std::string_view(start, len);
        } else {
          lineBuf_.append(start, len);
          line = lineBuf_;
        }
        return true;
      }
      lineBuf_.append(start, end_ - begin_);
      begin_ = end_;
    }
    if (eof_) break;
    const int got = gzread(static_cast<gzFile>(gz_), buffer_.data(), static_cast<unsigned>(buffer_.size()));
    if (got < 0) {
      int code = 0;
      const char* message = gzerror(static_cast<gzFile>(gz_), &code);
      fail(std::string("cannot read: ") + (message ? message : "zlib error"), true);
    }
    if (got == 0) eof_ = true;
    begin_ = 0;
    end_ = static_cast<std::size_t>(got);
  }
  if (lineBuf_.empty()) return false;
  ++line_;  // a last line without a newline
  line = lineBuf_;
  return true;
}

bool DumpReader::next(DumpFrame& frame) {
  std::string_view line;
  auto get = [&](const char* expecting) {
    if (!readLine(line)) fail("the file ends inside the frame of timestep " + std::to_string(frame.timestep) +
                                  " where " + expecting + " was expected (a truncated dump?)",
                              true);
  };
  // Skip blank lines between frames.
  do {
    if (!readLine(line)) return false;
  } while (trim(line).empty());
  frame.file = path_;
  frame.line = line_;
  frame.timestep = -1;
  if (trim(line) != "ITEM: TIMESTEP") fail("expected ITEM: TIMESTEP, found \"" + std::string(line.substr(0, 60)) + "\"");
  get("the timestep");
  std::int64_t step = 0;
  if (!parseInt(trim(line), step)) fail("the timestep is not an integer: \"" + std::string(line.substr(0, 60)) + "\"");
  frame.timestep = step;
  std::int64_t count = -1;
  bool haveBox = false;
  std::vector<std::string_view> w;
  for (;;) {
    get("an ITEM line");
    const std::string_view item = trim(line);
    if (item.rfind("ITEM: ", 0) != 0) fail("expected an ITEM line, found \"" + std::string(item.substr(0, 60)) + "\"");
    if (item == "ITEM: NUMBER OF ATOMS" || item == "ITEM: NUMBER OF ENTRIES") {
      get("the number of rows");
      if (!parseInt(trim(line), count) || count < 0) fail("the number of rows is not a count");
    } else if (item == "ITEM: TIME" || item == "ITEM: UNITS") {
      get("its value");
    } else if (item.rfind("ITEM: BOX BOUNDS", 0) == 0) {
      words(item.substr(16), w);
      DumpBox& b = frame.box;
      b.triclinic = !w.empty() && w[0] == "xy";
      const std::size_t flags = b.triclinic ? 3 : 0;
      if (w.size() < flags + 2) fail("ITEM: BOX BOUNDS gives no boundary flags");
      b.periodicX = w[flags] == "pp";
      b.periodicY = w[flags + 1] == "pp";
      double v[3][3] = {};
      for (int d = 0; d < 3; ++d) {
        get("a box bounds line");
        words(line, w);
        const std::size_t want = b.triclinic ? 3 : 2;
        if (w.size() != want || !parseDouble(w[0], v[d][0]) || !parseDouble(w[1], v[d][1]) ||
            (want == 3 && !parseDouble(w[2], v[d][2])))
          fail("a box bounds line needs " + std::to_string(want) + " numbers");
      }
      b.xy = b.triclinic ? v[0][2] : 0;
      const double xz = b.triclinic ? v[1][2] : 0, yz = b.triclinic ? v[2][2] : 0;
      // A triclinic dump gives the bounding box: the cell's bounds are inside it by the tilts.
      b.xlo = v[0][0] - std::min({0.0, b.xy, xz, b.xy + xz});
      b.xhi = v[0][1] - std::max({0.0, b.xy, xz, b.xy + xz});
      b.ylo = v[1][0] - std::min(0.0, yz);
      b.yhi = v[1][1] - std::max(0.0, yz);
      haveBox = true;
    } else if (item.rfind("ITEM: ATOMS", 0) == 0 || item.rfind("ITEM: ENTRIES", 0) == 0) {
      const bool atoms = item[6] == 'A';
      frame.kind = atoms ? DumpFrame::Kind::Atoms : DumpFrame::Kind::Entries;
      words(item.substr(atoms ? 11 : 13), w);
      frame.columns.assign(w.begin(), w.end());
      if (count < 0) fail("ITEM: NUMBER OF " + std::string(atoms ? "ATOMS" : "ENTRIES") + " is missing before the rows");
      if (!haveBox) fail("ITEM: BOX BOUNDS is missing before the rows");
      if (frame.columns.empty()) fail("the rows have no columns");
      frame.dataLine = line_ + 1;
      const std::size_t ncol = frame.columns.size();
      frame.values.resize(static_cast<std::size_t>(count) * ncol);
      double* out = frame.values.data();
      for (std::int64_t r = 0; r < count; ++r) {
        if (!readLine(line))
          fail("the file ends after " + std::to_string(r) + " of the " + std::to_string(count) +
                   " rows of the frame of timestep " + std::to_string(step) + " (a truncated dump?)",
               true);
        // The row's numbers, parsed in place.
        const char* p = line.data();
        const char* e = p + line.size();
        std::size_t c = 0;
        while (p < e) {
          while (p < e && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
          if (p == e) break;
          if (c == ncol) fail("row " + std::to_string(r + 1) + " has more than " + std::to_string(ncol) + " values");
          const auto res = std::from_chars(p, e, out[c]);
          if (res.ec != std::errc() || (res.ptr < e && *res.ptr != ' ' && *res.ptr != '\t' && *res.ptr != '\r'))
            fail("row " + std::to_string(r + 1) + ", column " + frame.columns[c] + ": not a number");
          p = res.ptr;
          ++c;
        }
        if (c != ncol) {
          const bool atEnd = eof_ && begin_ == end_;
          fail("row " + std::to_string(r + 1) + " of the frame of timestep " + std::to_string(step) + " has " +
                   std::to_string(c) + " of its " + std::to_string(ncol) + " values" +
                   (atEnd ? " (a truncated dump?)" : ""),
               atEnd);
        }
        out += ncol;
      }
      return true;
    } else {
      fail("unknown item \"" + std::string(item.substr(0, 60)) + "\"");
    }
  }
}

}  // namespace grainlab::lammps

#include "grainlab/vtk_writer.hpp"

#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "grainlab/output_writer.hpp"
#include "grainlab/periodic_cell.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

// The files say byte_order="LittleEndian" and the arrays are copied as they lie in memory.
static_assert(std::endian::native == std::endian::little, "the VTK writer assumes a little-endian machine");

template <class T>
constexpr const char* vtkType() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  else if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
  else if constexpr (std::is_same_v<T, std::int32_t>) return "Int32";
  else if constexpr (std::is_same_v<T, std::uint8_t>) return "UInt8";
}

// The DataArray elements of one section and the raw bytes they point into. Offsets count
// from the start of the appended data; each block is a UInt64 byte count and the values.
class AppendedData {
 public:
  template <class T>
  std::string array(const char* name, int components, const std::vector<T>& values) {
    char head[256];
    std::snprintf(head, sizeof head,
                  "<DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" format=\"appended\" "
                  "offset=\"%zu\"/>\n",
                  vtkType<T>(), name, components, bytes_.size());
    const std::uint64_t size = values.size() * sizeof(T);
    append(&size, sizeof size);
    append(values.data(), size);
    return head;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  void append(const void* p, std::size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  std::string bytes_;
};

struct Cells {
  std::vector<std::int64_t> connectivity, offsets;
  std::int64_t count() const { return static_cast<std::int64_t>(offsets.size()); }
  void close() { offsets.push_back(static_cast<std::int64_t>(connectivity.size())); }
};

std::string cellSection(const char* tag, const Cells& cells, AppendedData& data) {
  if (cells.count() == 0) return "";
  return std::string("<") + tag + ">\n" + data.array("connectivity", 1, cells.connectivity) +
         data.array("offsets", 1, cells.offsets) + "</" + tag + ">\n";
}

void writeAtomically(const fs::path& path, const std::string& head, const std::string& bytes,
                     const std::string& tail) {
  writeFileAtomically(path.string(), {head, bytes, tail});
}

struct PolyDataFile {
  std::int64_t points = 0;
  std::string pointData, cellData, pointsArray;
  Cells verts, lines, polys;
  AppendedData data;

  void write(const fs::path& path) {
    std::string head = "<?xml version=\"1.0\"?>\n"
                       "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                       "header_type=\"UInt64\">\n<PolyData>\n";
    head += "<Piece NumberOfPoints=\"" + std::to_string(points) + "\" NumberOfVerts=\"" +
            std::to_string(verts.count()) + "\" NumberOfLines=\"" + std::to_string(lines.count()) +
            "\" NumberOfStrips=\"0\" NumberOfPolys=\"" + std::to_string(polys.count()) + "\">\n";
    head += "<PointData>\n" + pointData + "</PointData>\n<CellData>\n" + cellData + "</CellData>\n";
    head += "<Points>\n" + pointsArray + "</Points>\n";
    head += cellSection("Verts", verts, data);
    head += cellSection("Lines", lines, data);
    head += cellSection("Polys", polys, data);
    head += "</Piece>\n</PolyData>\n<AppendedData encoding=\"raw\">\n_";
    writeAtomically(path, head, data.bytes(), "\n</AppendedData>\n</VTKFile>\n");
  }
};

std::string frameName(const char* kind, int frame) {
  char b[64];
  std::snprintf(b, sizeof b, "%s_%04d.vtp", kind, frame);
  return b;
}

// run.pvd is brought up to date at most this often (s of wall time) while the run goes on.
constexpr double kCollectionEverySeconds = 5.0;

double wallClock() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// The periodic cell's outline: points 0, h1, h1 + h2, h2 and one closed line through them; the
// edges also as cell data, h1 and h2 (m).
void writeCellOutline(const PeriodicCell& cell, const fs::path& path) {
  const auto& h = cell.edges();
  const Vec2 h1(h(0, 0), h(1, 0)), h2(h(0, 1), h(1, 1));
  PolyDataFile outline;
  std::vector<double> points;
  for (const Vec2& p : {Vec2(0, 0), h1, Vec2(h1 + h2), h2}) points.insert(points.end(), {p.x(), p.y(), 0.0});
  outline.points = 4;
  outline.lines.connectivity = {0, 1, 2, 3, 0};
  outline.lines.close();
  AppendedData& d = outline.data;
  outline.cellData = d.array("h1", 3, std::vector<double>{h1.x(), h1.y(), 0.0}) +
                     d.array("h2", 3, std::vector<double>{h2.x(), h2.y(), 0.0}) +
                     d.array("area", 1, std::vector<double>{cell.area()});
  outline.pointsArray = d.array("Points", 3, points);
  outline.write(path);
}

}  // namespace

VtkWriter::VtkWriter(std::string directory, int every) : dir_(std::move(directory)), every_(every) {
  if (every_ < 1) throw std::invalid_argument("VtkWriter: every must be >= 1, got " + std::to_string(every_));
}

void VtkWriter::onStart(const Scene&, const World&) {
  const fs::path vtk = fs::path(dir_) / "vtk";
  // Frames of an earlier run in the same directory would mix into this one's time series.
  if (fs::exists(vtk)) {
    for (const auto& entry : fs::directory_iterator(vtk)) {
      if (entry.path().extension() == ".vtp" || entry.path().extension() == ".pvd") fs::remove(entry.path());
    }
  }
  fs::create_directories(vtk);
}

void VtkWriter::persistOutput(StateArchive& a) {
  a.section("vtk");
  a(samples_);
  a(lastFrameStep_);
  a(bytes_);
  a(seconds_);
  std::uint64_t n = frames_.size();
  a(n);
  if (a.loading()) frames_.resize(n);
  for (auto& [time, frame] : frames_) {
    a(time);
    a(frame);
  }
}

void VtkWriter::onResume(const Scene&, const World&) {
  const fs::path vtk = fs::path(dir_) / "vtk";
  fs::create_directories(vtk);
  for (const auto& entry : fs::directory_iterator(vtk)) {
    if (entry.path().extension() != ".vtp") continue;
    // particles_NNNN.vtp / contacts_NNNN.vtp: the frame number after the last underscore
    const std::string stem = entry.path().stem().string();
    const auto at = stem.rfind('_');
    if (at == std::string::npos || at + 1 == stem.size() ||
        stem.find_first_not_of("0123456789", at + 1) != std::string::npos) continue;
    if (std::stoll(stem.substr(at + 1)) >= static_cast<long long>(frames_.size())) fs::remove(entry.path());
  }
  if (!frames_.empty()) writeCollection();
}

void VtkWriter::onSample(const Sample&, const World& world) {
  if (samples_++ % every_ == 0) writeFrame(world);
}

void VtkWriter::onFinish(const RunSummary& summary, const World& world) {
  // A failed run's state may be non-finite; its last good state is the last sample's frame.
  if (summary.status != RunStatus::Failed && world.stepCount() != lastFrameStep_) writeFrame(world);
  if (!frames_.empty()) writeCollection();
}

void VtkWriter::writeFrame(const World& world) {
  const auto start = std::chrono::steady_clock::now();
  const int frame = static_cast<int>(frames_.size());
  const fs::path vtk = fs::path(dir_) / "vtk";
  const int n = world.size();
  const auto x = world.positions();
  const auto v = world.velocities();
  world.contacts(contacts_);

  // Per particle: contacts touching it and the mean magnitude of their forces.
  std::vector<std::int32_t> coordination(static_cast<size_t>(n), 0);
  std::vector<double> forceSum(static_cast<size_t>(n), 0.0);
  for (const ContactRecord& c : contacts_) {
    const double f = std::hypot(c.fn, c.ft);
    ++coordination[c.i];
    forceSum[c.i] += f;
    if (!c.isWall()) {
      ++coordination[c.j];
      forceSum[c.j] += f;
    }
  }

  // Points: the centroids, then each polygon's corners. Corners carry their polygon's values
  // (so a polygon colours uniformly) and radius 0 (so glyphs scaled by radius draw discs only).
  PolyDataFile particles;
  std::vector<double> points, velocity, spin, angle, radius, meanForce;
  std::vector<std::int32_t> id, coord;
  std::vector<std::uint8_t> boundary;
  std::vector<std::int32_t> cellId;
  std::vector<Vec2> corners;
  auto addPoint = [&](const Vec2& p, int k, double r) {
    points.insert(points.end(), {p.x(), p.y(), 0.0});
    velocity.insert(velocity.end(), {v[k].x(), v[k].y(), 0.0});
    spin.push_back(world.spins()[k]);
    angle.push_back(world.angles()[k]);
    radius.push_back(r);
    meanForce.push_back(coordination[k] ? forceSum[k] / coordination[k] : 0.0);
    id.push_back(k);
    coord.push_back(coordination[k]);
    boundary.push_back(world.boundaryFlags()[k] ? 1 : 0);
  };
  for (int k = 0; k < n; ++k) {
    const bool disc = world.shapes()[k] == ShapeKind::Disc;
    addPoint(x[k], k, disc ? world.boundingRadii()[k] : 0.0);
  }
  // VTK numbers cells verts first, then polys: the discs' and clump members' ids, then the
  // polygons'.
  std::int64_t next = n;
  std::vector<ClumpMember> members;
  for (int k = 0; k < n; ++k) {
    if (world.shapes()[k] == ShapeKind::Clump) {
      // A clump is drawn as its discs: one vertex cell per member, carrying the clump's id.
      world.worldMembers(k, members);
      for (const ClumpMember& m : members) {
        addPoint(m.centre, k, m.radius);
        particles.verts.connectivity.push_back(next++);
        particles.verts.close();
        cellId.push_back(k);
      }
      continue;
    }
    if (world.shapes()[k] != ShapeKind::Disc) continue;
    particles.verts.connectivity.push_back(k);
    particles.verts.close();
    cellId.push_back(k);
  }
  for (int k = 0; k < n; ++k) {
    if (world.shapes()[k] != ShapeKind::Polygon) continue;
    world.worldVertices(k, corners);
    for (const Vec2& p : corners) {
      addPoint(p, k, 0.0);
      particles.polys.connectivity.push_back(next++);
    }
    particles.polys.close();
    cellId.push_back(k);
  }
  particles.points = next;
  AppendedData& pd = particles.data;
  particles.pointData = pd.array("id", 1, id) + pd.array("radius", 1, radius) + pd.array("velocity", 3, velocity) +
                        pd.array("spin", 1, spin) + pd.array("angle", 1, angle) +
                        pd.array("mean_contact_force", 1, meanForce) + pd.array("boundary", 1, boundary) +
                        pd.array("coordination", 1, coord);
  particles.cellData = pd.array("id", 1, cellId);
  particles.pointsArray = pd.array("Points", 3, points);
  particles.write(vtk / frameName("particles", frame));

  // Contacts: a line per contact between the centroids (a force chain is a path of them).
  PolyDataFile lines;
  std::vector<double> linePoints, pointFn, fn, ft, contactPoint, normal;
  std::vector<std::int32_t> ci, cj;
  std::vector<std::uint8_t> sliding;
  const double mu = world.material().friction;
  const PeriodicCell* cell = world.periodicCell();
  for (const ContactRecord& c : contacts_) {
    // In a periodic cell, to the image of j that i touches (the line does not cross the cell).
    const Vec2 end = c.isWall() ? c.point : cell ? Vec2(x[c.i] + cell->minimumImage(x[c.j] - x[c.i])) : x[c.j];
    linePoints.insert(linePoints.end(), {x[c.i].x(), x[c.i].y(), 0.0, end.x(), end.y(), 0.0});
    pointFn.insert(pointFn.end(), {c.fn, c.fn});
    const auto first = static_cast<std::int64_t>(linePoints.size() / 3 - 2);
    lines.lines.connectivity.insert(lines.lines.connectivity.end(), {first, first + 1});
    lines.lines.close();
    ci.push_back(c.i);
    cj.push_back(c.j);
    fn.push_back(c.fn);
    ft.push_back(c.ft);
    // The Coulomb cap is applied as ft = ±μ fn exactly, so equality means the contact slides.
    sliding.push_back(c.fn > 0 && std::abs(c.ft) >= mu * c.fn ? 1 : 0);
    contactPoint.insert(contactPoint.end(), {c.point.x(), c.point.y(), 0.0});
    normal.insert(normal.end(), {c.normal.x(), c.normal.y(), 0.0});
  }
  lines.points = static_cast<std::int64_t>(linePoints.size() / 3);
  AppendedData& ld = lines.data;
  lines.pointData = ld.array("fn", 1, pointFn);
  lines.cellData = ld.array("i", 1, ci) + ld.array("j", 1, cj) + ld.array("fn", 1, fn) + ld.array("ft", 1, ft) +
                   ld.array("sliding", 1, sliding) + ld.array("contact_point", 3, contactPoint) +
                   ld.array("normal", 3, normal);
  lines.pointsArray = ld.array("Points", 3, linePoints);
  lines.write(vtk / frameName("contacts", frame));

  if (cell) {
    writeCellOutline(*cell, vtk / frameName("cell", frame));
    bytes_ += fs::file_size(vtk / frameName("cell", frame));
  }

  frames_.emplace_back(world.time(), frame);
  lastFrameStep_ = world.stepCount();
  bytes_ += fs::file_size(vtk / frameName("particles", frame)) + fs::file_size(vtk / frameName("contacts", frame));
  if (collectionWrittenAt_ < 0 || wallClock() - collectionWrittenAt_ > kCollectionEverySeconds) {
    writeCollection();
    collectionWrittenAt_ = wallClock();
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void VtkWriter::writeCollection() const {
  const fs::path vtk = fs::path(dir_) / "vtk";
  auto collection = [&](const std::vector<const char*>& kinds) {
    std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
                       "byte_order=\"LittleEndian\">\n<Collection>\n";
    for (const auto& [time, frame] : frames_) {
      for (size_t part = 0; part < kinds.size(); ++part) {
        text += "<DataSet timestep=\"" + num(time) + "\" group=\"\" part=\"" + std::to_string(part) +
                "\" file=\"" + frameName(kinds[part], frame) + "\"/>\n";
      }
    }
    return text + "</Collection>\n</VTKFile>\n";
  };
  if (fs::exists(vtk / frameName("cell", frames_.front().second))) {
    // A run in a periodic cell: its outline is the third part of every frame.
    writeAtomically(vtk / "run.pvd", collection({"particles", "contacts", "cell"}), "", "");
    writeAtomically(vtk / "cell.pvd", collection({"cell"}), "", "");
  } else {
    writeAtomically(vtk / "run.pvd", collection({"particles", "contacts"}), "", "");
  }
  writeAtomically(vtk / "particles.pvd", collection({"particles"}), "", "");
  writeAtomically(vtk / "contacts.pvd", collection({"contacts"}), "", "");
}

}  // namespace grainlab

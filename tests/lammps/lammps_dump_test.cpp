// The LAMMPS dump reader and the import's refusals (engine/interop/lammps), on small dumps
// written here: no LAMMPS needed.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

#include "grainlab/lammps/dump_reader.hpp"
#include "grainlab/lammps/frame_contacts.hpp"
#include "grainlab/lammps/import.hpp"

namespace fs = std::filesystem;
using namespace grainlab::lammps;

namespace {

// A folder of this process's, removed when it exits.
fs::path scratch() {
  static const struct Folder {
    fs::path path = fs::temp_directory_path() / ("lammps_dump_test_" + std::to_string(::getpid()));
    Folder() { fs::create_directories(path); }
    ~Folder() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  } folder;
  return folder.path;
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// Two discs of radius 0.55 one unit apart along x (overlapping by 0.1), in a 10 × 10 cell.
std::string atomsFrame(long step, const std::string& columns = "id type x y vx vy omegaz radius",
                       const std::string& rows = "1 1 1 1 0 0 0 0.55\n2 1 2 1 0 0 0 0.55\n",
                       const std::string& box = "ITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n-0.5 0.5\n") {
  return "ITEM: TIMESTEP\n" + std::to_string(step) + "\nITEM: NUMBER OF ATOMS\n2\n" + box + "ITEM: ATOMS " + columns +
         "\n" + rows;
}

// The pair (1, 2) pushed apart: on atom 1 a normal force −F x̂ and a tangential force −T ŷ.
std::string localFrame(long step, double F = 3, double T = 1) {
  return "ITEM: TIMESTEP\n" + std::to_string(step) +
         "\nITEM: NUMBER OF ENTRIES\n1\nITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n-0.5 0.5\n"
         "ITEM: ENTRIES c_ends[1] c_ends[2] c_pairs[1] c_pairs[2] c_pairs[3] c_pairs[4] c_pairs[5]\n"
         "1 2 1 " + std::to_string(-F) + " 0 0 " + std::to_string(-T) + "\n";
}

}  // namespace

TEST(LammpsDump, ReadsAnyColumnOrderAndATriclinicCell) {
  const fs::path dir = scratch();
  // Columns shuffled; a triclinic cell: bounding box [−2, 10] in x with tilt xy = −2.
  write(dir / "a.dump", atomsFrame(5, "radius y id x type", "0.5 1 1 3 1\n0.5 1 2 4 1\n",
                                   "ITEM: BOX BOUNDS xy xz yz pp pp pp\n-2 10 -2\n0 8 0\n-0.5 0.5 0\n"));
  DumpReader reader((dir / "a.dump").string());
  DumpFrame f;
  ASSERT_TRUE(reader.next(f));
  EXPECT_EQ(f.timestep, 5);
  EXPECT_TRUE(f.box.triclinic);
  EXPECT_DOUBLE_EQ(f.box.xlo, 0);   // the cell: xlo_bound − min(0, xy)
  EXPECT_DOUBLE_EQ(f.box.xhi, 10);  // xhi_bound − max(0, xy)
  EXPECT_DOUBLE_EQ(f.box.xy, -2);
  EXPECT_EQ(f.at(1, f.require("x", "")), 4);
  EXPECT_FALSE(reader.next(f));
}

TEST(LammpsDump, ReadsGzip) {
  const fs::path dir = scratch();
  const std::string text = atomsFrame(0) + atomsFrame(10);
  gzFile g = gzopen((dir / "a.dump.gz").c_str(), "wb");
  gzwrite(g, text.data(), static_cast<unsigned>(text.size()));
  gzclose(g);
  DumpReader reader((dir / "a.dump.gz").string());
  DumpFrame f;
  ASSERT_TRUE(reader.next(f));
  ASSERT_TRUE(reader.next(f));
  EXPECT_EQ(f.timestep, 10);
  EXPECT_EQ(f.rows(), 2u);
  EXPECT_FALSE(reader.next(f));
}

TEST(LammpsDump, ContactForcesAndStressFollowGrainlabsConventions) {
  DumpFrame atoms, entries;
  const fs::path dir = scratch();
  write(dir / "a.dump", atomsFrame(0));
  write(dir / "c.dump", localFrame(0));
  DumpReader(dir.string() + "/a.dump").next(atoms);
  DumpReader(dir.string() + "/c.dump").next(entries);
  FrameContacts c;
  frameContacts(atoms, entries, LocalColumns{}, c);
  ASSERT_EQ(c.contacts.size(), 1u);
  const auto& k = c.contacts[0];
  // n from 1 to 2 = +x; force on 2 from 1 = +3 x̂ + 1 ŷ: fn = 3 (compressive), ft along t = +y: 1.
  EXPECT_DOUBLE_EQ(k.normal.x(), 1);
  EXPECT_DOUBLE_EQ(k.fn, 3);
  EXPECT_DOUBLE_EQ(k.ft, 1);
  EXPECT_NEAR(k.overlap, 0.1, 1e-15);
  EXPECT_NEAR(k.point.x(), 1 + 0.55 - 0.05, 1e-15);  // r_i − δ/2 from i, as in the engine
}

TEST(LammpsDump, APeriodicContactUsesTheNeighboursImage) {
  DumpFrame atoms, entries;
  const fs::path dir = scratch();
  // Atom 2 at x = 9.9 touches atom 1 at x = 0.5 through the periodic boundary (distance 0.6).
  write(dir / "a.dump", atomsFrame(0, "id type x y vx vy omegaz radius",
                                   "1 1 0.5 1 0 0 0 0.35\n2 1 9.9 1 0 0 0 0.35\n"));
  write(dir / "c.dump", "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ENTRIES\n1\nITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n-0.5 0.5\n"
                        "ITEM: ENTRIES c_ends[1] c_ends[2] c_pairs[1] c_pairs[2] c_pairs[3] c_pairs[4] c_pairs[5]\n"
                        "1 2 0.6 2 0 0 0\n");
  DumpReader(dir.string() + "/a.dump").next(atoms);
  DumpReader(dir.string() + "/c.dump").next(entries);
  FrameContacts c;
  frameContacts(atoms, entries, LocalColumns{}, c);
  ASSERT_EQ(c.contacts.size(), 1u);
  EXPECT_NEAR(c.contacts[0].normal.x(), -1, 1e-12);  // from 1 towards 2's image at x = −0.1
  EXPECT_EQ(c.centroids.size(), 3u);
  EXPECT_NEAR(c.centroids[2].x(), -0.1, 1e-12);
  EXPECT_NEAR(c.contacts[0].fn, 2, 1e-12);
}

TEST(LammpsImport, ATruncatedLastFrameIsReportedAndTheFramesBeforeKept) {
  const fs::path dir = scratch();
  std::string lastFrame = atomsFrame(20);
  lastFrame.resize(lastFrame.size() - 12);  // cut inside the second atom's row
  write(dir / "a.dump", atomsFrame(0) + atomsFrame(10) + lastFrame);
  write(dir / "c.dump", localFrame(0) + localFrame(10) + localFrame(20));
  const ImportReport r = importLammps({(dir / "a.dump").string(), (dir / "c.dump").string()}, (dir / "out").string());
  EXPECT_EQ(r.frames, 2);
  EXPECT_EQ(r.lastTimestep, 10);
  EXPECT_NE(r.warning.find("a.dump:33:"), std::string::npos) << r.warning;
  EXPECT_NE(r.warning.find("truncated"), std::string::npos) << r.warning;
  std::ifstream series(dir / "out" / "series.csv");
  int lines = 0;
  for (std::string line; std::getline(series, line);) ++lines;
  EXPECT_EQ(lines, 3);  // the header and two frames
}

TEST(LammpsImport, AMissingColumnIsNamedAndNothingIsWritten) {
  const fs::path dir = scratch();
  write(dir / "a.dump", atomsFrame(0, "id type x y vx vy omegaz", "1 1 1 1 0 0 0\n2 1 2 1 0 0 0\n"));
  write(dir / "c.dump", localFrame(0));
  try {
    importLammps({(dir / "a.dump").string(), (dir / "c.dump").string()}, (dir / "none").string());
    FAIL() << "imported a dump without radii";
  } catch (const DumpError& e) {
    EXPECT_NE(std::string(e.what()).find("a.dump:9: no column radius"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "none"));
}

TEST(LammpsImport, FramesOfDifferentTimestepsAreRefusedNamingThem) {
  const fs::path dir = scratch();
  write(dir / "a.dump", atomsFrame(0) + atomsFrame(10));
  write(dir / "c.dump", localFrame(0) + localFrame(20));
  try {
    importLammps({(dir / "a.dump").string(), (dir / "c.dump").string()}, (dir / "none").string());
    FAIL() << "imported mismatched frames";
  } catch (const DumpError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("c.dump:11:"), std::string::npos) << what;
    EXPECT_NE(what.find("timestep 20"), std::string::npos) << what;
    EXPECT_NE(what.find("timestep 10"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(dir / "none"));
}

TEST(LammpsImport, AContactWhoseAtomsAreElsewhereIsRefused) {
  const fs::path dir = scratch();
  write(dir / "a.dump", atomsFrame(0));
  // dist says 0.9 but the atoms are 1 apart: the local frame is not of these atoms' positions.
  std::string c = localFrame(0);
  c.replace(c.rfind("1 2 1 "), 6, "1 2 0.9 ");
  write(dir / "c.dump", c);
  try {
    importLammps({(dir / "a.dump").string(), (dir / "c.dump").string()}, (dir / "none").string());
    FAIL() << "imported a contact that does not fit its atoms";
  } catch (const DumpError& e) {
    EXPECT_NE(std::string(e.what()).find("do not match"), std::string::npos) << e.what();
  }
}

TEST(LammpsImport, ANonFiniteForceIsRefusedWithItsLine) {
  const fs::path dir = scratch();
  write(dir / "a.dump", atomsFrame(0));
  std::string c = localFrame(0);
  c.replace(c.rfind("1 2 1 "), 6, "1 2 1 nan ");
  c.erase(c.rfind(" 0 0 ") + 1, 2);  // keep seven values: nan replaces fx
  write(dir / "c.dump", c);
  try {
    importLammps({(dir / "a.dump").string(), (dir / "c.dump").string()}, (dir / "none").string());
    FAIL() << "imported a NaN force";
  } catch (const DumpError& e) {
    EXPECT_NE(std::string(e.what()).find("c.dump:10: the contact's force is not finite"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "none"));
}

TEST(LammpsImport, AFolderThatIsNotAnEarlierImportIsNotReplaced) {
  const fs::path dir = scratch();
  write(dir / "a.dump", atomsFrame(0));
  write(dir / "c.dump", localFrame(0));
  fs::create_directories(dir / "precious");
  write(dir / "precious" / "notes.txt", "keep me");
  EXPECT_THROW(importLammps({(dir / "a.dump").string(), (dir / "c.dump").string()}, (dir / "precious").string()),
               std::runtime_error);
  EXPECT_TRUE(fs::exists(dir / "precious" / "notes.txt"));
  // An earlier import is replaced.
  importLammps({(dir / "a.dump").string(), (dir / "c.dump").string()}, (dir / "imported").string());
  EXPECT_EQ(importLammps({(dir / "a.dump").string(), (dir / "c.dump").string()}, (dir / "imported").string()).frames, 1);
}

// POST /api/sweeps/import's root (import_root.hpp): inside is allowed, everything else is
// refused the same way whether it exists or not, through "..", absolute paths and symbolic links.
#include "import_root.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

namespace grainlab::server {
namespace {

namespace fs = std::filesystem;

class ImportRoot : public ::testing::Test {
 protected:
  void SetUp() override {
    base_ = fs::temp_directory_path() / ("grainlab-import-root-" + std::to_string(::getpid()));
    fs::remove_all(base_);
    fs::create_directories(base_ / "root" / "sweep");
    fs::create_directories(base_ / "root2");
    fs::create_directories(base_ / "outside");
    fs::create_directory_symlink(base_ / "outside", base_ / "root" / "escape");
  }
  void TearDown() override { fs::remove_all(base_); }
  std::string root() const { return (base_ / "root").string(); }
  fs::path base_;
};

TEST_F(ImportRoot, InsideIsResolved) {
  EXPECT_EQ(underImportRoot(root(), "sweep"), fs::canonical(base_ / "root" / "sweep"));
  EXPECT_EQ(underImportRoot(root(), (base_ / "root" / "sweep").string()), fs::canonical(base_ / "root" / "sweep"));
  EXPECT_TRUE(underImportRoot(root(), "not-yet-there"));  // inside: importSweep says why not
  EXPECT_TRUE(underImportRoot(root() + "/", "sweep"));
}

TEST_F(ImportRoot, OutsideIsRefusedWhetherItExistsOrNot) {
  for (const std::string& path : std::vector<std::string>{"/etc", "/nonexistent-grainlab-path", "..", "../outside", "sweep/../../outside",
                                 "escape", "escape/x", "../root2", (base_ / "root2").string(), "/"})
    EXPECT_FALSE(underImportRoot(root(), path)) << path;
  EXPECT_FALSE(underImportRoot("", "sweep"));
  EXPECT_FALSE(underImportRoot(root(), ""));
}

}  // namespace
}  // namespace grainlab::server

#pragma once
// A test fixture with its own scratch directory, made before each test and removed after it:
// /tmp/grainlab_<suite>_<pid>, so tests running in parallel processes do not meet.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace grainlab::testing {

class ScratchDirectoryTest : public ::testing::Test {
 protected:
  std::filesystem::path root_ =
      std::filesystem::temp_directory_path() /
      ("grainlab_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name()) + "_" +
       std::to_string(::getpid()));
  void SetUp() override { std::filesystem::create_directories(root_); }
  void TearDown() override { std::filesystem::remove_all(root_); }
};

}  // namespace grainlab::testing

#pragma once
// A file's whole contents, for tests that compare outputs byte for byte ("" if unreadable).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace grainlab::testing {

inline std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace grainlab::testing

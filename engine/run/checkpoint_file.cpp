#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "grainlab/checkpoint.hpp"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kMagic = "GRAINLAB-CHECKPOINT\n";
constexpr std::size_t kHeaderSize = kMagic.size() + 4 + 8 + 8;

template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}
template <class T>
T get(std::string_view in, std::size_t at) {
  T value;
  std::memcpy(&value, in.data() + at, sizeof value);
  return value;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error("cannot write checkpoint " + path + ": " + what);
}

// Writes all of `bytes` to a new file and fsyncs it.
void writeDurably(const std::string& path, std::string_view a, std::string_view b) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(path, std::strerror(errno));
  for (std::string_view part : {a, b}) {
    while (!part.empty()) {
      const ssize_t n = ::write(fd, part.data(), part.size());
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        const std::string why = std::strerror(errno);
        ::close(fd);
        ::unlink(path.c_str());
        fail(path, why);
      }
      part.remove_prefix(static_cast<std::size_t>(n));
    }
  }
  if (::fsync(fd) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd);
    ::unlink(path.c_str());
    fail(path, why);
  }
  ::close(fd);
}

void syncDirectory(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);  // the renames are durable once the directory is
  ::close(fd);
}

}  // namespace

std::uint64_t checkpointChecksum(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

void writeCheckpointFile(const std::string& path, std::string_view payload) {
  std::string header(kMagic);
  put(header, kCheckpointFormatVersion);
  put(header, static_cast<std::uint64_t>(payload.size()));
  put(header, checkpointChecksum(payload));
  const std::string tmp = path + ".tmp";
  writeDurably(tmp, header, payload);
  // The good checkpoint keeps its name until the new one replaces it in one rename, so a
  // kill at any moment leaves `path` readable: `.previous` is a second name (a hard link)
  // for it, made before the rename.
  std::error_code ec;
  if (fs::exists(path)) {
    const std::string previous = path + ".previous";
    fs::remove(previous, ec);
    fs::create_hard_link(path, previous, ec);
    if (ec) fs::copy_file(path, previous, fs::copy_options::overwrite_existing, ec);  // no hard links here
    if (ec) fail(previous, ec.message());
  }
  fs::rename(tmp, path, ec);
  if (ec) fail(path, ec.message());
  syncDirectory(fs::path(path).parent_path());
}

std::string checkpointPayload(std::string_view file, const std::string& name) {
  auto refuse = [&](const std::string& what) -> CheckpointError { return CheckpointError(name + ": " + what); };
  if (file.size() < kMagic.size() || file.substr(0, kMagic.size()) != kMagic) throw refuse("not a grainlab checkpoint");
  if (file.size() < kHeaderSize) throw refuse("truncated (" + std::to_string(file.size()) + " bytes, header incomplete)");
  const auto version = get<std::uint32_t>(file, kMagic.size());
  if (version != kCheckpointFormatVersion) {
    throw refuse("format version " + std::to_string(version) + ", this grainlab reads version " +
                 std::to_string(kCheckpointFormatVersion));
  }
  const auto size = get<std::uint64_t>(file, kMagic.size() + 4);
  const auto checksum = get<std::uint64_t>(file, kMagic.size() + 12);
  const std::string_view payload = file.substr(kHeaderSize);
  if (payload.size() < size) {
    throw refuse("truncated (" + std::to_string(payload.size()) + " of " + std::to_string(size) + " payload bytes)");
  }
  if (payload.size() > size) throw refuse(std::to_string(payload.size() - size) + " bytes past the end of the payload");
  if (checkpointChecksum(payload) != checksum) throw refuse("corrupt (checksum mismatch)");
  return std::string(payload);
}

std::string readCheckpointFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError(path + ": no checkpoint (" + std::strerror(errno) + ")");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return checkpointPayload(bytes.str(), path);
}

}  // namespace grainlab

#pragma once
// Checkpoint files: a run's whole state (grainlab/state_archive.hpp) in a file that is
// either complete and checked or refused.
//
// Layout (little-endian): the magic "GRAINLAB-CHECKPOINT\n" (20 bytes), the format version
// (u32), the payload's size (u64), its FNV-1a 64-bit checksum (u64), then the payload. A
// new checkpoint is written to a temporary file, flushed to disk (fsync), and renamed over
// the old one, which is first kept as `<path>.previous`: a crash at any moment leaves at
// least one complete checkpoint, and a reader never sees a torn one.
#include <cstdint>
#include <string>
#include <string_view>

#include "grainlab/state_archive.hpp"

namespace grainlab {

/// Bumped whenever the payload's layout changes; an older or newer file is refused.
inline constexpr std::uint32_t kCheckpointFormatVersion = 5;  // 2: the membrane's shear, spin and F; 3: histograms.csv; 4: the validity monitor; 5: the contact history block and rolling resistance

/// Writes `payload` to `path` atomically and durably, keeping the previous file as
/// `<path>.previous`. Throws std::runtime_error naming the file if it cannot (disk full):
/// the previous checkpoint is then untouched.
void writeCheckpointFile(const std::string& path, std::string_view payload);
/// The payload of the checkpoint at `path`. Throws CheckpointError naming the file and what
/// is wrong: missing, not a checkpoint, another format version, truncated, corrupt.
std::string readCheckpointFile(const std::string& path);
/// The checkpoint file's payload from the bytes of a whole file (for readCheckpointFile and
/// the fuzzer); `name` labels the errors.
std::string checkpointPayload(std::string_view file, const std::string& name);
/// FNV-1a, 64 bits.
std::uint64_t checkpointChecksum(std::string_view bytes);

/// When a run writes checkpoints (runScene, resumeRun).
struct CheckpointPolicy {
  std::string path;               ///< empty: none
  double everySeconds = 60;       ///< of wall time between checkpoints
  std::string sceneJson;          ///< the scene as given, kept in the checkpoint for resuming
};

}  // namespace grainlab

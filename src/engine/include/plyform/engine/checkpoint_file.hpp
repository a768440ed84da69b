#pragma once
// The checkpoint file (OUTDIR/d3dump): the records of a core::StateArchive behind a header
// with the format version and the fingerprint of the deck it belongs to, and a checksum.
//
//   "PLYFDUMP"  u32 format version  u32 0  u64 deck fingerprint  u64 record count
//   u64 payload bytes, then per record: u32 name length, name, u64 size, bytes
//   u64 FNV-1a checksum of everything before it
//
// It is written under a temporary name, flushed to the disk and renamed over the previous
// one, so a run killed while it writes leaves the previous checkpoint whole.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string_view>

#include "plyform/core/state_archive.hpp"

namespace plyform::engine {

inline constexpr std::uint32_t kCheckpointVersion = 4;
inline constexpr std::string_view checkpoint_file_name = "d3dump";

/// A checkpoint that cannot be used: the message says why (missing, not a checkpoint, another
/// format version, another deck, truncated, corrupted).
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// FNV-1a (64 bit) of `bytes`, continuing from `hash`.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash = 14695981039346656037ull);

/// Writes `records` to `file` atomically. Throws std::runtime_error naming the file on I/O
/// failure (the previous checkpoint then stays). For tests of that promise only: with
/// PLYFORM_TEST_KILL_IN_CHECKPOINT=N in the environment, the process kills itself (SIGKILL)
/// halfway through its N-th checkpoint.
void write_checkpoint(const std::filesystem::path& file, std::uint64_t fingerprint,
                      const core::StateArchive::Records& records);

/// The simulated time a checkpoint's records were saved at (engine/integrator/t); throws
/// core::StateError when they have none.
double checkpoint_time(const core::StateArchive::Records& records);

/// Reads `file` and checks its version, fingerprint and checksum; throws CheckpointError.
core::StateArchive::Records read_checkpoint(const std::filesystem::path& file,
                                            std::uint64_t fingerprint);

}  // namespace plyform::engine

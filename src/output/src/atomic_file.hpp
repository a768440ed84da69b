#pragma once
// A file written under a temporary name beside its target and renamed over the target on
// commit(), so readers never see a partly written file.

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string_view>

namespace plyform::output::detail {

class AtomicFile {
 public:
  /// Opens `target` + ".tmp" for writing; throws std::runtime_error naming it on failure.
  explicit AtomicFile(std::filesystem::path target);
  /// Removes the temporary file when commit() was not reached (an exception unwound).
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(const void* data, std::size_t bytes);
  void write(std::string_view text) { write(text.data(), text.size()); }
  /// Flushes, closes and renames the temporary file over the target.
  void commit();

 private:
  [[noreturn]] void fail(std::string_view what, const std::filesystem::path& file) const;

  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::FILE* file_ = nullptr;
};

/// The temporary name AtomicFile uses for `target`.
std::filesystem::path temp_path_for(const std::filesystem::path& target);

}  // namespace plyform::output::detail

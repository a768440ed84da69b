#include "atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace plyform::output::detail {

std::filesystem::path temp_path_for(const std::filesystem::path& target) {
  std::filesystem::path temp = target;
  temp += ".tmp";
  return temp;
}

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)), temp_(temp_path_for(target_)) {
  file_ = std::fopen(temp_.c_str(), "wb");
  if (file_ == nullptr) {
    fail("cannot open", temp_);
  }
}

AtomicFile::~AtomicFile() {
  if (file_ != nullptr) {
    std::fclose(file_);
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
  }
}

void AtomicFile::write(const void* data, std::size_t bytes) {
  if (bytes == 0) {
    return;
  }
  if (std::fwrite(data, 1, bytes, file_) != bytes) {
    fail("cannot write", temp_);
  }
}

void AtomicFile::commit() {
  if (std::fflush(file_) != 0) {
    fail("cannot write", temp_);
  }
  std::FILE* file = file_;
  file_ = nullptr;
  if (std::fclose(file) != 0) {
    const int error = errno;
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
    errno = error;
    fail("cannot write", temp_);
  }
  std::error_code ec;
  std::filesystem::rename(temp_, target_, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
    throw std::runtime_error("cannot rename " + temp_.string() + " to " + target_.string() + ": " +
                             ec.message());
  }
}

void AtomicFile::fail(std::string_view what, const std::filesystem::path& file) const {
  const int error = errno;
  throw std::runtime_error(std::string(what) + " " + file.string() + ": " +
                           (error != 0 ? std::strerror(error) : "I/O error"));
}

}  // namespace plyform::output::detail

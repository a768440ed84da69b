#include "plyform/engine/checkpoint_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

namespace plyform::engine {
namespace {

constexpr char kMagic[8] = {'P', 'L', 'Y', 'F', 'D', 'U', 'M', 'P'};
constexpr std::size_t kHeaderBytes = 8 + 4 + 4 + 8 + 8 + 8;

template <class T>
void append(std::string& out, T v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

[[noreturn]] void io_error(const std::string& what, const std::filesystem::path& file) {
  const int e = errno;
  throw std::runtime_error(what + " " + file.string() + ": " +
                           (e != 0 ? std::strerror(e) : "I/O error"));
}

// Writes all of `data` to the descriptor, retrying short writes.
bool write_all(int fd, const char* data, std::size_t bytes) {
  while (bytes > 0) {
    const ssize_t n = ::write(fd, data, bytes);
    if (n < 0) {
      if (errno == EINTR)
        continue;
      return false;
    }
    data += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return true;
}

int checkpoints_written = 0;  // for the kill test hook

}  // namespace

std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash) {
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

void write_checkpoint(const std::filesystem::path& file, std::uint64_t fingerprint,
                      const core::StateArchive::Records& records) {
  std::string body;
  for (const auto& [name, bytes] : records) {
    append<std::uint32_t>(body, static_cast<std::uint32_t>(name.size()));
    body += name;
    append<std::uint64_t>(body, bytes.size());
    body += bytes;
  }
  std::string head(kMagic, sizeof kMagic);
  append<std::uint32_t>(head, kCheckpointVersion);
  append<std::uint32_t>(head, 0);
  append<std::uint64_t>(head, fingerprint);
  append<std::uint64_t>(head, records.size());
  append<std::uint64_t>(head, body.size());
  std::string tail;
  append<std::uint64_t>(tail, fnv1a(body, fnv1a(head)));

  std::filesystem::path temp = file;
  temp += ".tmp";
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    io_error("cannot write the checkpoint", temp);
  ++checkpoints_written;
  const char* kill_at = std::getenv("PLYFORM_TEST_KILL_IN_CHECKPOINT");
  const bool kill_now = kill_at != nullptr && std::atoi(kill_at) == checkpoints_written;
  bool ok = write_all(fd, head.data(), head.size());
  if (kill_now) {
    ok = ok && write_all(fd, body.data(), body.size() / 2);
    ::fsync(fd);
    std::raise(SIGKILL);
  }
  ok = ok && write_all(fd, body.data(), body.size()) && write_all(fd, tail.data(), tail.size());
  ok = ok && ::fsync(fd) == 0;
  if (::close(fd) != 0)
    ok = false;
  if (!ok) {
    const int e = errno;
    std::filesystem::remove(temp);
    errno = e;
    io_error("cannot write the checkpoint", temp);
  }
  std::error_code ec;
  std::filesystem::rename(temp, file, ec);
  if (ec)
    throw std::runtime_error("cannot rename " + temp.string() + " to " + file.string() + ": " +
                             ec.message());
  // The rename itself reaches the disk with the folder.
  const int dir = ::open(file.parent_path().empty() ? "." : file.parent_path().c_str(),
                         O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

double checkpoint_time(const core::StateArchive::Records& records) {
  auto archive = core::StateArchive::for_loading(records);
  const auto scope = archive.scope("engine/integrator");
  double t = 0.0;
  archive.value("t", t);
  return t;
}

core::StateArchive::Records read_checkpoint(const std::filesystem::path& file,
                                            std::uint64_t fingerprint) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw CheckpointError("no checkpoint " + file.string() +
                          " (a run writes one at the *DATABASE_BINARY_D3DUMP interval and when "
                          "it is stopped by SIGINT or SIGTERM)");
  }
  std::ostringstream all;
  all << in.rdbuf();
  const std::string data = all.str();
  const std::string name = file.string();
  if (data.size() < sizeof kMagic || std::memcmp(data.data(), kMagic, sizeof kMagic) != 0)
    throw CheckpointError(name + " is not a plyform checkpoint");
  if (data.size() < kHeaderBytes)
    throw CheckpointError(name + " is truncated (" + std::to_string(data.size()) + " bytes)");
  const auto read = [&](std::size_t at, auto v) {
    std::memcpy(&v, data.data() + at, sizeof v);
    return v;
  };
  const std::uint32_t version = read(8, std::uint32_t{});
  if (version != kCheckpointVersion) {
    throw CheckpointError(name + " has checkpoint format version " + std::to_string(version) +
                          "; this plyform reads version " + std::to_string(kCheckpointVersion));
  }
  if (read(16, std::uint64_t{}) != fingerprint) {
    throw CheckpointError(name +
                          " belongs to another deck (the deck's files changed since it was "
                          "written); run the deck from the start, or restore the deck it was "
                          "written for");
  }
  const std::uint64_t count = read(24, std::uint64_t{});
  const std::uint64_t body = read(32, std::uint64_t{});
  if (data.size() != kHeaderBytes + body + 8) {
    throw CheckpointError(name + " is truncated or has extra bytes (" +
                          std::to_string(data.size()) + " bytes where its header says " +
                          std::to_string(kHeaderBytes + body + 8) + ")");
  }
  const std::string_view view(data);
  const std::uint64_t sum = read(kHeaderBytes + body, std::uint64_t{});
  if (sum != fnv1a(view.substr(kHeaderBytes, body), fnv1a(view.substr(0, kHeaderBytes))))
    throw CheckpointError(name + " is corrupted (its checksum does not match its contents)");
  core::StateArchive::Records records;
  std::size_t at = kHeaderBytes;
  const std::size_t end = kHeaderBytes + body;
  for (std::uint64_t r = 0; r < count; ++r) {
    if (at + 4 > end)
      throw CheckpointError(name + " is corrupted (record " + std::to_string(r) + ")");
    const std::uint32_t len = read(at, std::uint32_t{});
    at += 4;
    if (at + len + 8 > end)
      throw CheckpointError(name + " is corrupted (record " + std::to_string(r) + ")");
    std::string key(data.data() + at, len);
    at += len;
    const std::uint64_t size = read(at, std::uint64_t{});
    at += 8;
    if (at + size > end)
      throw CheckpointError(name + " is corrupted (record " + key + ")");
    records.emplace(std::move(key), std::string(data.data() + at, static_cast<std::size_t>(size)));
    at += static_cast<std::size_t>(size);
  }
  if (at != end)
    throw CheckpointError(name + " is corrupted (bytes after the last record)");
  return records;
}

}  // namespace plyform::engine

#pragma once
// The ranks of one run (docs/parallel.md). `mpirun -np N plyform run` starts N processes; each
// holds this process's place among them and calls the collectives below in the same order as
// every other rank. A build without MPI, or a process started without mpirun, is one rank and
// every call is a copy or nothing.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace plyform::comm {

/// MPI for the lifetime of the process's command (MPI_Init_thread ... MPI_Finalize). Made once in
/// main(); a build without MPI makes nothing.
class Session {
 public:
  Session(int* argc, char*** argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

/// True when this build can run over several ranks.
[[nodiscard]] bool mpi_available();

class Communicator {
 public:
  /// Every process of the run (MPI_COMM_WORLD; one rank without MPI).
  [[nodiscard]] static const Communicator& world();

  [[nodiscard]] int rank() const { return rank_; }
  [[nodiscard]] int size() const { return size_; }

  /// Every rank's `mine` laid end to end, rank by rank, into `all` on every rank: per_rank[r]
  /// values from rank r (the same counts on every rank; `all` holds their sum).
  void all_gather(std::span<const double> mine, std::span<double> all,
                  std::span<const std::size_t> per_rank) const;
  /// The same for raw bytes.
  void all_gather_bytes(std::span<const std::byte> mine, std::span<std::byte> all,
                        std::span<const std::size_t> per_rank) const;
  /// Values between pairs of ranks: send_counts[r] values of `send` (laid end to end, rank by
  /// rank) go to rank r, and receive_counts[r] values from rank r land in `receive` likewise.
  /// Only the ranks with a count talk (a domain's neighbours); both sides must agree on the
  /// counts. The counts to and from this rank itself must be 0.
  void exchange(std::span<const double> send, std::span<const std::size_t> send_counts,
                std::span<double> receive, std::span<const std::size_t> receive_counts) const;
  /// The largest of every rank's value.
  [[nodiscard]] long max(long mine) const;
  /// The largest of every rank's values, entry by entry, in place.
  void max_each(std::span<long> values) const;
  /// Stops every rank of the run with `code` (a rank that cannot go on while the others wait).
  [[noreturn]] void abort(int code) const;

 private:
  Communicator() = default;
  static Communicator& instance();
  int rank_ = 0;
  int size_ = 1;
  friend class Session;
};

}  // namespace plyform::comm

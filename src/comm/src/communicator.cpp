#include "plyform/comm/communicator.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#ifdef PLYFORM_HAVE_MPI
#include <mpi.h>
#endif

namespace plyform::comm {
namespace {

#ifdef PLYFORM_HAVE_MPI
// mpirun sets these for the processes it starts: a plain `plyform` (tests, scripts) then runs
// without initialising MPI at all, as one rank.
bool started_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr ||
         std::getenv("PMIX_RANK") != nullptr;
}
bool mpi_on = false;
#endif

}  // namespace

bool mpi_available() {
#ifdef PLYFORM_HAVE_MPI
  return true;
#else
  return false;
#endif
}

Session::Session([[maybe_unused]] int* argc, [[maybe_unused]] char*** argv) {
#ifndef PLYFORM_HAVE_MPI
  // Started by mpirun with several processes but built without MPI: each would think itself the
  // only one and write the same files. Say so instead.
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (size == nullptr)
    size = std::getenv("PMI_SIZE");
  if (size != nullptr && std::atoi(size) > 1) {
    std::fprintf(stderr,
                 "error: this plyform was built without MPI (PLYFORM_MPI off, or no MPI found): "
                 "it cannot run over %s ranks; run it without mpirun\n",
                 size);
    std::exit(1);
  }
#else
  if (!started_by_mpirun())
    return;
  // Only the main thread calls MPI (the OpenMP regions never do).
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  mpi_on = true;
  Communicator& w = Communicator::instance();
  MPI_Comm_rank(MPI_COMM_WORLD, &w.rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &w.size_);
#endif
}

Session::~Session() {
#ifdef PLYFORM_HAVE_MPI
  if (mpi_on)
    MPI_Finalize();
#endif
}

Communicator& Communicator::instance() {
  static Communicator w;
  return w;
}

const Communicator& Communicator::world() {
  return instance();
}

#ifdef PLYFORM_HAVE_MPI
namespace {

// MPI's counts and offsets of an all-gather from each rank's count.
void layout(std::span<const std::size_t> per_rank, std::vector<int>& counts,
            std::vector<int>& displs) {
  counts.resize(per_rank.size());
  displs.resize(per_rank.size());
  std::size_t at = 0;
  for (std::size_t r = 0; r < per_rank.size(); ++r) {
    counts[r] = static_cast<int>(per_rank[r]);
    displs[r] = static_cast<int>(at);
    at += per_rank[r];
  }
}

}  // namespace
#endif

void Communicator::all_gather(std::span<const double> mine, std::span<double> all,
                              std::span<const std::size_t> per_rank) const {
#ifdef PLYFORM_HAVE_MPI
  if (size_ > 1) {
    std::vector<int> counts, displs;
    layout(per_rank, counts, displs);
    MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(),
                   counts.data(), displs.data(), MPI_DOUBLE, MPI_COMM_WORLD);
    return;
  }
#endif
  static_cast<void>(per_rank);
  std::copy(mine.begin(), mine.end(), all.begin());
}

void Communicator::all_gather_bytes(std::span<const std::byte> mine, std::span<std::byte> all,
                                    std::span<const std::size_t> per_rank) const {
#ifdef PLYFORM_HAVE_MPI
  if (size_ > 1) {
    std::vector<int> counts, displs;
    layout(per_rank, counts, displs);
    MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_BYTE, all.data(), counts.data(),
                   displs.data(), MPI_BYTE, MPI_COMM_WORLD);
    return;
  }
#endif
  static_cast<void>(per_rank);
  std::copy(mine.begin(), mine.end(), all.begin());
}

void Communicator::exchange(std::span<const double> send, std::span<const std::size_t> send_counts,
                            std::span<double> receive,
                            std::span<const std::size_t> receive_counts) const {
#ifdef PLYFORM_HAVE_MPI
  if (size_ > 1) {
    // Posted receives first, then the sends: no rank waits on another's order.
    thread_local std::vector<MPI_Request> requests;
    requests.clear();
    std::size_t at = 0;
    for (std::size_t r = 0; r < receive_counts.size(); ++r) {
      if (receive_counts[r] > 0) {
        requests.emplace_back();
        MPI_Irecv(receive.data() + at, static_cast<int>(receive_counts[r]), MPI_DOUBLE,
                  static_cast<int>(r), 0, MPI_COMM_WORLD, &requests.back());
      }
      at += receive_counts[r];
    }
    at = 0;
    for (std::size_t r = 0; r < send_counts.size(); ++r) {
      if (send_counts[r] > 0) {
        requests.emplace_back();
        MPI_Isend(send.data() + at, static_cast<int>(send_counts[r]), MPI_DOUBLE,
                  static_cast<int>(r), 0, MPI_COMM_WORLD, &requests.back());
      }
      at += send_counts[r];
    }
    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
    return;
  }
#endif
  static_cast<void>(send);
  static_cast<void>(send_counts);
  static_cast<void>(receive);
  static_cast<void>(receive_counts);
}

void Communicator::max_each(std::span<long> values) const {
#ifdef PLYFORM_HAVE_MPI
  if (size_ > 1) {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_LONG, MPI_MAX,
                  MPI_COMM_WORLD);
  }
#endif
  static_cast<void>(values);
}

long Communicator::max(long mine) const {
  long all = mine;
#ifdef PLYFORM_HAVE_MPI
  if (size_ > 1)
    MPI_Allreduce(&mine, &all, 1, MPI_LONG, MPI_MAX, MPI_COMM_WORLD);
#endif
  return all;
}

void Communicator::abort(int code) const {
#ifdef PLYFORM_HAVE_MPI
  if (size_ > 1)
    MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::exit(code);
}

}  // namespace plyform::comm

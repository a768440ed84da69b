#include "node_share.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

#include "deterministic_sum.hpp"
#include "plyform/core/invariant.hpp"

namespace plyform::engine {

NodeLists node_lists(const core::Model& model, const std::vector<std::vector<WorkItem>>& phases,
                     std::span<const int> node_owner, std::span<const core::Index> everywhere,
                     int me, int rank_count) {
  const std::size_t n = node_owner.size();
  const auto ranks = static_cast<std::size_t>(rank_count);
  NodeLists x;
  // A rank computes every element with a node it owns, and so moves all that element's nodes.
  // This rank's nodes, and (node, rank) for each node it owns that another rank moves.
  std::vector<unsigned char> mine(n, 0), everyone(n, 0);
  std::vector<std::pair<core::Index, int>> wanted;
  std::vector<int> owners;
  for (const std::vector<WorkItem>& phase : phases) {
    for (const WorkItem& it : phase) {
      for (std::size_t e = it.begin; e < it.end; ++e) {
        const auto nodes = element_nodes(model, it, e);
        owners.clear();
        for (const core::Index node : nodes) {
          const int q = node_owner[static_cast<std::size_t>(node)];
          PLYFORM_INVARIANT(q >= 0 && q < rank_count, "a deformable element's node has an owner");
          owners.push_back(q);
        }
        const bool computed = std::find(owners.begin(), owners.end(), me) != owners.end();
        for (const core::Index node : nodes) {
          const auto i = static_cast<std::size_t>(node);
          mine[i] = mine[i] || computed;
          if (node_owner[i] != me)
            continue;
          for (const int q : owners)
            if (q != me)
              wanted.emplace_back(node, q);
        }
      }
    }
  }
  // Nodes no element touches and the nodes the whole passes read: every rank moves them.
  for (std::size_t i = 0; i < n; ++i)
    everyone[i] = node_owner[i] < 0 ? 1 : 0;
  for (const core::Index i : everywhere)
    everyone[static_cast<std::size_t>(i)] = 1;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(mine[i] || everyone[i]))
      continue;
    x.nodes.push_back(static_cast<core::Index>(i));
    if (everyone[i] && node_owner[i] == me)
      for (std::size_t q = 0; q < ranks; ++q)
        if (static_cast<int>(q) != me)
          wanted.emplace_back(static_cast<core::Index>(i), static_cast<int>(q));
  }
  x.chunk = kSumChunk;
  const std::size_t chunks = (n + kSumChunk - 1) / kSumChunk;
  x.chunk_start.assign(chunks + 1, x.nodes.size());
  for (std::size_t c = 0, j = 0; c < chunks; ++c) {
    while (j < x.nodes.size() && static_cast<std::size_t>(x.nodes[j]) < c * kSumChunk)
      ++j;
    x.chunk_start[c] = j;
  }
  // The exchange, by rank, nodes increasing: to rank q this rank's nodes q moves; from rank q,
  // q's nodes this rank moves. Both sides list the same nodes in the same order.
  std::sort(wanted.begin(), wanted.end(), [](const auto& a, const auto& b) {
    return std::tie(a.second, a.first) < std::tie(b.second, b.first);
  });
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  std::vector<std::vector<core::Index>> from(ranks), owned(ranks);
  for (std::size_t i = 0; i < n; ++i) {
    const int owner = node_owner[i];
    if (owner < 0)
      continue;
    owned[static_cast<std::size_t>(owner)].push_back(static_cast<core::Index>(i));
    if (owner != me && (mine[i] || everyone[i]))
      from[static_cast<std::size_t>(owner)].push_back(static_cast<core::Index>(i));
  }
  x.send_start.assign(ranks + 1, 0);
  for (const auto& [node, q] : wanted) {
    x.sent.push_back(node);
    ++x.send_start[static_cast<std::size_t>(q) + 1];
  }
  x.receive_start.assign(1, 0);
  x.owned_start.assign(1, 0);
  for (std::size_t q = 0; q < ranks; ++q) {
    x.send_start[q + 1] += x.send_start[q];
    x.received.insert(x.received.end(), from[q].begin(), from[q].end());
    x.receive_start.push_back(x.received.size());
    x.owned.insert(x.owned.end(), owned[q].begin(), owned[q].end());
    x.owned_start.push_back(x.owned.size());
  }
  return x;
}

NodeShare::NodeShare(const core::Model& model, const std::vector<std::vector<WorkItem>>& phases,
                     std::span<const int> node_owner, std::span<const core::Index> everywhere,
                     const comm::Communicator& comm)
    : comm_(&comm),
      lists_(node_lists(model, phases, node_owner, everywhere, comm.rank(), comm.size())) {}

void NodeShare::exchange(std::span<double* const> fields) {
  const std::size_t k = fields.size();
  const auto ranks = static_cast<std::size_t>(comm_->size());
  send_.resize(k * lists_.sent.size());
  std::size_t at = 0;
  for (const core::Index node : lists_.sent)
    for (double* f : fields)
      send_[at++] = f[static_cast<std::size_t>(node)];
  send_counts_.resize(ranks);
  receive_counts_.resize(ranks);
  for (std::size_t r = 0; r < ranks; ++r) {
    send_counts_[r] = k * (lists_.send_start[r + 1] - lists_.send_start[r]);
    receive_counts_[r] = k * (lists_.receive_start[r + 1] - lists_.receive_start[r]);
  }
  receive_.resize(k * lists_.received.size());
  comm_->exchange(send_, send_counts_, receive_, receive_counts_);
  at = 0;
  for (const core::Index node : lists_.received)
    for (double* f : fields)
      f[static_cast<std::size_t>(node)] = receive_[at++];
}

void NodeShare::gather(std::span<const Field> fields) {
  std::size_t per_node = 0;
  for (const Field& f : fields)
    per_node += f.stride;
  const auto me = static_cast<std::size_t>(comm_->rank());
  const auto ranks = static_cast<std::size_t>(comm_->size());
  send_.clear();
  for (std::size_t j = lists_.owned_start[me]; j < lists_.owned_start[me + 1]; ++j) {
    const auto node = static_cast<std::size_t>(lists_.owned[j]);
    for (const Field& f : fields)
      send_.insert(send_.end(), f.data + f.stride * node, f.data + f.stride * (node + 1));
  }
  std::vector<std::size_t> per_rank(ranks);
  for (std::size_t r = 0; r < ranks; ++r)
    per_rank[r] = per_node * (lists_.owned_start[r + 1] - lists_.owned_start[r]);
  receive_.resize(per_node * lists_.owned.size());
  comm_->all_gather(send_, receive_, per_rank);
  std::size_t at = 0;
  for (const core::Index node : lists_.owned) {
    const auto i = static_cast<std::size_t>(node);
    for (const Field& f : fields) {
      std::copy_n(receive_.begin() + static_cast<std::ptrdiff_t>(at), f.stride,
                  f.data + f.stride * i);
      at += f.stride;
    }
  }
}

}  // namespace plyform::engine

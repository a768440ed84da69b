#include "slave_share.hpp"

#include <bit>
#include <cstdint>
#include <cstring>

namespace plyform::contact {
namespace {

// A per-slave array as bytes: its data and the bytes each slave node holds.
struct SlaveArray {
  std::byte* data;
  std::size_t bytes;
};

template <class T>
void add(std::vector<SlaveArray>& a, T* data, std::size_t per_node) {
  if (data != nullptr)
    a.push_back({reinterpret_cast<std::byte*>(data), per_node * sizeof(T)});
}

template <class T>
void add(std::vector<SlaveArray>& a, std::vector<T>& v, std::size_t per_node) {
  if (!v.empty())
    add(a, v.data(), per_node);
}

// What the owner of a slave node alone updates and exchange_cycle does not carry, or carries
// only for the nodes whose force or books are not zero.
std::vector<SlaveArray> owner_arrays(PassRuntime& pr) {
  PassState& st = pr.st;
  std::vector<SlaveArray> a;
  add(a, st.frame, 9);
  add(a, st.seg, 1);
  add(a, st.side, 1);
  for (std::vector<double>* v : {&st.shape, &st.prev_shape})
    add(a, *v, 4);
  for (std::vector<double>* v : {&st.rs, &st.prev_rs})
    add(a, *v, 3);
  for (std::vector<double>* v :
       {&st.gap, &st.slip_x, &st.slip_y, &st.temperature, &st.k_normal, &st.k_tangent, &st.m_eff,
        &st.arrival_depth, &st.pressure, &st.tau_x, &st.tau_y, &st.stored, &st.gap_jump,
        &st.end_power, &st.tie_gap0, &st.rest_room})
    add(a, *v, 1);
  add(a, st.rest_from, 3);
  add(a, st.tie_state, 1);
  add(a, st.resting, 1);
  add(a, st.rest_wait, 1);
  const law::BatchHistory& h = pr.hist;
  add(a, h.state, 1);
  for (double* v : {h.beta, h.gap, h.slip_x, h.slip_y, h.opening_x, h.opening_y, h.e_damage,
                    h.e_viscous, h.e_friction, h.e_damping, h.e_healing, h.damping})
    add(a, v, 1);
  return a;
}

// A slave node's entry in a cycle's exchange: its place, segment, side, force, normal, surface
// point, shape weights, work and surface book.
constexpr std::size_t kCycleValues = 18;

// Whether a value is anything but +0: a node whose force and books are all +0 needs no entry
// (its receivers set +0 themselves, which sums as its owner's do, to the bit).
bool carries(double v) {
  return std::bit_cast<std::uint64_t>(v) != 0;
}

}  // namespace

SlaveShare::SlaveShare(const comm::Communicator& comm, const std::vector<int>& owner)
    : comm_(&comm) {
  const auto ranks = static_cast<std::size_t>(comm.size());
  mine_.resize(owner.size());
  std::vector<std::vector<std::size_t>> by_rank(ranks);
  for (std::size_t k = 0; k < owner.size(); ++k) {
    mine_[k] = owner[k] == comm.rank() ? 1 : 0;
    by_rank[static_cast<std::size_t>(owner[k])].push_back(k);
  }
  owned_start_.assign(1, 0);
  for (const auto& list : by_rank) {
    owned_.insert(owned_.end(), list.begin(), list.end());
    owned_start_.push_back(owned_.size());
  }
}

void SlaveShare::exchange_cycle(std::vector<std::unique_ptr<SlaveShare>>& shares,
                                std::vector<std::unique_ptr<PassRuntime>>& passes,
                                const std::vector<unsigned char>& active) {
  const comm::Communicator& comm = *shares.front()->comm_;
  const auto me = static_cast<std::size_t>(comm.rank());
  const auto ranks = static_cast<std::size_t>(comm.size());
  thread_local std::vector<double> send, receive, sizes;
  // This rank's entries, pass by pass: the number of entries, then the entries. Only the nodes
  // with a force or books: far from the tools most of a blank's nodes have neither.
  send.clear();
  for (std::size_t p = 0; p < passes.size(); ++p) {
    if (active[p] == 0)
      continue;
    const SlaveShare& sh = *shares[p];
    const PassState& st = passes[p]->st;
    const std::size_t count_at = send.size();
    send.push_back(0.0);
    std::size_t count = 0;
    for (std::size_t j = sh.owned_start_[me]; j < sh.owned_start_[me + 1]; ++j) {
      const std::size_t k = sh.owned_[j];
      const double* f = &st.force[3 * k];
      if (!carries(f[0]) && !carries(f[1]) && !carries(f[2]) && !carries(st.work_part[k]) &&
          !carries(st.surface_part[k]))
        continue;
      const double* n = &st.frame[9 * k];
      const double* rs = &st.rs[3 * k];
      const double* w = &st.shape[4 * k];
      send.insert(send.end(),
                  {static_cast<double>(k), static_cast<double>(st.seg[k]),
                   static_cast<double>(st.side[k]), f[0], f[1], f[2], n[0], n[1], n[2], rs[0],
                   rs[1], rs[2], w[0], w[1], w[2], w[3], st.work_part[k], st.surface_part[k]});
      ++count;
    }
    send[count_at] = static_cast<double>(count);
  }
  // How much each rank sends, then what.
  sizes.resize(ranks);
  const std::vector<std::size_t> one_each(ranks, 1);
  const double mine = static_cast<double>(send.size());
  comm.all_gather(std::span<const double>(&mine, 1), sizes, one_each);
  std::vector<std::size_t> per_rank(ranks);
  std::size_t total = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    per_rank[r] = static_cast<std::size_t>(sizes[r]);
    total += per_rank[r];
  }
  receive.resize(total);
  comm.all_gather(send, receive, per_rank);
  // The other ranks' nodes: +0 force and books, then their entries.
  std::size_t at = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    if (r == me) {
      at += per_rank[r];
      continue;
    }
    for (std::size_t p = 0; p < passes.size(); ++p) {
      if (active[p] == 0)
        continue;
      const SlaveShare& sh = *shares[p];
      PassState& st = passes[p]->st;
      for (std::size_t j = sh.owned_start_[r]; j < sh.owned_start_[r + 1]; ++j) {
        const std::size_t k = sh.owned_[j];
        st.force[3 * k] = st.force[3 * k + 1] = st.force[3 * k + 2] = 0.0;
        st.work_part[k] = st.surface_part[k] = 0.0;
      }
      const auto count = static_cast<std::size_t>(receive[at++]);
      for (std::size_t e = 0; e < count; ++e, at += kCycleValues) {
        const double* v = &receive[at];
        const auto k = static_cast<std::size_t>(v[0]);
        st.seg[k] = static_cast<core::Index>(v[1]);
        st.side[k] = static_cast<signed char>(v[2]);
        std::copy_n(v + 3, 3, &st.force[3 * k]);
        std::copy_n(v + 6, 3, &st.frame[9 * k]);
        std::copy_n(v + 9, 3, &st.rs[3 * k]);
        std::copy_n(v + 12, 4, &st.shape[4 * k]);
        st.work_part[k] = v[16];
        st.surface_part[k] = v[17];
      }
    }
  }
}

void SlaveShare::gather_state(PassRuntime& pr) {
  const auto me = static_cast<std::size_t>(comm_->rank());
  const auto ranks = static_cast<std::size_t>(comm_->size());
  const std::vector<SlaveArray> arrays = owner_arrays(pr);
  std::size_t per_node = 0;
  for (const SlaveArray& a : arrays)
    per_node += a.bytes;
  send_bytes_.clear();
  for (std::size_t j = owned_start_[me]; j < owned_start_[me + 1]; ++j) {
    const std::size_t k = owned_[j];
    for (const SlaveArray& a : arrays)
      send_bytes_.insert(send_bytes_.end(), a.data + a.bytes * k, a.data + a.bytes * (k + 1));
  }
  std::vector<std::size_t> per_rank(ranks);
  for (std::size_t r = 0; r < ranks; ++r)
    per_rank[r] = per_node * (owned_start_[r + 1] - owned_start_[r]);
  receive_bytes_.resize(per_node * owned_.size());
  comm_->all_gather_bytes(send_bytes_, receive_bytes_, per_rank);
  std::size_t at = 0;
  for (const std::size_t k : owned_) {
    for (const SlaveArray& a : arrays) {
      std::memcpy(a.data + a.bytes * k, &receive_bytes_[at], a.bytes);
      at += a.bytes;
    }
  }
}

}  // namespace plyform::contact

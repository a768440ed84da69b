#include "rank_exchange.hpp"

#include <algorithm>
#include <tuple>

#include "plyform/core/invariant.hpp"

namespace plyform::engine {
namespace {

// Every per-element array of a block's state (stresses, plastic strains, histories, ...), with
// its values per element; empty arrays are left out.
std::vector<std::vector<double>*> element_arrays(element::ShellBlockState& st) {
  std::vector<std::vector<double>*> a;
  for (auto& v : st.s)
    a.push_back(&v);
  a.push_back(&st.eps_p);
  a.push_back(&st.thickness);
  a.push_back(&st.dt_factor);
  a.push_back(&st.area);
  for (auto& v : st.hourglass)
    a.push_back(&v);
  a.push_back(&st.bulk_q);
  a.push_back(&st.history);
  a.push_back(&st.temperature);
  std::erase_if(a, [](const std::vector<double>* v) { return v->empty(); });
  return a;
}

std::vector<std::vector<double>*> element_arrays(element::SolidBlockState& st) {
  std::vector<std::vector<double>*> a;
  for (auto& v : st.s)
    a.push_back(&v);
  a.push_back(&st.eps_p);
  a.push_back(&st.hourglass);
  a.push_back(&st.bulk_q);
  a.push_back(&st.volume);
  a.push_back(&st.dt_factor);
  a.push_back(&st.history);
  a.push_back(&st.temperature);
  std::erase_if(a, [](const std::vector<double>* v) { return v->empty(); });
  return a;
}

}  // namespace

RankExchange::RankExchange(const core::Model& model,
                           const std::vector<std::vector<WorkItem>>& phases,
                           std::span<const int> node_owner, const comm::Communicator& comm)
    : comm_(&comm), phases_(phases) {
  const int me = comm.rank();
  const auto ranks = static_cast<std::size_t>(comm.size());
  shell_books_.resize(model.shell_blocks.size());
  solid_books_.resize(model.solid_blocks.size());
  std::vector<std::vector<ElementRef>> reported(ranks), split(ranks);
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> whole(ranks);
  pieces_.resize(phases.size());
  item_rank_.resize(phases.size());
  item_books_.resize(phases.size());
  for (std::size_t p = 0; p < phases.size(); ++p) {
    item_rank_[p].assign(phases[p].size(), -1);
    item_books_[p].resize(phases[p].size());
    for (std::size_t w = 0; w < phases[p].size(); ++w) {
      const WorkItem& it = phases[p][w];
      auto& books = it.shell ? shell_books_[it.block] : solid_books_[it.block];
      if (books.empty()) {
        books.resize(it.shell ? model.shell_blocks[it.block].size()
                              : model.solid_blocks[it.block].size());
      }
      std::vector<int> reporter(it.end - it.begin);
      std::size_t run_begin = it.end;  // the run of computed elements open (end: none)
      for (std::size_t e = it.begin; e < it.end; ++e) {
        const auto nodes = element_nodes(model, it, e);
        int lowest = comm.size();
        bool mine = false;
        for (const core::Index node : nodes) {
          const int owner = node_owner[static_cast<std::size_t>(node)];
          PLYFORM_INVARIANT(owner >= 0 && owner < comm.size(),
                            "a deformable element's node has an owner");
          lowest = std::min(lowest, owner);
          mine = mine || owner == me;
        }
        reporter[e - it.begin] = lowest;
        reported[static_cast<std::size_t>(lowest)].push_back({it.shell, it.block, e});
        if (mine) {
          ++computed_;
          if (run_begin == it.end)
            run_begin = e;
        } else if (run_begin != it.end) {
          pieces_[p].push_back({w, {it.shell, it.block, run_begin, e}});
          run_begin = it.end;
        }
      }
      if (run_begin != it.end)
        pieces_[p].push_back({w, {it.shell, it.block, run_begin, it.end}});
      if (std::all_of(reporter.begin(), reporter.end(),
                      [&](int r) { return r == reporter.front(); })) {
        // Its rank computed all of it, in one piece: the last one pushed.
        const int r = reporter.front();
        item_rank_[p][w] = r;
        whole[static_cast<std::size_t>(r)].emplace_back(p, w);
        if (r == me)
          my_whole_.push_back({p, w, pieces_[p].size() - 1});
      } else {
        for (std::size_t e = it.begin; e < it.end; ++e)
          split[static_cast<std::size_t>(reporter[e - it.begin])].push_back(
              {it.shell, it.block, e});
      }
    }
  }
  const auto flatten = [](const auto& lists, auto& flat, std::vector<std::size_t>& start) {
    start.assign(1, 0);
    for (const auto& list : lists) {
      flat.insert(flat.end(), list.begin(), list.end());
      start.push_back(flat.size());
    }
  };
  flatten(reported, reported_, reported_start_);
  flatten(split, split_, split_start_);
  flatten(whole, whole_, whole_start_);
  std::vector<std::vector<core::Index>> owned(ranks);
  for (std::size_t i = 0; i < node_owner.size(); ++i) {
    if (node_owner[i] >= 0)
      owned[static_cast<std::size_t>(node_owner[i])].push_back(static_cast<core::Index>(i));
  }
  flatten(owned, owned_, owned_start_);
  reported_shells_.assign(ranks, 0);
  for (std::size_t r = 0; r < ranks; ++r)
    for (std::size_t j = reported_start_[r]; j < reported_start_[r + 1]; ++j)
      reported_shells_[r] += reported_[j].shell ? 1 : 0;
}

void RankExchange::gather_nodes(std::span<double* const> fields) {
  const std::size_t k = fields.size();
  const auto me = static_cast<std::size_t>(comm_->rank());
  const auto ranks = static_cast<std::size_t>(comm_->size());
  send_.clear();
  for (std::size_t j = owned_start_[me]; j < owned_start_[me + 1]; ++j) {
    const auto node = static_cast<std::size_t>(owned_[j]);
    for (double* f : fields)
      send_.push_back(f[node]);
  }
  std::vector<std::size_t> per_rank(ranks);
  for (std::size_t r = 0; r < ranks; ++r)
    per_rank[r] = k * (owned_start_[r + 1] - owned_start_[r]);
  receive_.resize(k * owned_.size());
  comm_->all_gather(send_, receive_, per_rank);
  std::size_t at = 0;
  for (const core::Index node : owned_) {
    for (double* f : fields)
      f[static_cast<std::size_t>(node)] = receive_[at++];
  }
}

namespace {

// A rank's report as it travels, first in its part of the elements' all-gather.
constexpr std::size_t kReport = 9;

void put_report(const RankElementReport& mine, std::vector<double>& out) {
  out.insert(out.end(),
             {mine.dt_min, static_cast<double>(mine.dt_phase), static_cast<double>(mine.dt_item),
              static_cast<double>(mine.dt_element), mine.failed ? 1.0 : 0.0,
              mine.unsupported_material ? 1.0 : 0.0, static_cast<double>(mine.failed_phase),
              static_cast<double>(mine.failed_item), static_cast<double>(mine.failed_element)});
}

// The smallest step and the first failure among the ranks' reports: by value, then by place in
// the loop.
void choose(const double* v, RankElementReport& best) {
  const auto as_index = [](double x) { return static_cast<std::size_t>(x); };
  const auto place = [](const double* w, std::size_t at) {
    return std::make_tuple(w[at], w[at + 1], w[at + 2]);
  };
  if (std::make_tuple(v[0], v[1], v[2], v[3]) <
      std::make_tuple(best.dt_min, static_cast<double>(best.dt_phase),
                      static_cast<double>(best.dt_item), static_cast<double>(best.dt_element))) {
    best.dt_min = v[0];
    best.dt_phase = as_index(v[1]);
    best.dt_item = as_index(v[2]);
    best.dt_element = as_index(v[3]);
  }
  if (v[4] != 0.0 &&
      (!best.failed || place(v, 6) < std::make_tuple(static_cast<double>(best.failed_phase),
                                                     static_cast<double>(best.failed_item),
                                                     static_cast<double>(best.failed_element)))) {
    best.failed = true;
    best.unsupported_material = v[5] != 0.0;
    best.failed_phase = as_index(v[6]);
    best.failed_item = as_index(v[7]);
    best.failed_element = as_index(v[8]);
  }
}

}  // namespace

RankElementReport RankExchange::gather_elements(
    const std::vector<std::vector<RangeBooks>>& piece_books,
    std::vector<element::ShellBlockState>& shells, bool thickness, const RankElementReport& mine) {
  constexpr std::size_t k = 6;  // the books' sums
  const auto me = static_cast<std::size_t>(comm_->rank());
  const auto ranks = static_cast<std::size_t>(comm_->size());
  const auto put = [&](const RangeBooks& b) {
    send_.insert(send_.end(), {b.internal, b.hourglass, b.start_power, b.end_power,
                               b.hourglass_start_power, b.hourglass_end_power});
  };
  send_.clear();
  put_report(mine, send_);
  for (const WholeItem& x : my_whole_)
    put(piece_books[x.phase][x.piece]);
  for (std::size_t j = split_start_[me]; j < split_start_[me + 1]; ++j)
    put(books(split_[j].shell, split_[j].block)[split_[j].element]);
  if (thickness) {
    for (std::size_t j = reported_start_[me]; j < reported_start_[me + 1]; ++j) {
      if (reported_[j].shell)
        send_.push_back(shells[reported_[j].block].thickness[reported_[j].element]);
    }
  }
  std::vector<std::size_t> per_rank(ranks);
  std::size_t total = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    per_rank[r] = kReport + k * (whole_start_[r + 1] - whole_start_[r]) +
                  k * (split_start_[r + 1] - split_start_[r]) +
                  (thickness ? reported_shells_[r] : 0);
    total += per_rank[r];
  }
  receive_.resize(total);
  comm_->all_gather(send_, receive_, per_rank);
  const auto take = [&](std::size_t at) {
    const double* v = &receive_[at];
    return RangeBooks{v[0], v[1], v[2], v[3], v[4], v[5]};
  };
  RankElementReport chosen;
  std::size_t at = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    choose(&receive_[at], chosen);
    at += kReport;
    for (std::size_t j = whole_start_[r]; j < whole_start_[r + 1]; ++j, at += k)
      item_books_[whole_[j].first][whole_[j].second] = take(at);
    for (std::size_t j = split_start_[r]; j < split_start_[r + 1]; ++j, at += k)
      books(split_[j].shell, split_[j].block)[split_[j].element] = take(at);
    if (thickness) {
      for (std::size_t j = reported_start_[r]; j < reported_start_[r + 1]; ++j) {
        if (reported_[j].shell)
          shells[reported_[j].block].thickness[reported_[j].element] = receive_[at++];
      }
    }
  }
  // The items across domains: their elements' books in the item's order, as a kernel sums them.
  for (std::size_t p = 0; p < item_rank_.size(); ++p) {
    for (std::size_t w = 0; w < item_rank_[p].size(); ++w) {
      if (item_rank_[p][w] >= 0)
        continue;
      const WorkItem& it = phases_[p][w];
      const element::ElementBooks* b = books(it.shell, it.block);
      RangeBooks sum;
      for (std::size_t e = it.begin; e < it.end; ++e) {
        sum.internal += b[e].internal;
        sum.hourglass += b[e].hourglass;
        sum.start_power += b[e].start_power;
        sum.end_power += b[e].end_power;
        sum.hourglass_start_power += b[e].hourglass_start_power;
        sum.hourglass_end_power += b[e].hourglass_end_power;
      }
      item_books_[p][w] = sum;
    }
  }
  return chosen;
}

void RankExchange::gather_element_state(std::vector<element::ShellBlockState>& shells,
                                        std::vector<element::SolidBlockState>& solids) {
  if (comm_->size() < 2)
    return;
  // Each block's arrays and their values per element, the same on every rank.
  std::vector<std::vector<std::pair<std::vector<double>*, std::size_t>>> shell_arrays(
      shells.size()),
      solid_arrays(solids.size());
  const auto with_strides = [](auto& st, std::size_t elements) {
    std::vector<std::pair<std::vector<double>*, std::size_t>> out;
    for (std::vector<double>* v : element_arrays(st)) {
      PLYFORM_INVARIANT(elements > 0 && v->size() % elements == 0,
                        "an element array holds a whole number of values per element");
      out.emplace_back(v, v->size() / elements);
    }
    return out;
  };
  for (std::size_t b = 0; b < shells.size(); ++b)
    if (!shell_books_[b].empty())
      shell_arrays[b] = with_strides(shells[b], shell_books_[b].size());
  for (std::size_t b = 0; b < solids.size(); ++b)
    if (!solid_books_[b].empty())
      solid_arrays[b] = with_strides(solids[b], solid_books_[b].size());
  const auto arrays_of = [&](const ElementRef& x) -> const auto& {
    return x.shell ? shell_arrays[x.block] : solid_arrays[x.block];
  };
  const auto me = static_cast<std::size_t>(comm_->rank());
  const auto ranks = static_cast<std::size_t>(comm_->size());
  std::vector<std::size_t> per_rank(ranks, 0);
  for (std::size_t r = 0; r < ranks; ++r)
    for (std::size_t j = reported_start_[r]; j < reported_start_[r + 1]; ++j)
      for (const auto& [v, stride] : arrays_of(reported_[j]))
        per_rank[r] += stride;
  send_.clear();
  for (std::size_t j = reported_start_[me]; j < reported_start_[me + 1]; ++j) {
    const ElementRef& x = reported_[j];
    for (const auto& [v, stride] : arrays_of(x)) {
      const auto at = v->begin() + static_cast<std::ptrdiff_t>(stride * x.element);
      send_.insert(send_.end(), at, at + static_cast<std::ptrdiff_t>(stride));
    }
  }
  std::size_t total = 0;
  for (const std::size_t c : per_rank)
    total += c;
  receive_.resize(total);
  comm_->all_gather(send_, receive_, per_rank);
  std::size_t at = 0;
  for (const ElementRef& x : reported_) {
    for (const auto& [v, stride] : arrays_of(x)) {
      std::copy_n(receive_.begin() + static_cast<std::ptrdiff_t>(at), stride,
                  v->begin() + static_cast<std::ptrdiff_t>(stride * x.element));
      at += stride;
    }
  }
}

}  // namespace plyform::engine

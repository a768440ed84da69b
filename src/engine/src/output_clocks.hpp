#pragma once
// When each output of a run is due: one clock per output file (or series), kept in the
// checkpoint. write_outputs asks each whether it is due, writes, then moves it past t.

#include <array>
#include <cstddef>
#include <string_view>

#include "plyform/core/state_archive.hpp"

namespace plyform::engine {

/// The outputs written on a clock of their own, in the order write_outputs writes them.
enum class Output : unsigned {
  state,    // the VTU states (*DATABASE_BINARY_D3PLOT)
  glstat,   // glstat.csv, with rbdout.csv
  nodout,   // nodout.csv
  bndout,   // bndout.csv
  heat,     // heat.csv (on tprint's interval, else glstat's)
  tprint,   // tprint.csv
  rcforc,   // rcforc.csv
  spcforc,  // spcforc.csv
  rwforc,   // rwforc.csv
  sleout,   // sleout.csv and interface_energy.csv
  matsum,   // matsum.csv
  elout,    // elout.csv
  count
};

class OutputClocks {
 public:
  static constexpr std::size_t kCount = static_cast<std::size_t>(Output::count);

  /// Whether `o` is due at t: its time has come (within `eps`), or this is the end of the run
  /// (`last`) and it has not been written at t yet (no file gets its final row twice).
  [[nodiscard]] bool due(Output o, double t, double eps, bool last) const {
    return t + eps >= next_[index(o)] || (last && !written_now(o, t));
  }
  /// `o` was written at t; its clock moves to its first multiple of `interval` past t (or,
  /// with no interval, to `otherwise`: the end time for the states, never again for the rest).
  void wrote(Output o, double t, double eps, double interval, double otherwise) {
    if (t != written_at_) {
      written_at_ = t;
      written_ = 0;
    }
    written_ |= 1u << static_cast<unsigned>(o);
    double& next = next_[index(o)];
    if (!(interval > 0.0)) {
      next = otherwise;
      return;
    }
    while (next <= t + eps)
      next += interval;
  }
  /// Whether `o` was written at exactly t.
  [[nodiscard]] bool written_now(Output o, double t) const {
    return t == written_at_ && (written_ & (1u << static_cast<unsigned>(o))) != 0;
  }

  /// The clocks and what was written at the last output time: a restart writes what the
  /// uninterrupted run would have.
  void visit_state(core::StateArchive& a) {
    static constexpr std::array<std::string_view, kCount> names{
        "state",  "glstat",  "nodout", "bndout", "heat",   "tprint",
        "rcforc", "spcforc", "rwforc", "sleout", "matsum", "elout"};
    for (std::size_t k = 0; k < kCount; ++k)
      a.value(names[k], next_[k]);
    a.value("written_at", written_at_);
    a.value("written", written_);
  }

 private:
  static constexpr std::size_t index(Output o) { return static_cast<std::size_t>(o); }
  std::array<double, kCount> next_{};  // the time each output is due next (all due at t = 0)
  double written_at_ = -1.0;           // the time of the outputs `written_` lists
  unsigned written_ = 0;               // a bit per Output written at written_at_
};

}  // namespace plyform::engine

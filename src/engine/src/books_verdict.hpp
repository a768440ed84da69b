#pragma once
// The run's verdict on its own energy books (docs/energy.md): the energy ratio against the most
// energy that entered the model, the warnings (hourglass energy, a contact that gives energy,
// the ratio out of balance), the reasons not to trust the results with the time each first
// held, and the stop band. The engine measures the books; this judges them, alone, so that
// the rules can be driven by a test with a series of books.

#include <span>

#include "plyform/contact/contact_set.hpp"
#include "plyform/core/state_archive.hpp"
#include "plyform/engine/solver.hpp"

namespace plyform::engine {

/// The block with the most hourglass energy, which the hourglass warning names.
struct HourglassLeader {
  core::GlobalId part = 0;
  double hourglass = 0.0;
  double internal = 0.0;
};

class BooksVerdict {
 public:
  /// Beyond 1 +- distrust_band the results are not to be trusted. No healthy run comes near
  /// it: the shipped examples stay within 1 +- 0.01, a velocity jump at t = 0 within 1 +- 0.001.
  static constexpr double distrust_band = 0.1;

  /// At t = 0: the energy the model starts with (|kinetic| + the initial stresses' energy),
  /// and whether heat works in it (thermal expansion may drive the internal energy negative:
  /// the hourglass book is then judged against its largest magnitude).
  void start(double start_energy, bool heat_works);

  /// e.ratio from e.total against `entered` (the initial energy plus the external work): 1 +
  /// the difference over the most energy that entered so far, which is LS-DYNA's total /
  /// (initial + external work) while that energy grows and stays meaningful once the work has
  /// been taken back out (a block compressed and released). Updates the run's peaks.
  void measure(Energies& e, double entered);

  /// A judgement of the books e (at an output or a check between outputs; `last`: the end of
  /// the run): warnings and reasons for distrust go into res.
  void judge(const Energies& e, double start_energy, const HourglassLeader& leader,
             std::span<const contact::InterfaceReport> interfaces, bool last, RunResult& res);

  /// At the end of a run that completed: the hourglass and contact distrust judged again
  /// against the whole run's largest internal energy and most energy that entered (an early
  /// share the run outgrew does not count against its results; the warning stays in the log).
  void settle(RunResult& res) const;

  /// The ratio against the stop band (ENDENG, else 1 +- 0.5): the number of checks in a row it
  /// has been outside (the run stops at two).
  int stop_check(double ratio, double band);

  void visit_state(core::StateArchive& a);

 private:
  bool heat_works_ = false;
  bool warned_hourglass_ = false, warned_contact_ = false;
  double energy_scale_ = 0.0;        // the most energy that entered (the ratio's scale)
  double internal_peak_ = 0.0;       // the largest internal energy (the hourglass yardstick)
  double internal_magnitude_ = 0.0;  // the largest |internal energy| (heat at work)
  double hourglass_peak_ = 0.0;      // the largest hourglass energy of the run
  double contact_low_ = 0.0;         // the most negative energy of any interface at a judgement
  bool distrusted_ratio_ = false, distrusted_contact_ = false;
  // Consecutive judgements with the ratio outside the distrust band (and the time of the first
  // of them) and outside the stop band: one alone is a velocity that jumps at that very
  // instant (a prescribed motion's kink), read between its two half steps.
  int ratio_out_ = 0, stop_out_ = 0;
  double ratio_out_since_ = 0.0;
};

}  // namespace plyform::engine

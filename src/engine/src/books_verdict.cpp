#include "books_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include <fmt/format.h>

namespace plyform::engine {

namespace {

std::string time_text(double t) {
  std::ostringstream os;
  os.precision(6);
  os << t;
  return os.str();
}

void distrust(RunResult& res, std::string reason, double when) {
  res.distrust.push_back({std::move(reason), when});
}

}  // namespace

void BooksVerdict::start(double start_energy, bool heat_works) {
  energy_scale_ = start_energy;
  heat_works_ = heat_works;
}

void BooksVerdict::measure(Energies& e, double entered) {
  energy_scale_ = std::max(energy_scale_, std::abs(entered));
  e.ratio = energy_scale_ > 0.0 ? 1.0 + (e.total - entered) / energy_scale_ : 1.0;
  internal_peak_ = std::max(internal_peak_, e.internal);
  internal_magnitude_ = std::max(internal_magnitude_, std::abs(e.internal));
  hourglass_peak_ = std::max(hourglass_peak_, e.hourglass);
}

// Each book is judged once, at the first judgement where it breaks: hourglass energy above
// 10 % of the internal energy, named by the part with the most; an interface's contact energy
// below zero (the contact gave energy to the model) beyond 1e-3 of the energy that entered
// (a warning; from 1e-2 the results are not to be trusted); the ratio outside the distrust
// band at two judgements in a row.
void BooksVerdict::judge(const Energies& e, double start_energy, const HourglassLeader& leader,
                         std::span<const contact::InterfaceReport> interfaces, bool last,
                         RunResult& res) {
  // Energies at round-off (a model at rest, the first outputs) say nothing: the hourglass
  // book is judged once it is a millionth of the energy that entered the model.
  const double entered = std::max(energy_scale_, start_energy + std::abs(e.external_work));
  // Against the largest internal energy of the run: the present one passes through zero when
  // a released part gives its energy back (the demo's block warned at 11 % of round-off), and
  // is negative early in a thermal run (thermal contraction's stress work).
  // With heat at work the internal energy may be negative: its largest magnitude then.
  const double internal_scale = heat_works_ ? internal_magnitude_ : internal_peak_;
  const double yardstick = internal_scale > 0.0 ? internal_scale : entered;
  if (!warned_hourglass_ && e.hourglass > 0.1 * yardstick && e.hourglass > 1e-6 * entered) {
    warned_hourglass_ = true;
    std::ostringstream os;
    os.precision(4);
    os << "hourglass energy " << e.hourglass << " is " << 100.0 * e.hourglass / yardstick
       << " % of the " << (internal_scale > 0.0 ? "largest internal energy " : "energy entered ")
       << yardstick << " at t = " << e.time << ": most in part " << leader.part << " (hourglass "
       << leader.hourglass << ", internal " << leader.internal
       << "); its results are not to be trusted (a stiffness hourglass control, *HOURGLASS "
          "IHQ 4 or 5, or a finer mesh)";
    res.warnings.push_back(os.str());
    distrust(res,
             fmt::format("hourglass energy {:.4g} % of the largest internal energy (above 10 %)",
                         100.0 * e.hourglass / yardstick),
             e.time);
  }
  for (const contact::InterfaceReport& r : interfaces)
    contact_low_ = std::min(contact_low_, r.work);
  if (!warned_contact_ || !distrusted_contact_) {
    for (const contact::InterfaceReport& r : interfaces) {
      if (!warned_contact_ && r.work < -1e-3 * entered) {
        warned_contact_ = true;
        std::ostringstream os;
        os.precision(4);
        os << "contact " << r.id << " energy " << r.work << " is negative at t = " << e.time
           << ": the interface gave energy to the model (" << -100.0 * r.work / entered
           << " % of the energy that entered it)";
        res.warnings.push_back(os.str());
      }
      // Warned from 0.1 % of the energy that entered; the books count as broken from 1 %.
      if (!distrusted_contact_ && r.work < -1e-2 * entered) {
        distrusted_contact_ = true;
        distrust(res,
                 fmt::format("contact {} energy {:.4g} negative ({:.4g} % of the energy that "
                             "entered the model)",
                             r.id, r.work, -100.0 * r.work / entered),
                 e.time);
      }
    }
  }
  if (std::abs(e.ratio - 1.0) > distrust_band) {
    if (ratio_out_++ == 0)
      ratio_out_since_ = e.time;
  } else {
    ratio_out_ = 0;
  }
  // Out of the band at two judgements in a row, or at the last one (the end of the run has no
  // next judgement to confirm it).
  if (!distrusted_ratio_ && (ratio_out_ >= 2 || (last && ratio_out_ >= 1))) {
    distrusted_ratio_ = true;
    const std::string what = fmt::format(
        "energy ratio {:.6g}: the books are {:.3g} % of the energy that entered "
        "out of balance (more than {:.3g} %)",
        e.ratio, 100.0 * std::abs(e.ratio - 1.0), 100.0 * distrust_band);
    res.warnings.push_back(what + " from t = " + time_text(ratio_out_since_));
    distrust(res, what, ratio_out_since_);
  }
}

// The hourglass book judged against the largest internal energy of the whole run, of which the
// judgements during the run knew only the part so far: early in a forming run the internal
// energy is a sliver of what it becomes (a plain three-layer draw: 1.9 mJ of hourglass at the
// holder's first touch, 24 % of the 8 mJ internal energy then, 0.001 % of the run's 208 J).
// The contact book likewise against the most energy that entered during the whole run: an
// interface that gave a trace of energy before anything entered (tracked initial penetrations
// in the first cycles: 0.05 J when the model was at rest) read as "infinitely" broken; 1e-5
// of the run's 13.8 kJ is not.
void BooksVerdict::settle(RunResult& res) const {
  const double internal_scale = heat_works_ ? internal_magnitude_ : internal_peak_;
  const auto is_hourglass = [](const Distrust& d) {
    return d.reason.rfind("hourglass energy", 0) == 0;
  };
  if (internal_scale > 0.0 && hourglass_peak_ <= 0.1 * internal_scale &&
      std::any_of(res.distrust.begin(), res.distrust.end(), is_hourglass)) {
    std::erase_if(res.distrust, is_hourglass);
    res.warnings.push_back(fmt::format(
        "the hourglass energy warned about above peaked at {:.4g}, {:.4g} % of the run's "
        "largest internal energy {:.4g}: within 10 %, so it does not count against the results",
        hourglass_peak_, 100.0 * hourglass_peak_ / internal_scale, internal_scale));
  }
  const auto is_contact = [](const Distrust& d) { return d.reason.rfind("contact ", 0) == 0; };
  if (energy_scale_ > 0.0 && contact_low_ >= -1e-2 * energy_scale_ &&
      std::any_of(res.distrust.begin(), res.distrust.end(), is_contact)) {
    std::erase_if(res.distrust, is_contact);
    res.warnings.push_back(fmt::format(
        "the negative contact energy warned about above reached {:.4g}, {:.3g} % of the most "
        "energy that entered the model in the run ({:.4g}): within 1 %, so it does not count "
        "against the results",
        contact_low_, -100.0 * contact_low_ / energy_scale_, energy_scale_));
  }
}

int BooksVerdict::stop_check(double ratio, double band) {
  stop_out_ = std::abs(ratio - 1.0) <= band ? 0 : stop_out_ + 1;
  return stop_out_;
}

void BooksVerdict::visit_state(core::StateArchive& a) {
  a.value("warned_hourglass", warned_hourglass_);
  a.value("warned_contact", warned_contact_);
  a.value("energy_scale", energy_scale_);
  a.value("internal_peak", internal_peak_);
  a.value("internal_magnitude", internal_magnitude_);
  a.value("hourglass_peak", hourglass_peak_);
  a.value("contact_low", contact_low_);
  a.value("distrusted_ratio", distrusted_ratio_);
  a.value("distrusted_contact", distrusted_contact_);
  a.value("ratio_out", ratio_out_);
  a.value("stop_out", stop_out_);
  a.value("ratio_out_since", ratio_out_since_);
}

}  // namespace plyform::engine

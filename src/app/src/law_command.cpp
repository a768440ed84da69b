// `plyform law`: one contact point of the deck's *USER_INTERFACE_FRICTION driven along a
// prescribed path of gap, slip and temperature.

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <fstream>
#include <ostream>

#include "plyform/app/commands.hpp"
#include "plyform/app/path_csv.hpp"
#include "plyform/keyword/read_deck.hpp"
#include "plyform/law/law.hpp"
#include "plyform/law/point_driver.hpp"
#include "plyform/setup/cohesive_law.hpp"
#include "plyform/setup/validate.hpp"

namespace plyform::app {
namespace {

void print_errors(const std::vector<keyword::Diagnostic>& errors, std::ostream& err) {
  for (const auto& d : errors)
    fmt::print(err, "error: {}\n", d.to_string());
}

void write_samples(const std::vector<law::PathSample>& samples, std::ostream& os) {
  os << "time,gap,slip_x,slip_y,temperature,pressure,tau_x,tau_y,beta,state,dissipated\n";
  for (const law::PathSample& s : samples) {
    const law::NodeHistory& h = s.history;
    const double dissipated = h.e_damage + h.e_viscous + h.e_friction + h.e_damping;
    fmt::print(
        os, "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{},{:.10g}\n",
        s.at.time, s.at.gap, s.at.slip[0], s.at.slip[1], s.at.temperature, s.response.pressure,
        s.response.tau[0], s.response.tau[1], h.beta, law::to_string(h.state), dissipated);
  }
}

}  // namespace

int run_law(const LawOptions& options, std::ostream& out, std::ostream& err) {
  const keyword::ReadResult read = keyword::read_deck(options.deck);
  if (!read.ok()) {
    print_errors(read.errors, err);
    return 1;
  }
  if (const auto errors = setup::validate(read.model); !errors.empty()) {
    print_errors(errors, err);
    return 1;
  }
  const auto& uifs = read.model.user_interface_frictions;
  const model::UserInterfaceFrictionDesc* uif = nullptr;
  if (options.interface_id) {
    for (const auto& u : uifs) {
      if (u.contact_id == *options.interface_id)
        uif = &u;
    }
    if (uif == nullptr) {
      fmt::print(err, "error: {}: no *USER_INTERFACE_FRICTION with NOSID {}\n",
                 options.deck.string(), *options.interface_id);
      return 1;
    }
  } else if (uifs.size() == 1) {
    uif = &uifs.front();
  } else if (uifs.empty()) {
    fmt::print(err, "error: {}: the deck has no *USER_INTERFACE_FRICTION to drive\n",
               options.deck.string());
    return 1;
  } else {
    fmt::print(err,
               "error: {}: the deck has {} *USER_INTERFACE_FRICTION cards; choose one with "
               "--interface NOSID\n",
               options.deck.string(), uifs.size());
    return 1;
  }

  const setup::CohesiveLawBuild built = setup::build_cohesive_law(read.model, *uif);
  if (!built.parameters) {
    print_errors(built.errors, err);
    return 1;
  }
  const law::Law law(*built.parameters);
  law::DriverSettings settings;
  settings.k_normal = options.penalty.value_or(built.parameters->cn);
  if (!(settings.k_normal > 0.0)) {
    fmt::print(err, "error: --penalty must be greater than 0, got {}\n", settings.k_normal);
    return 1;
  }

  std::vector<law::PathSample> samples;
  try {
    samples = law::drive(law, read_path_csv(options.path_csv), settings);
  } catch (const std::exception& e) {
    fmt::print(err, "error: {}\n", e.what());
    return 1;
  }

  if (options.output) {
    std::ofstream file(*options.output);
    if (!file) {
      fmt::print(err, "error: cannot write {}\n", options.output->string());
      return 1;
    }
    write_samples(samples, file);
    if (!file.flush()) {
      fmt::print(err, "error: writing {} failed\n", options.output->string());
      return 1;
    }
  } else {
    write_samples(samples, out);
  }
  return 0;
}

}  // namespace plyform::app

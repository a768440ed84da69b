// `plyform check`: read and validate a deck, report every error with its location, and
// summarise what was read.

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <cmath>
#include <ostream>

#include "plyform/app/commands.hpp"
#include "plyform/keyword/read_deck.hpp"
#include "plyform/law/user_constants.hpp"
#include "plyform/setup/cohesive_law.hpp"
#include "plyform/setup/validate.hpp"

namespace plyform::app {
namespace {

// One line per constant: name, value (or where it came from), unit, meaning.
void print_law(const model::ModelDesc& model, const model::UserInterfaceFrictionDesc& uif,
               std::ostream& out) {
  fmt::print(out, "\n*USER_INTERFACE_FRICTION for contact {} ({}:{}), NOC {}, NOCI {}\n",
             uif.contact_id, uif.where.file, uif.where.line, uif.noc, uif.noci);
  const auto built = setup::build_cohesive_law(model, uif);
  const auto table = law::user_constant_table();
  for (const law::ConstantSpec& s : table) {
    const auto i = static_cast<std::size_t>(s.index - 1);
    const bool given = i < uif.constants.size() && uif.constants[i].has_value();
    std::string value;
    if (given) {
      const double v = *uif.constants[i];
      value = s.temperature_dependent && v < 0.0 ? fmt::format("load curve {}", -v)
                                                 : fmt::format("{:g}", v);
    } else if (s.required) {
      value = "(missing)";
    } else if (s.default_from > 0) {
      value =
          fmt::format("= {} (default)", table[static_cast<std::size_t>(s.default_from - 1)].name);
    } else {
      value = fmt::format("{:g} (default)", s.default_value);
    }
    fmt::print(out, "  UC{:<3}{:<10}{:>22}  [{}]  {}\n", s.index, s.name, value, s.unit, s.meaning);
  }
  if (built.parameters) {
    const law::Parameters& p = *built.parameters;
    const double smax = law::evaluate(p.sigma_max, p, p.t_lo);
    fmt::print(out,
               "  derived at T_LO: omega = sigma_max^2 / C_N = {:g} [energy/area], "
               "g_c = sigma_max / C_N = {:g} [length]\n",
               law::adhesion_energy(smax, p.cn), smax / p.cn);
  }
}

}  // namespace

int run_check(const std::filesystem::path& deck, std::ostream& out, std::ostream& err) {
  const keyword::ReadResult read = keyword::read_deck(deck);
  for (const auto& w : read.warnings)
    fmt::print(err, "warning: {}\n", w.to_string());
  std::vector<keyword::Diagnostic> errors = read.errors;
  if (read.ok())
    errors = setup::validate(read.model);
  if (!errors.empty()) {
    for (const auto& d : errors)
      fmt::print(err, "error: {}\n", d.to_string());
    fmt::print(err, "{}: {} error{}\n", deck.string(), errors.size(),
               errors.size() == 1 ? "" : "s");
    return 1;
  }

  const model::ModelDesc& m = read.model;
  fmt::print(out, "{}: valid\n", deck.string());
  if (!m.title.empty())
    fmt::print(out, "title: {}\n", m.title);
  fmt::print(out, "files read: {}\n", m.files_read.size());
  fmt::print(out, "curves: {}\n", m.curves.size());
  for (const auto& c : m.curves) {
    fmt::print(out, "  curve {}{}: {} points\n", c.id, c.title.empty() ? "" : " (" + c.title + ")",
               c.abscissa.size());
  }
  fmt::print(out, "cohesive interfaces: {}\n", m.user_interface_frictions.size());
  for (const auto& u : m.user_interface_frictions)
    print_law(m, u, out);
  return 0;
}

}  // namespace plyform::app

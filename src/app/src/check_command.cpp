// `plyform check`: read and validate a deck, report every error with its location, and
// summarise what was read.

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <array>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <ostream>
#include <string>
#include <variant>

#include "decomposition_report.hpp"
#include "plyform/app/commands.hpp"
#include "plyform/domain/decomposition.hpp"
#include "plyform/engine/initial_contact_step.hpp"
#include "plyform/engine/initial_step.hpp"
#include "plyform/keyword/read_deck.hpp"
#include "plyform/law/user_constants.hpp"
#include "plyform/material/law_registry.hpp"
#include "plyform/setup/build.hpp"
#include "plyform/setup/cohesive_law.hpp"
#include "plyform/setup/contact_penalty.hpp"
#include "plyform/setup/fibre_alignment.hpp"
#include "plyform/setup/hinge_resolution.hpp"
#include "plyform/setup/interface_warnings.hpp"
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

std::string side_name(model::ContactSideType type, int id) {
  switch (type) {
    case model::ContactSideType::segment_set:
      return fmt::format("segment set {}", id);
    case model::ContactSideType::part_set:
      return fmt::format("part set {}", id);
    case model::ContactSideType::part:
      return fmt::format("part {}", id);
    case model::ContactSideType::node_set:
      return fmt::format("node set {}", id);
    case model::ContactSideType::all_parts:
      return "every part";
  }
  return fmt::format("{}", id);
}

// One line per contact: id, keyword, slave and master sides, and the cohesive law of a
// *USER_INTERFACE_FRICTION that names it.
void print_contacts(const model::ModelDesc& m, std::ostream& out) {
  fmt::print(out, "contacts: {}\n", m.contacts.size());
  for (const auto& c : m.contacts) {
    const bool cohesive =
        c.id != 0 &&
        std::any_of(m.user_interface_frictions.begin(), m.user_interface_frictions.end(),
                    [&](const auto& u) { return u.contact_id == c.id; });
    const std::string id = c.id != 0 ? std::to_string(c.id) : "(no CID)";
    const std::string heading = c.heading.empty() ? "" : " '" + c.heading + "'";
    if (c.kind == model::ContactKind::automatic_single_surface) {
      fmt::print(out, "  contact {}{} {}: single surface {}\n", id, heading, c.keyword,
                 c.ssid == 0 ? std::string("every part") : side_name(c.sstyp, c.ssid));
      continue;
    }
    fmt::print(out, "  contact {}{} {}: slave {}, master {}{}\n", id, heading, c.keyword,
               side_name(c.sstyp, c.ssid), side_name(c.mstyp, c.msid),
               cohesive ? ", cohesive law (UIF)" : "");
  }
}

// The law's keyword, from the registry (material/law_registry.hpp).
std::string_view material_name(const core::Material& m) {
  return material::law_info(m).keyword;
}

// ", thermal expansion alpha ..." of a block that expands with temperature, else empty.
std::string expansion_text(const core::LoadCurve& alpha) {
  if (alpha.x.empty())
    return {};
  const auto [lo, hi] = std::minmax_element(alpha.y.begin(), alpha.y.end());
  if (*lo == *hi)
    return fmt::format(", thermal expansion alpha {:g} 1/temperature", *lo);
  return fmt::format(", thermal expansion alpha {:g} to {:g} 1/temperature over [{:g}, {:g}]", *lo,
                     *hi, alpha.x.front(), alpha.x.back());
}

// The parameters of a *MAT_REINFORCED_THERMOPLASTIC ply by name and unit, a line each (the
// deck's units: "stress" is the deck's stress unit).
void print_woven_ply(const core::ReinforcedThermoplastic& m, std::ostream& out) {
  constexpr double deg = 180.0 / std::numbers::pi;
  const auto range = [](const core::LoadCurve& c, const char* name) {
    const auto [lo, hi] = std::minmax_element(c.y.begin(), c.y.end());
    return fmt::format("{} {:g} to {:g} over temperatures {:g} to {:g}", name, *lo, *hi,
                       c.x.front(), c.x.back());
  };
  const auto curve_text = [](const core::CurveTable& t, const char* what) {
    if (t.value.size() <= 1)
      return fmt::format("curve of {}", what);
    return fmt::format("table of {} at {} temperatures {:g} to {:g}", what, t.value.size(),
                       t.value.front(), t.value.back());
  };
  const std::string young = m.young_of_t.x.empty() ? fmt::format("EM {:g} (stress)", m.young)
                                                   : range(m.young_of_t, "EM (stress, LCEM)");
  const std::string nu = m.poisson_of_t.x.empty() ? fmt::format("PRM {:g}", m.poisson)
                                                  : range(m.poisson_of_t, "PRM (LCPRM)");
  fmt::print(out, "    matrix: {}, {}, {}\n", young, nu,
             m.yield.curve.empty()
                 ? std::string("elastic")
                 : "J2, isotropic hardening, LCSIGY " +
                       curve_text(m.yield, "yield stress (stress) against plastic strain"));
  static constexpr const char* kAxes[] = {"0 (element edge 1-2)", "", "2 (global vector a)",
                                          "3 (v x normal)"};
  fmt::print(out, "    material axes: AOPT {}{}\n", kAxes[m.aopt],
             m.aopt == 2
                 ? fmt::format(" a = ({:g}, {:g}, {:g})", m.a[0], m.a[1], m.a[2])
                 : fmt::format(", MANGL {:g} degrees (element BETA where given)", m.angle * deg));
  for (int i = 0; i < m.families; ++i) {
    const auto& f = m.fibre[static_cast<std::size_t>(i)];
    fmt::print(out,
               "    fibre family {}: ALPH{} {:g} degrees, {}, tension only; G23_{} {:g}, G31_{} "
               "{:g} (stress, transverse shear)\n",
               i + 1, i + 1, f.alpha * deg,
               f.stress.curve.empty()
                   ? fmt::format("EF{} {:g} (stress)", i + 1, f.modulus)
                   : fmt::format("LCEF{} {}", i + 1,
                                 curve_text(f.stress, "nominal stress against fibre strain")),
               i + 1, f.g23, i + 1, f.g31);
  }
  for (int k = 0; k + 1 < m.families; ++k) {
    const auto& sh = m.shear[static_cast<std::size_t>(k)];
    const std::string pair = k == 0 ? "12" : "23";
    std::string response =
        sh.stress.curve.empty()
            ? fmt::format("linear, G{} {:g} (stress)", pair, sh.modulus)
            : fmt::format("METH{} {} ({}), LCG{} {}", pair, sh.meth,
                          sh.meth == 3
                              ? fmt::format("elasto-plastic, unloading G{} {:g}", pair, sh.modulus)
                              : std::string("elastic"),
                          pair, curve_text(sh.stress, "shear stress against shear angle (rad)"));
    if (sh.lock_angle > 0.0)
      response += fmt::format(
          "; locking at ALOC{} {:g} rad ({:.1f} degrees), then GLOC{} {:g} "
          "(stress)",
          pair, sh.lock_angle, sh.lock_angle * deg, pair, sh.lock_modulus);
    fmt::print(out, "    shear {}-{}: {}\n", k + 1, k + 2, response);
  }
}

// "N (Belytschko-Tsay; T triangles)": the formulations of the shells, with their counts when
// the deck mixes them.
std::string shell_summary(const core::Model& m) {
  std::size_t bt = 0, full = 0, triangles = 0;
  for (const auto& b : m.shell_blocks) {
    (b.formulation == core::ShellFormulation::fully_integrated ? full : bt) += b.size();
    for (std::size_t e = 0; e < b.size(); ++e) {
      if (b.connectivity[4 * e + 2] == b.connectivity[4 * e + 3])
        ++triangles;
    }
  }
  constexpr const char* kBt = "Belytschko-Tsay";
  constexpr const char* kFull = "ELFORM 16 fully integrated";
  const std::string kinds = full == 0 ? std::string(kBt)
                            : bt == 0 ? std::string(kFull)
                                      : fmt::format("{}: {}, {}: {}", kBt, bt, kFull, full);
  return fmt::format("{} ({}; {} triangles)", bt + full, kinds, triangles);
}

// The step the run starts with and the cycles it takes to the end time, mass scaling applied
// as the run applies it (engine::initial_stable_step), and the mass it adds.
void print_stable_step(const core::Model& m, std::ostream& out) {
  const engine::InitialStep step = engine::initial_stable_step(m);
  if (!(step.dt < 1e300))
    return;
  const double tssfac = m.controls.tssfac;
  const double dt = tssfac * step.dt;
  // *CONTROL_TIMESTEP LCTM caps the step by a curve of time: the cycles are the integral of
  // 1 / min(dt, cap(t)) over the run (sampled; the run steps from one cap to the next).
  const core::Index cap_curve = m.controls.max_step_curve;
  double cycles = m.controls.end_time / dt;
  if (cap_curve >= 0) {
    const core::LoadCurve& cap = m.curves[static_cast<std::size_t>(cap_curve)];
    constexpr int kSamples = 10000;
    const double h = m.controls.end_time / kSamples;
    cycles = 0.0;
    for (int k = 0; k < kSamples; ++k)
      cycles += h / std::max(std::min(dt, cap((k + 0.5) * h)), 1e-300);
  }
  fmt::print(out,
             "stable time step estimate: {:.6g} (TSSFAC {:g}, set by element {}{}), about {:.6g} "
             "cycles{}\n",
             dt, tssfac, step.element, step.scaled_elements > 0 ? ", mass scaled" : "", cycles,
             cap_curve >= 0 ? " with the largest step of the curve LCTM" : "");
  if (m.controls.dt2ms != 0.0) {
    const double share = step.physical_mass > 0.0 ? step.added_mass / step.physical_mass : 0.0;
    fmt::print(out,
               "mass scaling (DT2MS {:g}): {} element{} below the step {:.6g} made heavier, "
               "adding {:.6g} ({:.3g} % of the mass {:.6g}); without it the step would be "
               "{:.6g} (element {}), about {:.6g} cycles\n",
               m.controls.dt2ms, step.scaled_elements, step.scaled_elements == 1 ? "" : "s",
               tssfac * std::abs(m.controls.dt2ms), step.added_mass, 100.0 * share,
               step.physical_mass, tssfac * step.dt_unscaled, step.element_unscaled,
               m.controls.end_time / (tssfac * step.dt_unscaled));
  }
}

// Counts, parts and the stable step of a deck with a mesh; false (errors printed) when the
// runtime model cannot be built.
void print_mesh(const model::ModelDesc& desc, const core::Model& m, std::ostream& out) {
  if (desc.units) {
    fmt::print(out,
               "units (as declared, no conversion): length {}, time {}, mass {}, temperature {}\n",
               desc.units->length, desc.units->time, desc.units->mass, desc.units->temp);
  }
  if (desc.accuracy) {
    // What *CONTROL_ACCURACY asks, and how plyform meets it.
    const int inn = desc.accuracy->inn;
    const char* frame =
        inn == 1   ? "off"
        : inn == 3 ? "solids: met, plyform's hexahedra have no element frame"
                   : "shells: plyform's shell frame follows the edge N1-N2 (as INN 1); "
                     "isotropic shells do not depend on its in-plane orientation, laws with "
                     "element axes (AOPT 0) take them from the edge N1-N2 as written";
    fmt::print(out,
               "accuracy (*CONTROL_ACCURACY): OSU {}: met, plyform's stress update is always "
               "objective; INN {}: {}\n",
               desc.accuracy->osu, inn, frame);
  }
  if (desc.parallel) {
    // A negative NCPU asks LS-DYNA for consistency; plyform's results never depend on the
    // thread count, so there is nothing to warn about, only to say.
    const model::ControlParallelDesc& p = *desc.parallel;
    fmt::print(out,
               "threads (*CONTROL_PARALLEL NCPU {}): {} for `plyform run` without --threads{}\n",
               p.ncpu, p.threads(),
               p.ncpu < 0 || p.consistency == 1
                   ? "; the consistency it asks for is always met: plyform's results do not "
                     "depend on the thread count"
                   : "");
  }
  std::size_t one = 0, two = 0;
  for (const auto& b : m.solid_blocks) {
    (b.formulation == core::SolidFormulation::one_point ? one : two) += b.size();
  }
  fmt::print(out, "nodes: {}\n", m.node_count());
  fmt::print(out, "solid elements: {} (ELFORM 1: {}, ELFORM 2: {})\n", one + two, one, two);
  fmt::print(out, "shell elements: {}\n", shell_summary(m));
  fmt::print(out, "parts: {}\n", m.parts.size());
  for (const auto& b : m.solid_blocks) {
    const core::Material& mat = m.materials[static_cast<std::size_t>(b.material)];
    const std::string_view law = material_name(mat);
    const core::Part& part = m.parts[static_cast<std::size_t>(b.part)];
    fmt::print(out, "  part {} '{}': {} elements, ELFORM {}, {}, hourglass IHQ {} QM {:g}{}\n",
               part.id, part.title, b.size(), static_cast<int>(b.formulation), law, b.hourglass.ihq,
               b.hourglass.qm, expansion_text(b.expansion));
  }
  for (const auto& b : m.shell_blocks) {
    const core::Material& mat = m.materials[static_cast<std::size_t>(b.material)];
    const core::Part& part = m.parts[static_cast<std::size_t>(b.part)];
    fmt::print(out, "  part {} '{}': {} shells{}, NIP {}, {}{}\n", part.id, part.title, b.size(),
               b.formulation == core::ShellFormulation::fully_integrated
                   ? " (ELFORM 16, fully integrated: no hourglass control)"
                   : "",
               b.nip, material_name(mat), expansion_text(b.expansion));
    if (const auto* ply = std::get_if<core::ReinforcedThermoplastic>(&mat))
      print_woven_ply(*ply, out);
  }
  fmt::print(out, "constraints: {} fixed nodes/dofs, {} prescribed motions, {} nodal loads\n",
             m.fixed.size(), m.motions.size(), m.loads.size());
  if (!m.pressure_loads.empty()) {
    fmt::print(out,
               "pressure loads: {} on {} segments (each on its current area, against its "
               "normal N1 -> N2 -> N3)\n",
               m.pressure_loads.size(), m.pressure_segments.size());
  }
  // What the build made of each tied contact (the deck's contacts list names them above).
  for (const core::TiedInterface& t : m.tied) {
    fmt::print(out, "tied contact {} {}: {} slave nodes tied{}\n",
               t.id != 0 ? std::to_string(t.id) : std::string("(no CID)"), t.keyword,
               t.slaves.size(), t.rotations ? ", with their rotations" : "");
  }
  for (const core::RigidWall& w : m.rigid_walls) {
    const std::string friction = w.friction == 0.0   ? "frictionless"
                                 : w.friction >= 1.0 ? "no sliding"
                                                     : fmt::format("Coulomb {}", w.friction);
    fmt::print(out,
               "rigid wall {}: {} plane through ({}, {}, {}), normal ({:.4g}, {:.4g}, {:.4g}), {} "
               "slave nodes, {}{}\n",
               w.id,
               w.finite ? fmt::format("a {} x {} rectangle of the", w.length_l, w.length_m)
                        : std::string("the"),
               w.origin[0], w.origin[1], w.origin[2], w.normal[0], w.normal[1], w.normal[2],
               w.nodes.size(), friction,
               w.mass > 0.0
                   ? fmt::format(", moving: mass {}, {} along the normal", w.mass, w.velocity0)
                   : std::string());
  }
  // What the build made of each contact: the sides as slave nodes and master segments, with
  // their offsets and SOFT = 0 penalty (docs/contact.md).
  for (const core::ContactInterface& c : m.contacts) {
    if (c.tiebreak.enabled()) {
      const core::Tiebreak& tb = c.tiebreak;
      const std::string ties = tb.ties_on_contact()
                                   ? "nodes in contact at t = 0 and every node that touches later"
                                   : "nodes in contact at t = 0";
      const std::string holds =
          tb.holds_tangential() ? "held normal and tangential"
                                : (tb.sfls_is_friction_limit
                                       ? fmt::format("held normal, sliding at SFLS {:g}", tb.sfls)
                                       : std::string("held normal, sliding with FS"));
      const std::string fails =
          !tb.can_fail() ? "never fail"
          : tb.holds_tangential()
              ? fmt::format(
                    "fail at (sigma_n / {:g})^2 + (tau / {:g})^2 = 1, then penalty "
                    "contact with friction",
                    tb.nfls, tb.sfls)
              : fmt::format("fail at sigma_n = {:g}, then penalty contact with friction", tb.nfls);
      fmt::print(out, "  contact {}: tiebreak OPTION {}: {} tie ({}), ties {}\n", c.id, tb.option,
                 ties, holds, fails);
    }
    for (std::size_t p = 0; p < c.passes.size(); ++p) {
      const core::ContactPass& cp = c.passes[p];
      const auto range = [](const std::vector<double>& v) {
        if (v.empty())
          return std::string("-");
        const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
        const std::string a = fmt::format("{:.4g}", *lo), b = fmt::format("{:.4g}", *hi);
        return a == b ? a : a + "-" + b;
      };
      // The master's per area too, and the one the pass uses by PENOPT: a soft layer (a
      // polymer core) makes a soft min(slave, master), under which forming pressures sink
      // layers into each other.
      const std::vector<double> k_area = setup::slave_penalty_per_area(cp);
      const std::vector<double> km_area = setup::master_penalty_per_area(m, cp);
      std::string used = c.penopt == 3   ? "slave"
                         : c.penopt == 2 ? "master"
                         : c.penopt == 0 ? "a layer interface's: the stiffer side, at most "
                                           "m* / (4 dt0^2)"
                                         : "the smaller";
      if (cp.guard)
        used +=
            "; the guard: the master's nodes against the slave's segments, pressure only, "
            "beyond a tenth of the offsets";
      fmt::print(out,
                 "  contact {} pass {}: {} slave nodes against {} segments; offsets slave {}, "
                 "master {}{}; penalty per area slave {}, master {}, PENOPT {}: {} (SOFT {})\n",
                 c.id, p + 1, cp.slave_count(), cp.segment_count(), range(cp.slave_offset),
                 range(cp.segment_offset),
                 cp.offsets_follow_thickness ? " (following the thickness)" : "", range(k_area),
                 range(km_area), c.penopt, used, c.penalty == core::PenaltyKind::mass ? 1 : 0);
    }
  }
  if (m.thermal.enabled) {
    const core::ThermalControls& t = m.thermal;
    std::size_t conducting = 0;
    for (const core::Part& p : m.parts)
      conducting += p.thermal_material >= 0 ? 1 : 0;
    fmt::print(out,
               "heat transfer: {} ({}), {} part{} conducting, {} heat boundar{}; {} step {:g}{}, "
               "theta {:g} ({}), {} solver, speed-up factor {}\n",
               t.thermal_only ? "thermal only (SOLN 1)" : "coupled with the mechanics (SOLN 2)",
               t.steady ? "steady state" : "transient", conducting, conducting == 1 ? "" : "s",
               m.heat_boundaries.size(), m.heat_boundaries.size() == 1 ? "y" : "ies",
               t.variable_step ? "variable" : "fixed", t.dt_initial,
               t.variable_step ? fmt::format(" (DTEMP {:g})", t.dtemp) : std::string(), t.theta,
               t.theta == 0.5   ? "Crank-Nicolson"
               : t.theta == 1.0 ? "backward Euler"
                                : "implicit",
               t.solver == 12 ? "diagonally scaled conjugate-gradient" : "direct LDL^T",
               t.tsf_curve >= 0 ? std::string("from a curve") : fmt::format("{:g}", t.tsf));
    if (t.thick_shells) {
      fmt::print(out,
                 "  thick thermal shells (THSHEL 1): bottom, middle and top temperatures "
                 "through every conducting shell\n");
    }
    if (!t.thermal_only && t.fwork > 0.0) {
      fmt::print(out,
                 "  plastic work heats the parts: FWORK {:g} of the plastic dissipation, times "
                 "EQHEAT {:g}\n",
                 t.fwork, t.eqheat);
    }
  }
  fmt::print(out, "termination time: {:g}\n", m.controls.end_time);
  if (m.output.d3dump_cycles > 0) {
    fmt::print(out,
               "checkpoints: OUTDIR/d3dump every {} cycles and at the end (restart: plyform "
               "run DECK -o OUTDIR --restart)\n",
               m.output.d3dump_cycles);
  }
  if (m.output.elout_dt > 0.0) {
    // What elout.csv will hold: a row per shell thickness point, one per solid.
    std::size_t shell_rows = 0;
    for (const core::BlockElement& h : m.output.history_shells)
      shell_rows += static_cast<std::size_t>(m.shell_blocks[static_cast<std::size_t>(h.block)].nip);
    const std::size_t shell_count = m.output.history_shells.size();
    const std::size_t solid_count = m.output.history_solids.size();
    fmt::print(out,
               "elout.csv every {:g}: {} shell element{} ({} thickness point{}), {} solid "
               "element{}; {} row{} per output time\n",
               m.output.elout_dt, shell_count, shell_count == 1 ? "" : "s", shell_rows,
               shell_rows == 1 ? "" : "s", solid_count, solid_count == 1 ? "" : "s",
               shell_rows + solid_count, shell_rows + solid_count == 1 ? "" : "s");
  }
  print_stable_step(m, out);
}

// What is known to break the interfaces between layers (setup/interface_warnings.hpp), as
// warnings before the run: they do not make the deck invalid.
void print_interface_warnings(const core::Model& m, std::ostream& err) {
  std::vector<setup::InterfaceWarning> all = setup::viscous_hourglass_warnings(m);
  for (auto& w : setup::penalty_pressure_warnings(m))
    all.push_back(std::move(w));
  const engine::InitialStep step = engine::initial_stable_step(m);
  const double tssfac = m.controls.tssfac > 0.0 ? m.controls.tssfac : 0.9;
  if (step.dt < 1e300 && !m.contacts.empty()) {
    for (auto& w :
         setup::contact_step_warnings(m, tssfac * step.dt, engine::initial_contact_steps(m)))
      all.push_back(std::move(w));
  }
  for (const setup::InterfaceWarning& w : all)
    fmt::print(err, "warning: {}\n", w.message);
}

}  // namespace

int run_check(const std::filesystem::path& deck, std::ostream& out, std::ostream& err, int ranks) {
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
  // A deck with a mesh must also build into a runnable model; a deck is valid or not, so the
  // build's errors come before anything is called valid.
  std::optional<setup::BuildResult> built;
  if (!m.nodes.empty() || !m.solids.empty()) {
    built = setup::build(m);
    for (const auto& w : built->warnings)
      fmt::print(err, "warning: {}\n", w.to_string());
    if (!built->model) {
      for (const auto& d : built->errors)
        fmt::print(err, "error: {}\n", d.to_string());
      fmt::print(err, "{}: {} error{}\n", deck.string(), built->errors.size(),
                 built->errors.size() == 1 ? "" : "s");
      return 1;
    }
  }
  fmt::print(out, "{}: valid\n", deck.string());
  if (!m.title.empty())
    fmt::print(out, "title: {}\n", m.title);
  fmt::print(out, "files read: {}\n", m.files_read.size());
  fmt::print(out, "curves: {}\n", m.curves.size());
  for (const auto& c : m.curves) {
    fmt::print(out, "  curve {}{}: {} points\n", c.id, c.title.empty() ? "" : " (" + c.title + ")",
               c.abscissa.size());
  }
  print_contacts(m, out);
  fmt::print(out, "cohesive interfaces: {}\n", m.user_interface_frictions.size());
  for (const auto& u : m.user_interface_frictions)
    print_law(m, u, out);
  if (built)
    print_mesh(m, *built->model, out);
  for (const setup::HingeAdvice& a :
       built ? setup::hinge_resolution_advice(*built->model) : std::vector<setup::HingeAdvice>{})
    fmt::print(out, "advice: {}\n", a.message);
  for (const setup::FibreAlignmentAdvice& a : built ? setup::fibre_alignment_advice(*built->model)
                                                    : std::vector<setup::FibreAlignmentAdvice>{})
    fmt::print(out, "advice: {}\n", a.message);
  if (built)
    print_interface_warnings(*built->model, err);
  if (ranks > 1) {
    if (!built) {
      fmt::print(err, "error: {}: --ranks {}: the deck has no mesh to split\n", deck.string(),
                 ranks);
      return 1;
    }
    const domain::DecomposeResult split = domain::decompose(*built->model, ranks);
    if (!split.error.empty()) {
      fmt::print(err, "error: {}: --ranks {}: {}\n", deck.string(), ranks, split.error);
      return 1;
    }
    print_decomposition(*built->model, split.decomposition, out);
  }
  return 0;
}

}  // namespace plyform::app

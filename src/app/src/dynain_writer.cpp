#include "plyform/app/dynain_writer.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "plyform/element/shell_kernels.hpp"
#include "shell_formability.hpp"
#include "shell_stress_global.hpp"

namespace plyform::app {
namespace {

/// A real number right-aligned in `width` characters, in E notation with as many digits as the
/// field holds: a sign, "d.", the decimals and "E+dd" (width 16: 10 significant digits). With
/// `blank`, one digit fewer, so that a blank always leads the field (a reader that splits the
/// card at blanks still finds the fields). Magnitudes below 1e-99 are written as 0 (a
/// three-digit exponent would not fit); none of the written quantities reaches 1e100, which is
/// refused rather than written wider.
std::string real_field(double v, int width, bool blank = false) {
  if (!std::isfinite(v))
    throw std::runtime_error(fmt::format("dynain: a non-finite value ({}) cannot be written", v));
  if (std::abs(v) < 1e-99)
    v = 0.0;
  if (std::abs(v) >= 1e100)
    throw std::runtime_error(fmt::format("dynain: {:.6e} does not fit a field", v));
  return fmt::format("{:>{}.{}E}", v, width, width - (blank ? 8 : 7));
}

/// The fields of LARGE 1 (*INITIAL_STRESS_SHELL, *INITIAL_STRAIN_SHELL): LS-DYNA's large
/// format, five fields of 16 characters to a card of 80 columns, as OpenRadioss's reader of
/// LS-DYNA decks and LS-PrePost's dynain take it (pydyna writes 20; plyform reads both:
/// keyword/common_cards.hpp); 9 significant digits behind a blank.
std::string large_field(double v) {
  return real_field(v, 16, true);
}

/// One shell to write: its deck id (the file lists them in id order), block and index.
struct ShellRef {
  core::GlobalId id;
  std::size_t block, element, shell;  // shell: its index among all shells (formability)
};

std::vector<ShellRef> written_shells(const core::Model& m) {
  std::vector<std::size_t> first(m.shell_blocks.size() + 1, 0);
  for (std::size_t b = 0; b < m.shell_blocks.size(); ++b)
    first[b + 1] = first[b] + m.shell_blocks[b].size();
  std::vector<ShellRef> out;
  for (const core::Index bi : m.output.dynain.shell_blocks) {
    const auto b = static_cast<std::size_t>(bi);
    for (std::size_t e = 0; e < m.shell_blocks[b].size(); ++e)
      out.push_back({m.shell_blocks[b].element_id[e], b, e, first[b] + e});
  }
  std::sort(out.begin(), out.end(),
            [](const ShellRef& a, const ShellRef& b) { return a.id < b.id; });
  return out;
}

void write_nodes(std::ostream& f, const core::Model& m, const engine::NodalState& ns,
                 const std::vector<ShellRef>& shells) {
  std::vector<core::Index> nodes;
  for (const ShellRef& r : shells) {
    const core::Index* c = &m.shell_blocks[r.block].connectivity[4 * r.element];
    nodes.insert(nodes.end(), c, c + 4);
  }
  std::sort(nodes.begin(), nodes.end(), [&](core::Index a, core::Index b) {
    return m.node_id[static_cast<std::size_t>(a)] < m.node_id[static_cast<std::size_t>(b)];
  });
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  f << "*NODE\n$#   nid               x               y               z\n";
  for (const core::Index n : nodes) {
    const auto i = static_cast<std::size_t>(n);
    f << fmt::format("{:>8}", m.node_id[i]) << real_field(ns.x[i], 16) << real_field(ns.y[i], 16)
      << real_field(ns.z[i], 16) << '\n';
  }
}

void write_elements(std::ostream& f, const core::Model& m,
                    const std::vector<element::ShellBlockState>& states,
                    const std::vector<ShellRef>& shells) {
  f << "*ELEMENT_SHELL_THICKNESS\n"
       "$#   eid     pid      n1      n2      n3      n4\n"
       "$#         thic1           thic2           thic3           thic4            beta\n";
  for (const ShellRef& r : shells) {
    const core::ShellBlock& blk = m.shell_blocks[r.block];
    const core::Index* c = &blk.connectivity[4 * r.element];
    f << fmt::format("{:>8}{:>8}", r.id, m.parts[static_cast<std::size_t>(blk.part)].id);
    for (int k = 0; k < 4; ++k)
      f << fmt::format("{:>8}", m.node_id[static_cast<std::size_t>(c[k])]);
    f << '\n';
    // The element's current thickness at its four nodes: the element keeps one thickness.
    const double h = states[r.block].thickness[r.element];
    for (int k = 0; k < 4; ++k)
      f << real_field(h, 16);
    if (!blk.material_angle.empty())
      f << real_field(blk.material_angle[r.element] * 180.0 / std::numbers::pi, 16);
    f << '\n';
  }
}

void write_stresses(std::ostream& f, const core::Model& m, const engine::Snapshot& s,
                    const std::vector<ShellRef>& shells) {
  f << "*INITIAL_STRESS_SHELL\n"
       "$#     eid    nplane    nthick     nhisv    ntensr     large    nthint    nthhsv\n"
       "$#             t           sigxx           sigyy           sigzz           sigxy\n"
       "$#         sigyz           sigzx             eps\n";
  std::vector<double> zeta, weight;
  for (const ShellRef& r : shells) {
    const core::ShellBlock& blk = m.shell_blocks[r.block];
    const element::ShellBlockState& st = (*s.shells)[r.block];
    const auto nip = static_cast<std::size_t>(st.nip);
    const auto inplane = static_cast<std::size_t>(st.inplane);
    zeta.resize(nip);
    weight.resize(nip);
    element::thickness_rule(blk.rule, st.nip, zeta.data(), weight.data());
    double e1[3], e2[3], e3[3];
    current_shell_frame(blk, *s.nodes, r.element, e1, e2, e3);
    const double* axes[3] = {e1, e2, e3};
    f << fmt::format("{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}\n", r.id, inplane, nip, 0, 0,
                     1, 0, 0);
    // LS-DYNA's order: per thickness point, its in-plane points (ELFORM 16: the Gauss points
    // (-,-) (+,-) (+,+) (-,+), the kernel's own order).
    for (std::size_t k = 0; k < nip; ++k) {
      for (std::size_t g = 0; g < inplane; ++g) {
        const std::size_t q = r.element * st.points_per_element() + g * nip + k;
        const double l[3][3] = {{st.s[0][q], st.s[2][q], st.s[4][q]},
                                {st.s[2][q], st.s[1][q], st.s[3][q]},
                                {st.s[4][q], st.s[3][q], 0.0}};
        double sig[6];
        shell_stress_to_global(axes, l, sig);
        f << large_field(zeta[k]) << large_field(sig[0]) << large_field(sig[1])
          << large_field(sig[2]) << large_field(sig[3]) << '\n'
          << large_field(sig[4]) << large_field(sig[5]) << large_field(st.eps_p[q]) << '\n';
      }
    }
  }
}

void write_strains(std::ostream& f, const std::vector<element::ShellBlockState>& states,
                   const std::vector<ShellRef>& shells, const ShellFormability& formability) {
  f << "*INITIAL_STRAIN_SHELL\n"
       "$#     eid    nplane    nthick     large                              ilocal\n"
       "$#         epsxx           epsyy           epszz           epsxy           epsyz\n"
       "$#         epszx               t\n";
  for (const ShellRef& r : shells) {
    double bottom[6], top[6];
    if (!formability.surface_strain_tensors(r.shell, states[r.block].thickness[r.element], bottom,
                                            top))
      continue;  // a collapsed shell has no strain to give
    f << fmt::format("{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}\n", r.id, 1, 2, 1, "", "",
                     "", 0);
    const double* surface[2] = {bottom, top};
    for (int k = 0; k < 2; ++k) {
      const double* e = surface[k];
      f << large_field(e[0]) << large_field(e[1]) << large_field(e[2]) << large_field(e[3])
        << large_field(e[4]) << '\n'
        << large_field(e[5]) << large_field(k == 0 ? -1.0 : 1.0) << '\n';
    }
  }
}

}  // namespace

void write_dynain(const std::filesystem::path& file, const core::Model& model,
                  const engine::Snapshot& s) {
  const std::vector<ShellRef> shells = written_shells(model);
  std::filesystem::path tmp = file;
  tmp += ".tmp";
  {
    std::ofstream f(tmp);
    if (!f)
      throw std::runtime_error("cannot write " + tmp.string());
    f << "*KEYWORD\n"
      << fmt::format(
             "$ plyform dynain: the formed part at t = {:.9g} (cycle {}): current nodes and "
             "thicknesses,\n$ every point's stress (global axes) and plastic strain, the "
             "surfaces' strains. Velocities,\n$ contact states and the laws' other history are "
             "not carried (docs/outputs.md).\n",
             s.time, s.cycle);
    write_nodes(f, model, *s.nodes, shells);
    write_elements(f, model, *s.shells, shells);
    write_stresses(f, model, s, shells);
    if (!shells.empty()) {
      // The surface strains' curvature fit needs every shell's neighbours: set up once here,
      // at the end of the run (the states keep their own).
      ShellFormability formability(model, model.solid_count() + model.shell_count());
      formability.compute(*s.nodes, *s.shells);
      write_strains(f, *s.shells, shells, formability);
    }
    f << "*END\n";
    f.flush();
    if (!f)
      throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, file);
}

}  // namespace plyform::app

#include "plyform/thermal/heat_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <sstream>
#include <string>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "plyform/core/invariant.hpp"
#include "plyform/core/stopwatch.hpp"
#include "plyform/thermal/element_conductance.hpp"

namespace plyform::thermal {
namespace {

using core::Index;
using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major, int indices

[[nodiscard]] std::size_t idx(Index i) {
  return static_cast<std::size_t>(i);
}

double curve_or_constant(const core::Model& m, Index curve, double mult, double t) {
  return curve >= 0 ? mult * m.curves[idx(curve)](t) : mult;
}

bool is_triangle(const Index* c) {
  return c[3] == c[2];
}

// A time in a message, to 6 significant digits (as the engine prints it): std::to_string's
// fixed 6 decimals print 0.000000 at explicit time scales.
std::string time_text(double t) {
  std::ostringstream os;
  os.precision(6);
  os << t;
  return os.str();
}

// A contact link's part of the step: the flux into the slave q = hA (sum w_j T_j - T_s) =
// -hA sum_i a_i T_i with a = (1, -w_1 .. -w_4).
struct LinkTerm {
  std::array<Index, 5> node;     // slave, masters
  std::array<Index, 5> unknown;  // theirs (-1: a node that does not conduct)
  std::array<double, 5> a;
  double ha;
  bool one_way;
};

// A prescribed temperature of the step: its change, its row's right-hand side and diagonal
// before it was held, and its column's off-diagonal entries (row, value), entries
// [column_begin, column_end) of the step's held_column.
struct Held {
  std::size_t unknown;
  double change;
  double b;
  double diagonal;
  std::size_t column_begin, column_end;
};

// Calls f(thermal material, nodes, corners, volume, thick) for every element of a part that
// conducts, on the reference geometry: a hexahedron's 8 nodes and volume, a shell's 4 (a
// triangle's 3) and its area times its initial thickness; `thick`: a thick thermal shell.
template <class F>
void for_each_conducting_element(const core::Model& model, F&& f) {
  const auto node_xyz = [&](Index i) {
    return Vec3{model.x0[idx(i)], model.y0[idx(i)], model.z0[idx(i)]};
  };
  for (const core::SolidBlock& b : model.solid_blocks) {
    const Index mat = model.parts[idx(b.part)].thermal_material;
    if (mat < 0)
      continue;
    for (std::size_t e = 0; e < b.size(); ++e) {
      const Index* c = &b.connectivity[8 * e];
      std::array<Vec3, 8> x;
      for (std::size_t k = 0; k < 8; ++k)
        x[k] = node_xyz(c[k]);
      f(mat, c, 8, hex8_volume(x), false);
    }
  }
  for (const core::ShellBlock& b : model.shell_blocks) {
    const Index mat = model.parts[idx(b.part)].thermal_material;
    if (mat < 0)
      continue;
    for (std::size_t e = 0; e < b.size(); ++e) {
      const Index* c = &b.connectivity[4 * e];
      const bool tri = is_triangle(c);
      std::array<Vec3, 4> x;
      for (std::size_t k = 0; k < 4; ++k)
        x[k] = node_xyz(c[k]);
      const int corners = tri ? 3 : 4;
      double t0 = 0.0;
      for (int k = 0; k < corners; ++k)
        t0 += b.thickness[4 * e + static_cast<std::size_t>(k)] / corners;
      f(mat, c, corners, face_area(x, tri) * t0, model.thermal.thick_shells);
    }
  }
}

}  // namespace

struct HeatSolver::Matrices {
  SparseMatrix K;             // conductance, unscaled by the speed-up factor
  SparseMatrix A;             // the step's matrix: C / dt + theta (TSF K + H)
  std::vector<int> diagonal;  // position of each unknown's diagonal entry in the values
  Eigen::SimplicialLDLT<SparseMatrix> direct;
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper,
                           Eigen::DiagonalPreconditioner<double>>
      iterative;
  bool analysed = false;
  // Scratch of one step, sized once and reused (a thermal step may come every cycle).
  Eigen::VectorXd t, kt, b, dt, guess;
  std::vector<double> s_conv, h_conv, s_rad, h_rad, s_flux, s_gen;
  std::vector<LinkTerm> terms;
  std::vector<Held> held;
  std::vector<std::pair<int, double>> held_column;
  std::vector<char> is_held;  // per unknown, while a step has prescribed temperatures

  // The position of entry (row, col) in the values (-1: not in the pattern).
  [[nodiscard]] int entry(const SparseMatrix& m, int row, int col) const {
    const int* begin = m.innerIndexPtr() + m.outerIndexPtr()[col];
    const int* end = m.innerIndexPtr() + m.outerIndexPtr()[col + 1];
    const int* it = std::lower_bound(begin, end, row);
    return it != end && *it == row ? static_cast<int>(it - m.innerIndexPtr()) : -1;
  }
};

HeatSolver::HeatSolver(const core::Model& model, std::span<double> temperature)
    : model_(model), m_(std::make_unique<Matrices>()) {
  const std::size_t n = model.node_count();
  unknown_.assign(n, -1);
  // Capacity per node, and every node of a conducting element an unknown (in node order).
  // A thick thermal shell's corners also get a bottom and a top unknown (after all the
  // nodes'), the capacity shared t (1/6, 2/3, 1/6) between bottom, middle and top.
  std::vector<double> capacity(n, 0.0), face_capacity(n, 0.0);
  std::vector<char> thick(n, 0);
  for_each_conducting_element(
      model, [&](Index mat, const Index* c, int corners, double volume, bool thick_shell) {
        const core::ThermalMaterial& tm = model.thermal_materials[idx(mat)];
        for (int k = 0; k < corners; ++k) {
          const double share = tm.density * tm.heat_capacity * volume / corners;
          capacity[idx(c[k])] += thick_shell ? share * 2.0 / 3.0 : share;
          if (thick_shell) {
            face_capacity[idx(c[k])] += share / 6.0;
            thick[idx(c[k])] = 1;
          }
          unknown_[idx(c[k])] = 0;
        }
      });
  for (std::size_t i = 0; i < n; ++i) {
    if (unknown_[i] == 0) {
      unknown_[i] = static_cast<Index>(nodes_.size());
      nodes_.push_back(static_cast<Index>(i));
      layer_.push_back(0);
      capacity_.push_back(capacity[i]);
    }
  }
  for (int side : {-1, 1}) {
    std::vector<Index>& face = side < 0 ? bottom_ : top_;
    face.assign(std::find(thick.begin(), thick.end(), 1) != thick.end() ? n : 0, -1);
    for (std::size_t i = 0; i < face.size(); ++i) {
      if (!thick[i])
        continue;
      face[i] = static_cast<Index>(nodes_.size());
      nodes_.push_back(static_cast<Index>(i));
      layer_.push_back(static_cast<signed char>(side));
      capacity_.push_back(face_capacity[i]);
    }
  }
  normal_.assign(bottom_.empty() ? 0 : 3 * n, 0.0);
  const std::size_t u = nodes_.size();
  Matrices& m = *m_;
  build_pattern();
  for (auto* v : {&m.s_conv, &m.h_conv, &m.s_rad, &m.h_rad, &m.s_flux, &m.s_gen})
    v->assign(u, 0.0);
  m.t.resize(static_cast<Eigen::Index>(u));
  m.dt.setZero(static_cast<Eigen::Index>(u));

  // Heat generation: each element's volume share, per material (a thick shell's shared as
  // its capacity).
  for_each_conducting_element(
      model, [&](Index mat, const Index* c, int corners, double volume, bool thick_shell) {
        if (model.thermal_materials[idx(mat)].generation == 0.0)
          return;
        for (int k = 0; k < corners; ++k) {
          for (int side = thick_shell ? -1 : 0; side <= (thick_shell ? 1 : 0); ++side) {
            const double share = !thick_shell ? 1.0 : side == 0 ? 2.0 / 3.0 : 1.0 / 6.0;
            generation_.push_back({unknown_at(c[k], side), share * volume / corners});
            generation_material_.push_back(mat);
          }
        }
      });

  // Prescribed temperatures of conducting nodes; those active at t = 0 hold from the start.
  for (std::size_t h = 0; h < model.temperature_histories.size(); ++h) {
    const core::TemperatureHistory& th = model.temperature_histories[h];
    const Index un = unknown_at(th.node, th.loc);
    if (un < 0)
      continue;
    prescribed_.push_back({un, h});
  }
  // Every unknown starts at its node's temperature (a thick shell uniform through its
  // thickness), the prescribed ones active at t = 0 at theirs.
  temperature_.resize(u);
  for (std::size_t i = 0; i < u; ++i)
    temperature_[i] = temperature[idx(nodes_[i])];
  for (const auto& [un, h] : prescribed_) {
    const core::TemperatureHistory& th = model.temperature_histories[h];
    if (th.birth <= 0.0)
      temperature_[idx(un)] = curve_or_constant(model, th.curve, th.scale, 0.0);
  }
  for (std::size_t i = 0; i < u; ++i)
    if (layer_[i] == 0)
      temperature[idx(nodes_[i])] = temperature_[i];
  initial_ = temperature_;
  change_.assign(u, 0.0);
  next_ = model.thermal.dt_initial;
}

HeatSolver::~HeatSolver() = default;

// The matrix pattern: every pair of nodes of a conducting element, every diagonal, and the
// couplings the contact links have brought so far (extra_). The values start at 0.
void HeatSolver::build_pattern() {
  const std::size_t u = nodes_.size();
  const auto conducts = [&](Index part) { return model_.parts[idx(part)].thermal_material >= 0; };
  std::vector<Eigen::Triplet<double>> pairs;
  for (std::size_t i = 0; i < u; ++i)
    pairs.emplace_back(static_cast<int>(i), static_cast<int>(i), 0.0);
  const auto add_pairs = [&](const auto& blocks, std::size_t per) {
    for (const auto& b : blocks) {
      if (!conducts(b.part))
        continue;
      for (std::size_t e = 0; e < b.size(); ++e)
        for (std::size_t i = 0; i < per; ++i)
          for (std::size_t j = 0; j < per; ++j)
            pairs.emplace_back(static_cast<int>(unknown_[idx(b.connectivity[per * e + i])]),
                               static_cast<int>(unknown_[idx(b.connectivity[per * e + j])]), 0.0);
    }
  };
  add_pairs(model_.solid_blocks, 8);
  if (!model_.thermal.thick_shells) {
    add_pairs(model_.shell_blocks, 4);
  } else {
    for (const core::ShellBlock& b : model_.shell_blocks) {
      if (!conducts(b.part))
        continue;
      for (std::size_t e = 0; e < b.size(); ++e) {
        const std::array<Index, 12> un = thick_unknowns(&b.connectivity[4 * e]);
        for (Index i : un)
          for (Index j : un)
            pairs.emplace_back(static_cast<int>(i), static_cast<int>(j), 0.0);
      }
    }
  }
  for (const auto& rc : extra_) {
    pairs.emplace_back(rc[0], rc[1], 0.0);
    pairs.emplace_back(rc[1], rc[0], 0.0);
  }
  Matrices& m = *m_;
  m.K = SparseMatrix(static_cast<int>(u), static_cast<int>(u));
  m.K.setFromTriplets(pairs.begin(), pairs.end());
  m.K.makeCompressed();
  std::fill(m.K.valuePtr(), m.K.valuePtr() + m.K.nonZeros(), 0.0);
  m.A = m.K;
  m.diagonal.resize(u);
  for (std::size_t i = 0; i < u; ++i)
    m.diagonal[i] = m.entry(m.K, static_cast<int>(i), static_cast<int>(i));
  m.analysed = false;
  since_assembly_ = 0;  // the conductance is assembled anew
}

double HeatSolver::step_length(double dt_mech) const {
  const core::ThermalControls& c = model_.thermal;
  if (!c.variable_step)
    return c.dt_initial;
  const double lo = c.dt_min > 0.0 ? c.dt_min : dt_mech;
  const double hi = c.dt_max > 0.0  ? c.dt_max
                    : dt_mech > 0.0 ? 100.0 * dt_mech
                                    : std::numeric_limits<double>::infinity();
  return std::clamp(next_, lo, std::max(lo, hi));
}

// The conductance on the current geometry, colour by colour (a colour's elements share no
// node, hence no matrix entry: they add in parallel without races).
void HeatSolver::assemble(const Geometry& g) {
  Matrices& m = *m_;
  double* values = m.K.valuePtr();
  std::fill(values, values + m.K.nonZeros(), 0.0);
  const auto at = [&](Index i) {
    const double* p = g.xyz + g.stride * idx(i);
    return Vec3{p[0], p[1], p[2]};
  };
  const bool one_point = model_.thermal.one_point;
  for (const core::SolidBlock& b : model_.solid_blocks) {
    const Index tmat = model_.parts[idx(b.part)].thermal_material;
    if (tmat < 0)
      continue;
    const core::ThermalMaterial& tm = model_.thermal_materials[idx(tmat)];
    for (std::size_t colour = 0; colour + 1 < b.colour_start.size(); ++colour) {
      const long first = static_cast<long>(b.colour_start[colour]);
      const long last = static_cast<long>(b.colour_start[colour + 1]);
#pragma omp parallel for schedule(static)
      for (long le = first; le < last; ++le) {
        const Index* c = &b.connectivity[8 * static_cast<std::size_t>(le)];
        std::array<Vec3, 8> x;
        for (std::size_t k = 0; k < 8; ++k)
          x[k] = at(c[k]);
        const Tensor3 k = conductivity_tensor(tm, x[0], x[1], x[3], 1.0);
        double ke[8][8];
        hex8_conductance(x, k, one_point, ke);
        for (std::size_t j = 0; j < 8; ++j) {
          const int col = static_cast<int>(unknown_[idx(c[j])]);
          for (std::size_t i = 0; i < 8; ++i)
            values[m.entry(m.K, static_cast<int>(unknown_[idx(c[i])]), col)] += ke[i][j];
        }
      }
    }
  }
  for (std::size_t bi = 0; bi < model_.shell_blocks.size(); ++bi) {
    const core::ShellBlock& b = model_.shell_blocks[bi];
    const Index tmat = model_.parts[idx(b.part)].thermal_material;
    if (tmat < 0)
      continue;
    const core::ThermalMaterial& tm = model_.thermal_materials[idx(tmat)];
    const double* current = bi < g.shell_thickness.size() ? g.shell_thickness[bi] : nullptr;
    const bool thick = model_.thermal.thick_shells;
    for (std::size_t colour = 0; colour + 1 < b.colour_start.size(); ++colour) {
      const long first = static_cast<long>(b.colour_start[colour]);
      const long last = static_cast<long>(b.colour_start[colour + 1]);
#pragma omp parallel for schedule(static)
      for (long le = first; le < last; ++le) {
        const auto e = static_cast<std::size_t>(le);
        const Index* c = &b.connectivity[4 * e];
        const bool tri = is_triangle(c);
        std::array<Vec3, 4> x;
        for (std::size_t k = 0; k < 4; ++k)
          x[k] = at(c[k]);
        const int corners = tri ? 3 : 4;
        double t = 0.0;
        if (current != nullptr) {
          t = current[e];
        } else {
          for (int k = 0; k < corners; ++k)
            t += b.thickness[4 * e + static_cast<std::size_t>(k)] / corners;
        }
        const Tensor3 k = conductivity_tensor(tm, x[0], x[1], x[3], 1.0);
        if (thick) {
          double ke[12][12];
          thick_shell_conductance(x, tri, k, t, ke);
          const std::array<Index, 12> un = thick_unknowns(c);
          for (std::size_t j = 0; j < 12; ++j) {
            if (j % 4 >= static_cast<std::size_t>(corners))
              continue;
            const int col = static_cast<int>(un[j]);
            for (std::size_t i = 0; i < 12; ++i)
              if (i % 4 < static_cast<std::size_t>(corners))
                values[m.entry(m.K, static_cast<int>(un[i]), col)] += ke[i][j];
          }
          continue;
        }
        double ke[4][4];
        shell_conductance(x, tri, k, t, ke);
        for (int j = 0; j < corners; ++j) {
          const int col = static_cast<int>(unknown_[idx(c[j])]);
          for (int i = 0; i < corners; ++i)
            values[m.entry(m.K, static_cast<int>(unknown_[idx(c[i])]), col)] += ke[i][j];
        }
      }
    }
  }
}

StepReport HeatSolver::advance(double t1, const Geometry& g, std::span<double> temperature,
                               const MechanicalHeat& heat,
                               std::span<const core::ContactHeatLink> links, double /*dt_mech*/) {
  StepReport rep;
  const double h = t1 - time_;
  if (!(h > 0.0))
    return rep;
  const core::ThermalControls& c = model_.thermal;
  Matrices& m = *m_;
  const std::size_t u = nodes_.size();
  const bool steady = c.steady;
  const double theta = steady ? 1.0 : c.theta;
  const double t_theta = time_ + theta * h;  // where the step's sources are evaluated
  const double scale =
      c.tsf_curve >= 0 ? model_.curves[idx(c.tsf_curve)](t_theta) : std::max(c.tsf, 0.0);

  // Contact links: each couples a slave node to its segment's nodes. A coupling of two
  // conducting nodes the pattern lacks rebuilds it (the contact found a new neighbour).
  // Each link's unknowns: a thick shell's node couples through the face turned to the other
  // side of the contact.
  if (!normal_.empty())
    update_normals(g);
  link_unknowns_.resize(links.size());
  for (std::size_t li = 0; li < links.size(); ++li)
    link_unknowns_[li] = link_unknowns(links[li], g);
  bool new_coupling = false;
  for (std::size_t li = 0; li < links.size(); ++li) {
    const core::ContactHeatLink& l = links[li];
    if (l.heat->one_way)
      continue;
    const std::array<Index, 5>& un = link_unknowns_[li];
    std::array<double, 5> w{1.0, l.weight[0], l.weight[1], l.weight[2], l.weight[3]};
    for (std::size_t i = 0; i < 5; ++i) {
      const Index ui = un[i];
      if (ui < 0 || w[i] == 0.0)
        continue;
      for (std::size_t j = i + 1; j < 5; ++j) {
        const Index uj = un[j];
        if (uj >= 0 && w[j] != 0.0 &&
            m.entry(m.K, static_cast<int>(ui), static_cast<int>(uj)) < 0) {
          extra_.push_back({static_cast<int>(ui), static_cast<int>(uj)});
          new_coupling = true;
        }
      }
    }
  }
  if (new_coupling)
    build_pattern();

  if (since_assembly_ == 0 || since_assembly_ >= std::max(1, c.reassemble_every)) {
    assemble(g);
    since_assembly_ = 0;
  }
  ++since_assembly_;

  for (std::size_t i = 0; i < u; ++i)
    m.t[static_cast<Eigen::Index>(i)] = temperature_[i];
  m.kt.noalias() = scale * (m.K * m.t);

  // Faces: convection, radiation (linearized about T_n) and flux, lumped on the nodes.
  for (auto* v : {&m.s_conv, &m.h_conv, &m.s_rad, &m.h_rad, &m.s_flux, &m.s_gen})
    std::fill(v->begin(), v->end(), 0.0);
  const auto at = [&](Index i) {
    const double* p = g.xyz + g.stride * idx(i);
    return Vec3{p[0], p[1], p[2]};
  };
  // BC_FLG 1: the nodes in contact take no boundary heat.
  covered_.clear();
  for (const core::ContactHeatLink& l : links) {
    if (!l.heat->boundaries_off_in_contact || l.gap > l.heat->lmin)
      continue;
    if (covered_.empty())
      covered_.assign(model_.node_count(), 0);
    covered_[idx(l.slave)] = 1;
    for (std::size_t j = 0; j < 4; ++j)
      if (l.weight[j] != 0.0)
        covered_[idx(l.master[j])] = 1;
  }
  for (const core::HeatBoundary& hb : model_.heat_boundaries) {
    const double f = curve_or_constant(model_, hb.curve, hb.mult, t_theta) * scale;
    const double ambient = curve_or_constant(model_, hb.ambient_curve, hb.ambient_mult, t_theta);
    for (std::size_t face = 0; face * 4 < hb.faces.size(); ++face) {
      const Index* fn = &hb.faces[4 * face];
      const bool tri = is_triangle(fn);
      std::array<Vec3, 4> x;
      for (std::size_t k = 0; k < 4; ++k)
        x[k] = at(fn[k]);
      const int corners = tri ? 3 : 4;
      const double share = face_area(x, tri) / corners;
      for (int k = 0; k < corners; ++k) {
        const Index un = unknown_at(fn[k], hb.loc);
        if (un < 0 || (!covered_.empty() && covered_[idx(fn[k])]))
          continue;
        const std::size_t q = idx(un);
        const double tn = temperature_[q];
        switch (hb.kind) {
          case core::HeatBoundaryKind::convection:
            m.s_conv[q] += f * share * (ambient - tn);
            m.h_conv[q] += theta * f * share;
            break;
          case core::HeatBoundaryKind::radiation: {
            const double t2 = tn * tn, a2 = ambient * ambient;
            m.s_rad[q] += f * share * (a2 * a2 - t2 * t2);
            m.h_rad[q] += theta * 4.0 * f * share * t2 * tn;
            break;
          }
          case core::HeatBoundaryKind::flux:
            m.s_flux[q] += f * hb.node_mult[static_cast<std::size_t>(k)] * share;
            break;
        }
      }
    }
  }
  for (std::size_t k = 0; k < generation_.size(); ++k) {
    const core::ThermalMaterial& tm = model_.thermal_materials[idx(generation_material_[k])];
    m.s_gen[idx(generation_[k].first)] +=
        curve_or_constant(model_, tm.generation_curve, tm.generation, t_theta) * scale *
        generation_[k].second;
  }
  double mech_contact = 0.0, mech_friction = 0.0, mech_plastic = 0.0;
  m.b.resize(static_cast<Eigen::Index>(u));
  for (std::size_t i = 0; i < u; ++i) {
    double mech = 0.0;
    const std::size_t node = idx(nodes_[i]);
    if (layer_[i] != 0) {  // a thick shell's face: the mechanics' heat goes to the middle
      m.b[static_cast<Eigen::Index>(i)] =
          m.s_conv[i] + m.s_rad[i] + m.s_flux[i] + m.s_gen[i] - m.kt[static_cast<Eigen::Index>(i)];
      continue;
    }
    if (heat.contact != nullptr)
      mech += heat.contact[node], mech_contact += heat.contact[node];
    if (heat.friction != nullptr)
      mech += heat.friction[node], mech_friction += heat.friction[node];
    if (heat.plastic != nullptr)
      mech += heat.plastic[node], mech_plastic += heat.plastic[node];
    m.b[static_cast<Eigen::Index>(i)] = m.s_conv[i] + m.s_rad[i] + m.s_flux[i] + m.s_gen[i] +
                                        mech / h - m.kt[static_cast<Eigen::Index>(i)];
  }

  // A = C / h + theta (TSF K + H). A has K's pattern (build_pattern() gives it that pattern,
  // and nothing removes an entry): the values are copied, nothing is allocated.
  PLYFORM_INVARIANT(m.A.nonZeros() == m.K.nonZeros() && m.A.isCompressed(), "A has K's pattern");
  std::copy_n(m.K.valuePtr(), m.K.nonZeros(), m.A.valuePtr());
  double* a = m.A.valuePtr();
  const double ks = theta * scale;
  for (Eigen::Index k = 0; k < m.A.nonZeros(); ++k)
    a[k] *= ks;
  for (std::size_t i = 0; i < u; ++i)
    a[m.diagonal[i]] += (steady ? 0.0 : capacity_[i] / h) + m.h_conv[i] + m.h_rad[i];

  // Contact links: the flux into the slave q = hA (sum w_j T_j - T_s) = -hA sum_i a_i T_i
  // (a = 1, -w_1 .. -w_4) adds hA a_i a_j to the conducting rows and columns (symmetric, rows
  // summing to 0); a node that does not conduct (a tool), and the master of a one-way link,
  // keeps its temperature: its part moves to the right-hand side.
  // A link member's temperature: its unknown's, else (a tool) its node's.
  const auto t_at = [&](Index un, Index node) {
    return un >= 0 ? temperature_[idx(un)] : temperature[idx(node)];
  };
  std::vector<LinkTerm>& terms = m.terms;
  terms.clear();
  for (std::size_t li = 0; li < links.size(); ++li) {
    const core::ContactHeatLink& l = links[li];
    const std::array<Index, 5>& lu = link_unknowns_[li];
    const core::ContactHeat& ch = *l.heat;
    const double ts = t_at(lu[0], l.slave);
    double tm = 0.0;
    for (std::size_t j = 0; j < 4; ++j)
      tm += l.weight[j] * t_at(lu[j + 1], l.master[j]);
    double hc = 0.0;
    if (l.gap <= ch.lmin) {
      hc = ch.h0_curve >= 0 ? model_.curves[idx(ch.h0_curve)](std::max(l.pressure, 0.0)) : ch.h0;
    } else {
      hc = ch.k / l.gap + ch.frad * (ts * ts + tm * tm) * (ts + tm);
    }
    const double ha = hc * l.area * scale;
    if (!(ha > 0.0))
      continue;
    const LinkTerm lt{{l.slave, l.master[0], l.master[1], l.master[2], l.master[3]},
                      lu,
                      {1.0, -l.weight[0], -l.weight[1], -l.weight[2], -l.weight[3]},
                      ha,
                      ch.one_way};
    for (std::size_t i = 0; i < 5; ++i) {
      const Index ui = lt.unknown[i];
      if (ui < 0 || lt.a[i] == 0.0 || (lt.one_way && i > 0))
        continue;
      double r = 0.0;
      for (std::size_t j = 0; j < 5; ++j) {
        if (lt.a[j] == 0.0)
          continue;
        const Index uj = lt.unknown[j];
        r -= ha * lt.a[i] * lt.a[j] * t_at(uj, lt.node[j]);
        if (uj >= 0 && !(lt.one_way && j > 0))
          a[m.entry(m.A, static_cast<int>(ui), static_cast<int>(uj))] +=
              theta * ha * lt.a[i] * lt.a[j];
      }
      m.b[static_cast<Eigen::Index>(ui)] += r;
    }
    terms.push_back(lt);
  }

  // Prescribed temperatures: their change is known; their columns move to the right-hand
  // side (the matrix stays symmetric), and what holding them takes is the residual of their
  // rows in the full system.
  std::vector<Held>& held = m.held;
  std::vector<std::pair<int, double>>& held_column = m.held_column;
  held.clear();
  held_column.clear();
  for (const auto& [un, hi] : prescribed_) {
    const core::TemperatureHistory& th = model_.temperature_histories[hi];
    if (t1 < th.birth || t1 > th.death)
      continue;
    const std::size_t q = idx(un);
    Held x{q,
           curve_or_constant(model_, th.curve, th.scale, t1) - temperature_[q],
           m.b[static_cast<Eigen::Index>(q)],
           a[m.diagonal[q]],
           held_column.size(),
           0};
    const int col = static_cast<int>(q);
    for (int k = m.A.outerIndexPtr()[col]; k < m.A.outerIndexPtr()[col + 1]; ++k)
      if (m.A.innerIndexPtr()[k] != col)
        held_column.emplace_back(m.A.innerIndexPtr()[k], a[k]);
    x.column_end = held_column.size();
    held.push_back(x);
  }
  const auto column_of = [&](const Held& x) {
    return std::span<const std::pair<int, double>>(held_column.data() + x.column_begin,
                                                   x.column_end - x.column_begin);
  };
  for (const Held& x : held) {
    const int col = static_cast<int>(x.unknown);
    for (const auto& [row, v] : column_of(x)) {
      m.b[row] -= v * x.change;
      a[m.entry(m.A, row, col)] = 0.0;
      a[m.entry(m.A, col, row)] = 0.0;
    }
  }
  for (const Held& x : held)
    m.b[static_cast<Eigen::Index>(x.unknown)] = x.diagonal * x.change;

  core::Stopwatch solve_clock;
  if (c.solver == 12) {
    if (!m.analysed) {
      m.iterative.analyzePattern(m.A);
      m.analysed = true;
    }
    m.iterative.factorize(m.A);
    m.iterative.setMaxIterations(std::max(1, c.max_iterations));
    const double bnorm = m.b.norm();
    m.iterative.setTolerance(bnorm > 0.0 ? std::max(c.rel_tol, c.abs_tol / bnorm) : c.rel_tol);
    m.guess.resize(static_cast<Eigen::Index>(u));
    const double grow = last_dt_ > 0.0 ? h / last_dt_ : 1.0;
    for (std::size_t i = 0; i < u; ++i)
      m.guess[static_cast<Eigen::Index>(i)] = change_[i] * grow;
    for (const Held& x : held)
      m.guess[static_cast<Eigen::Index>(x.unknown)] = x.change;
    if (bnorm > 0.0)
      m.dt = m.iterative.solveWithGuess(m.b, m.guess);
    else
      m.dt.setZero(static_cast<Eigen::Index>(u));
    rep.iterations = static_cast<int>(m.iterative.iterations());
    rep.converged = bnorm == 0.0 || m.iterative.info() == Eigen::Success;
    iterations_ += rep.iterations;
  } else {
    if (!m.analysed) {
      m.direct.analyzePattern(m.A);
      m.analysed = true;
    }
    m.direct.factorize(m.A);
    if (m.direct.info() != Eigen::Success) {
      rep.ok = false;
      rep.error = "the thermal matrix is not positive definite at t = " + time_text(t1) +
                  " (a part with no capacity, or a negative conductivity)";
      return rep;
    }
    m.dt = m.direct.solve(m.b);
  }
  solve_seconds_ += solve_clock.lap();

  // The books of the step.
  HeatLedger step;
  for (std::size_t i = 0; i < u; ++i) {
    const double d = m.dt[static_cast<Eigen::Index>(i)];
    if (!std::isfinite(d)) {
      rep.ok = false;
      rep.error = "non-finite temperature at node " +
                  std::to_string(model_.node_id[idx(nodes_[i])]) + " at t = " + time_text(t1);
      return rep;
    }
    step.convection += h * (m.s_conv[i] - m.h_conv[i] * d);
    step.radiation += h * (m.s_rad[i] - m.h_rad[i] * d);
    step.flux += h * m.s_flux[i];
    step.generation += h * m.s_gen[i];
  }
  for (const Held& x : held) {
    double r = x.diagonal * x.change - x.b;
    for (const auto& [row, v] : column_of(x))
      r += v * m.dt[row];
    step.prescribed += h * r;
  }
  // The heat the links brought into the conducting nodes, at the theta point: between two
  // conducting sides it sums to 0; what remains came from tools and one-way masters.
  double contact_heat = 0.0;
  for (const LinkTerm& lt : terms) {
    double tsum = 0.0;
    for (std::size_t j = 0; j < 5; ++j) {
      if (lt.a[j] == 0.0)
        continue;
      const Index uj = lt.unknown[j];
      const bool implicit = uj >= 0 && !(lt.one_way && j > 0);
      tsum += lt.a[j] * (t_at(uj, lt.node[j]) +
                         (implicit ? theta * m.dt[static_cast<Eigen::Index>(uj)] : 0.0));
    }
    for (std::size_t i = 0; i < 5; ++i) {
      if (lt.a[i] == 0.0 || lt.unknown[i] < 0 || (lt.one_way && i > 0))
        continue;
      contact_heat -= h * lt.ha * lt.a[i] * tsum;
    }
  }
  step.contact = mech_contact + contact_heat;

  step.friction = mech_friction;
  step.plastic = mech_plastic;
  ledger_.contact += step.contact;
  ledger_.friction += step.friction;
  ledger_.plastic += step.plastic;
  ledger_.convection += step.convection;
  ledger_.radiation += step.radiation;
  ledger_.flux += step.flux;
  ledger_.generation += step.generation;
  ledger_.prescribed += step.prescribed;
  ledger_.moved += std::abs(step.contact) + std::abs(step.friction) + std::abs(step.plastic) +
                   std::abs(step.convection) + std::abs(step.radiation) + std::abs(step.flux) +
                   std::abs(step.generation) + std::abs(step.prescribed);

  std::vector<char>& is_held = m.is_held;
  if (!held.empty()) {
    is_held.assign(u, 0);  // no allocation once sized
    for (const Held& x : held)
      is_held[x.unknown] = 1;
  }
  double stored = 0.0;
  for (std::size_t i = 0; i < u; ++i) {
    const double d = m.dt[static_cast<Eigen::Index>(i)];
    temperature_[i] += d;
    change_[i] = d;
    if (held.empty() || !is_held[i])
      rep.max_change = std::max(rep.max_change, std::abs(d));
    if (layer_[i] == 0)
      temperature[idx(nodes_[i])] = temperature_[i];
    stored += capacity_[i] * (temperature_[i] - initial_[i]);
  }
  ledger_.stored = stored;
  time_ = t1;
  last_dt_ = h;
  ++steps_;
  if (c.variable_step) {
    if (rep.max_change > c.dtemp)
      next_ = h * c.tscp;
    else if (rep.max_change < 0.5 * c.dtemp)
      next_ = h * 1.25;
    else
      next_ = h;
  }
  return rep;
}

Index HeatSolver::unknown_at(Index node, int loc) const {
  const std::vector<Index>& face = loc < 0 ? bottom_ : top_;
  if (loc != 0 && !face.empty() && face[idx(node)] >= 0)
    return face[idx(node)];
  return unknown_[idx(node)];
}

std::array<Index, 12> HeatSolver::thick_unknowns(const Index* c) const {
  std::array<Index, 12> un{};
  for (std::size_t i = 0; i < 4; ++i) {
    un[i] = unknown_[idx(c[i])];
    un[4 + i] = bottom_[idx(c[i])];
    un[8 + i] = top_[idx(c[i])];
  }
  return un;
}

// The area-weighted normals of the thick thermal shells' nodes on the current geometry.
void HeatSolver::update_normals(const Geometry& g) {
  std::fill(normal_.begin(), normal_.end(), 0.0);
  for (const core::ShellBlock& b : model_.shell_blocks) {
    if (model_.parts[idx(b.part)].thermal_material < 0)
      continue;
    for (std::size_t e = 0; e < b.size(); ++e) {
      const Index* c = &b.connectivity[4 * e];
      const bool tri = is_triangle(c);
      std::array<Vec3, 4> x;
      for (std::size_t k = 0; k < 4; ++k) {
        const double* p = g.xyz + g.stride * idx(c[k]);
        x[k] = Vec3{p[0], p[1], p[2]};
      }
      const Vec3 n = face_normal(x, tri);
      const double area = face_area(x, tri);
      for (std::size_t k = 0; k < (tri ? 3u : 4u); ++k)
        for (std::size_t d = 0; d < 3; ++d)
          normal_[3 * idx(c[k]) + d] += area * n[d];
    }
  }
}

// A link's unknowns (slave, then the segment's nodes): a node of a thick thermal shell
// couples through its face on the side of the other surface (the slave's toward the point it
// projects to, a master node's toward the slave); other nodes through their one temperature.
std::array<Index, 5> HeatSolver::link_unknowns(const core::ContactHeatLink& l,
                                               const Geometry& g) const {
  const auto at = [&](Index i) {
    const double* p = g.xyz + g.stride * idx(i);
    return Vec3{p[0], p[1], p[2]};
  };
  std::array<Index, 5> un{unknown_[idx(l.slave)], unknown_[idx(l.master[0])],
                          unknown_[idx(l.master[1])], unknown_[idx(l.master[2])],
                          unknown_[idx(l.master[3])]};
  if (normal_.empty())
    return un;
  const Vec3 xs = at(l.slave);
  Vec3 p{0.0, 0.0, 0.0};
  for (std::size_t j = 0; j < 4; ++j) {
    const Vec3 xj = at(l.master[j]);
    for (std::size_t d = 0; d < 3; ++d)
      p[d] += l.weight[j] * xj[d];
  }
  const auto face_toward = [&](Index node, const Vec3& from, const Vec3& to) {
    if (bottom_[idx(node)] < 0)
      return unknown_[idx(node)];
    double s = 0.0;
    for (std::size_t d = 0; d < 3; ++d)
      s += normal_[3 * idx(node) + d] * (to[d] - from[d]);
    return s >= 0.0 ? top_[idx(node)] : bottom_[idx(node)];
  };
  un[0] = face_toward(l.slave, xs, p);
  for (std::size_t j = 0; j < 4; ++j)
    un[j + 1] = face_toward(l.master[j], p, xs);
  return un;
}

void HeatSolver::face_temperatures(std::span<double> bottom, std::span<double> top) const {
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const std::size_t node = idx(nodes_[i]);
    if (layer_[i] == 0) {
      bottom[node] = top[node] = temperature_[i];  // until a face says otherwise
    }
  }
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (layer_[i] != 0)
      (layer_[i] < 0 ? bottom : top)[idx(nodes_[i])] = temperature_[i];
  }
}

void HeatSolver::interface_temperatures(std::span<double> temperature) const {
  for (std::size_t li = 0; li < link_unknowns_.size(); ++li) {
    const Index un = link_unknowns_[li][0];
    if (un >= 0)
      temperature[idx(nodes_[idx(un)])] = temperature_[idx(un)];
  }
}

void HeatSolver::visit_state(core::StateArchive& a) {
  a.fixed("temperature", std::span<double>(temperature_));
  a.fixed("change", std::span<double>(change_));
  a.array("pattern_links", extra_);
  if (!a.saving())
    build_pattern();  // the pattern the saved conductance fills
  a.fixed("conductance",
          std::span<double>(m_->K.valuePtr(), static_cast<std::size_t>(m_->K.nonZeros())));
  a.value("time", time_);
  a.value("next", next_);
  a.value("last_dt", last_dt_);
  a.value("steps", steps_);
  a.value("iterations", iterations_);
  a.value("since_assembly", since_assembly_);
  a.value("ledger", ledger_);
}

}  // namespace plyform::thermal

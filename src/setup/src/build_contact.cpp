#include "build_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <variant>

#include "plyform/contact/initial_penetrations.hpp"
#include "plyform/material/law_registry.hpp"
#include "plyform/setup/cohesive_law.hpp"
#include "plyform/setup/contact_penalty.hpp"
#include "tied_search.hpp"

namespace plyform::setup {
namespace {

using core::Index;
using Diagnostics = std::vector<keyword::Diagnostic>;

// Outward faces of an 8-node solid in LS-DYNA's node order (0-based local nodes).
constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                 {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double norm(const Vec& a) {
  return std::sqrt(dot(a, a));
}

// A contact surface: segments with what their stiffness and offset need.
struct Surface {
  std::vector<Index> segments;    // 4 per segment; a triangle repeats its third node
  std::vector<double> area;       // per segment
  std::vector<double> stiffness;  // per segment: K A / diagonal (shell) or K A^2 / V (solid)
  std::vector<double> thickness;  // per segment: shell thickness (0 for solid faces)
  std::vector<char> rigid;        // per segment: on a rigid part
  std::vector<Index> shell;       // per segment: its shell (numbered across blocks), -1 none
  std::vector<double> depth;      // per segment: a solid face's element depth V / A (0 shell)
  [[nodiscard]] std::size_t size() const { return area.size(); }
};

struct Geometry {
  const core::Model& m;
  [[nodiscard]] Vec x(Index n) const {
    const auto i = static_cast<std::size_t>(n);
    return {m.x0[i], m.y0[i], m.z0[i]};
  }
  [[nodiscard]] double area(const Index* q) const {
    if (q[2] == q[3])
      return 0.5 * norm(cross(sub(x(q[1]), x(q[0])), sub(x(q[2]), x(q[0]))));
    return 0.5 * norm(cross(sub(x(q[2]), x(q[0])), sub(x(q[3]), x(q[1]))));
  }
  [[nodiscard]] double diagonal(const Index* q) const {
    if (q[2] == q[3]) {
      return std::max(
          {norm(sub(x(q[1]), x(q[0]))), norm(sub(x(q[2]), x(q[1]))), norm(sub(x(q[0]), x(q[2])))});
    }
    return std::max(norm(sub(x(q[2]), x(q[0]))), norm(sub(x(q[3]), x(q[1]))));
  }
  // Volume of a solid from its outward faces (divergence theorem over their triangles).
  [[nodiscard]] double volume(const Index* c) const {
    double v = 0.0;
    for (const auto& f : kHexFaces) {
      const Vec a = x(c[f[0]]), b = x(c[f[1]]), cc = x(c[f[2]]), d = x(c[f[3]]);
      v += dot(a, cross(b, cc)) + dot(a, cross(cc, d));
    }
    return v / 6.0;
  }
};

// A face of 4 node indices with repeats removed: a quad, a triangle (q[2] == q[3]) or nothing.
bool normalise_face(std::array<Index, 4>& q) {
  std::array<Index, 4> u{};
  int n = 0;
  for (Index v : q) {
    if (n > 0 && (u[static_cast<std::size_t>(n - 1)] == v))
      continue;
    if (n == 3 && u[0] == v)
      continue;
    u[static_cast<std::size_t>(n++)] = v;
  }
  if (n >= 2 && u[static_cast<std::size_t>(n - 1)] == u[0])
    --n;
  if (n < 3)
    return false;
  if (n == 3)
    u[3] = u[2];
  q = u;
  return true;
}

std::array<Index, 4> sorted_key(const Index* q) {
  std::array<Index, 4> k{q[0], q[1], q[2], q[3]};
  std::sort(k.begin(), k.end());
  return k;
}

struct ContactBuilder {
  const model::ModelDesc& d;
  core::Model& m;
  Diagnostics& errors;
  Diagnostics& warnings;
  Geometry geo{m};
  std::unordered_map<std::int64_t, Index> node;
  std::unordered_map<std::int64_t, Index> part;

  void error(const model::SourceLocation& w, const std::string& kw, const std::string& field,
             const std::string& msg) {
    errors.push_back({w, kw, field, msg});
  }

  void index() {
    for (std::size_t i = 0; i < m.node_id.size(); ++i)
      node.emplace(m.node_id[i], static_cast<Index>(i));
    for (std::size_t i = 0; i < m.parts.size(); ++i)
      part.emplace(m.parts[i].id, static_cast<Index>(i));
  }

  [[nodiscard]] bool rigid_material(Index mat) const {
    return std::holds_alternative<core::RigidMaterial>(m.materials[static_cast<std::size_t>(mat)]);
  }

  // Segments of the shells and exterior solid faces of the parts marked in `pick`.
  Surface surface_of_parts(const std::vector<char>& pick) {
    Surface s;
    const auto add = [&](const Index* q, double k_base, double t, bool rigid, Index shell) {
      for (int j = 0; j < 4; ++j)
        s.segments.push_back(q[j]);
      s.area.push_back(geo.area(q));
      s.stiffness.push_back(k_base);
      s.thickness.push_back(t);
      s.rigid.push_back(rigid ? 1 : 0);
      s.shell.push_back(shell);
      s.depth.push_back(0.0);
    };
    Index shell_base = 0;  // shells numbered across the blocks, in block order
    for (const core::ShellBlock& b : m.shell_blocks) {
      const Index base = shell_base;
      shell_base += static_cast<Index>(b.size());
      if (!pick[static_cast<std::size_t>(b.part)])
        continue;
      const double kb = material::bulk_modulus(m.materials[static_cast<std::size_t>(b.material)]);
      for (std::size_t e = 0; e < b.size(); ++e) {
        const Index* q = &b.connectivity[4 * e];
        const int nn = q[2] == q[3] ? 3 : 4;
        double t = 0.0;
        for (int j = 0; j < nn; ++j)
          t += b.thickness[4 * e + static_cast<std::size_t>(j)];
        add(q, kb * geo.area(q) / geo.diagonal(q), t / nn, rigid_material(b.material),
            base + static_cast<Index>(e));
      }
    }
    for (const core::SolidBlock& b : m.solid_blocks) {
      if (!pick[static_cast<std::size_t>(b.part)])
        continue;
      const double kb = material::bulk_modulus(m.materials[static_cast<std::size_t>(b.material)]);
      // Exterior faces: those of one element only (among the solids of these parts).
      std::map<std::array<Index, 4>, int> count;
      for (std::size_t e = 0; e < b.size(); ++e) {
        for (const auto& f : kHexFaces) {
          std::array<Index, 4> q{};
          for (int j = 0; j < 4; ++j)
            q[static_cast<std::size_t>(j)] = b.connectivity[8 * e + static_cast<std::size_t>(f[j])];
          if (normalise_face(q))
            ++count[sorted_key(q.data())];
        }
      }
      for (std::size_t e = 0; e < b.size(); ++e) {
        const Index* c = &b.connectivity[8 * e];
        const double v = geo.volume(c);
        for (const auto& f : kHexFaces) {
          std::array<Index, 4> q{};
          for (int j = 0; j < 4; ++j)
            q[static_cast<std::size_t>(j)] = c[f[j]];
          if (!normalise_face(q) || count[sorted_key(q.data())] != 1)
            continue;
          const double a = geo.area(q.data());
          add(q.data(), v > 0.0 ? kb * a * a / v : 0.0, 0.0, rigid_material(b.material), -1);
          s.depth.back() = a > 0.0 ? v / a : 0.0;
        }
      }
    }
    return s;
  }

  // Every shell and exterior solid face of the model, keyed by its sorted nodes.
  Surface model_surface;
  std::map<std::array<Index, 4>, std::size_t> model_face;
  void ensure_model_surface() {
    if (!model_face.empty() || m.parts.empty())
      return;
    model_surface = surface_of_parts(std::vector<char>(m.parts.size(), 1));
    for (std::size_t s = 0; s < model_surface.size(); ++s)
      model_face.emplace(sorted_key(&model_surface.segments[4 * s]), s);
  }

  // The surface a contact side names; nullopt after an error. `nodes_only`: a node set.
  std::optional<Surface> side_surface(const model::ContactDesc& c, model::ContactSideType type,
                                      int id, const char* field, std::vector<Index>& node_list) {
    node_list.clear();
    if (type == model::ContactSideType::part || type == model::ContactSideType::part_set) {
      std::vector<char> pick(m.parts.size(), 0);
      std::vector<int> ids;
      if (type == model::ContactSideType::part) {
        ids.push_back(id);
      } else {
        for (const auto& ps : d.part_sets)
          if (ps.id == id)
            ids = ps.ids;
      }
      for (int p : ids) {
        const auto it = part.find(p);
        if (it == part.end()) {
          error(c.card1, c.keyword, field, "part " + std::to_string(p) + " does not exist");
          return std::nullopt;
        }
        pick[static_cast<std::size_t>(it->second)] = 1;
      }
      Surface s = surface_of_parts(pick);
      if (s.size() == 0) {
        error(c.card1, c.keyword, field,
              "the parts of " + std::string(field) + " " + std::to_string(id) +
                  " have no shell element or solid face to make a contact surface");
        return std::nullopt;
      }
      return s;
    }
    if (type == model::ContactSideType::segment_set) {
      const model::SetSegmentDesc* set = nullptr;
      for (const auto& ss : d.segment_sets)
        if (ss.id == id)
          set = &ss;
      if (set == nullptr) {
        error(c.card1, c.keyword, field, "*SET_SEGMENT " + std::to_string(id) + " does not exist");
        return std::nullopt;
      }
      ensure_model_surface();
      Surface s;
      for (std::size_t k = 0; k < set->segments.size(); ++k) {
        std::array<Index, 4> q{};
        bool ok = true;
        for (int j = 0; j < 4; ++j) {
          const auto it = node.find(set->segments[k][static_cast<std::size_t>(j)]);
          ok = ok && it != node.end();
          if (ok)
            q[static_cast<std::size_t>(j)] = it->second;
        }
        if (!ok || !normalise_face(q)) {
          error(set->segments_where[k], "*SET_SEGMENT", "N1",
                "segment " + std::to_string(k + 1) + " of set " + std::to_string(id) +
                    " is not a triangle or quadrilateral of existing nodes");
          return std::nullopt;
        }
        const auto it = model_face.find(sorted_key(q.data()));
        if (it == model_face.end()) {
          error(set->segments_where[k], "*SET_SEGMENT", "N1",
                "segment " + std::to_string(k + 1) + " of set " + std::to_string(id) +
                    " is neither a shell element nor an exterior face of a solid: its "
                    "stiffness and thickness are unknown");
          return std::nullopt;
        }
        const std::size_t f = it->second;
        for (Index v : q)
          s.segments.push_back(v);  // the set's own node order (its orientation)
        s.area.push_back(model_surface.area[f]);
        s.stiffness.push_back(model_surface.stiffness[f]);
        s.thickness.push_back(model_surface.thickness[f]);
        s.rigid.push_back(model_surface.rigid[f]);
        s.shell.push_back(model_surface.shell[f]);
        s.depth.push_back(model_surface.depth[f]);
      }
      return s;
    }
    // A node set (slave side only): the nodes carry the share of the model's surfaces.
    const model::SetListDesc* set = nullptr;
    for (const auto& ns : d.node_sets)
      if (ns.id == id)
        set = &ns;
    if (set == nullptr) {
      error(c.card1, c.keyword, field, "*SET_NODE_LIST " + std::to_string(id) + " does not exist");
      return std::nullopt;
    }
    for (int n : set->ids) {
      const auto it = node.find(n);
      if (it == node.end()) {
        error(c.card1, c.keyword, field, "node " + std::to_string(n) + " does not exist");
        return std::nullopt;
      }
      node_list.push_back(it->second);
    }
    ensure_model_surface();
    return model_surface;
  }

  // The slave-node data of a pass from the slave surface: each node gets an equal share of
  // the area and stiffness of each segment around it, and the mean offset of those segments.
  bool fill_slaves(const model::ContactDesc& c, const Surface& s, const std::vector<Index>& only,
                   double factor, double sst, double sfst, bool rigid_offset,
                   core::ContactPass& p) {
    const std::size_t n = m.node_count();
    std::vector<double> area(n, 0.0), stiff(n, 0.0), thick(n, 0.0), count(n, 0.0);
    std::vector<char> rigid(n, 0);
    std::vector<std::vector<Index>> shells(n), faces(n);
    for (std::size_t k = 0; k < s.size(); ++k) {
      const Index* q = &s.segments[4 * k];
      const int nn = q[2] == q[3] ? 3 : 4;
      for (int j = 0; j < nn; ++j) {
        const auto i = static_cast<std::size_t>(q[j]);
        area[i] += s.area[k] / nn;
        stiff[i] += s.stiffness[k] / nn;
        thick[i] += s.thickness[k];
        count[i] += 1.0;
        rigid[i] = static_cast<char>(rigid[i] | s.rigid[k]);
        if (s.shell[k] >= 0)
          shells[i].push_back(s.shell[k]);
        faces[i].push_back(static_cast<Index>(k));
      }
    }
    p.slave_shell_start.assign(1, 0);
    p.slave_faces = s.segments;
    p.slave_face_start.assign(1, 0);
    // In index order, however the side names them: a node set and the part it covers then give
    // the same pass, summed in the same order.
    std::vector<Index> nodes = only;
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    if (nodes.empty()) {
      for (std::size_t i = 0; i < n; ++i)
        if (count[i] > 0.0)
          nodes.push_back(static_cast<Index>(i));
    }
    for (Index v : nodes) {
      const auto i = static_cast<std::size_t>(v);
      if (!(area[i] > 0.0)) {
        error(c.card1, c.keyword, "SSID",
              "slave node " + std::to_string(m.node_id[i]) +
                  " belongs to no shell element or solid face: it has no contact area");
        return false;
      }
      const double t = count[i] > 0.0 ? thick[i] / count[i] : 0.0;
      const bool offset = !rigid[i] || rigid_offset;
      p.slave_nodes.push_back(v);
      p.slave_area.push_back(area[i]);
      p.slave_stiffness.push_back(factor * stiff[i]);
      p.slave_offset.push_back(offset ? 0.5 * (sst > 0.0 ? sst : sfst * t) : 0.0);
      // Shell nodes only: the offset then follows the mean thickness of those shells.
      const bool follows = offset && sst <= 0.0 && !shells[i].empty() &&
                           shells[i].size() == static_cast<std::size_t>(count[i]);
      p.slave_offset_factor.push_back(follows ? 0.5 * sfst : 0.0);
      if (follows)
        p.slave_shells.insert(p.slave_shells.end(), shells[i].begin(), shells[i].end());
      p.slave_shell_start.push_back(p.slave_shells.size());
      p.slave_face_index.insert(p.slave_face_index.end(), faces[i].begin(), faces[i].end());
      p.slave_face_start.push_back(p.slave_face_index.size());
    }
    return true;
  }

  void fill_master(const Surface& s, double factor, double mst, double sfmt, bool rigid_offset,
                   core::ContactPass& p) {
    p.segments = s.segments;
    for (std::size_t k = 0; k < s.size(); ++k) {
      const bool offset = !s.rigid[k] || rigid_offset;
      p.segment_offset.push_back(offset ? 0.5 * (mst > 0.0 ? mst : sfmt * s.thickness[k]) : 0.0);
      p.segment_stiffness.push_back(factor * s.stiffness[k]);
      const bool follows = offset && mst <= 0.0 && s.shell[k] >= 0;
      p.segment_shell.push_back(follows ? s.shell[k] : -1);
      p.segment_one_sided.push_back(s.shell[k] < 0 ? 1 : 0);  // a solid's exterior face
      p.segment_depth.push_back(s.depth[k]);
      p.segment_offset_factor.push_back(follows ? 0.5 * sfmt : 0.0);
    }
  }

  // *CONTACT_AUTOMATIC_SINGLE_SURFACE: one pass, every node of the surface against every segment
  // of it but those that touch it through the mesh: the segments around the node and those that
  // share a node with them (a node of a bent sheet would otherwise see its neighbours' faces
  // within the thickness). Rigid nodes skip rigid segments.
  std::optional<core::ContactPass> single_surface_pass(const model::ContactDesc& c, double slsfac,
                                                       bool rigid_offset, bool thkchg) {
    std::optional<Surface> surface;
    std::vector<Index> none;
    if (c.ssid == 0) {
      surface = surface_of_parts(std::vector<char>(m.parts.size(), 1));
      if (surface->size() == 0) {
        error(c.card1, c.keyword, "SSID", "the model has no shell element or solid face");
        return std::nullopt;
      }
    } else {
      surface = side_surface(c, c.sstyp, c.ssid, "SSID", none);
    }
    if (!surface)
      return std::nullopt;
    core::ContactPass p;
    p.offsets_follow_thickness = thkchg;
    if (!fill_slaves(c, *surface, {}, slsfac * c.sfs, c.sst, c.sfst, rigid_offset, p))
      return std::nullopt;
    fill_master(*surface, slsfac * c.sfm, c.mst, c.sfmt, rigid_offset, p);
    // Node -> segments (CSR), then per slave node its segments' nodes' segments.
    const std::size_t nseg = surface->size();
    std::vector<std::size_t> start(m.node_count() + 1, 0);
    const auto corners = [&](std::size_t s) {
      return surface->segments[4 * s + 2] == surface->segments[4 * s + 3] ? 3 : 4;
    };
    for (std::size_t s = 0; s < nseg; ++s)
      for (int j = 0; j < corners(s); ++j)
        ++start[static_cast<std::size_t>(surface->segments[4 * s + static_cast<std::size_t>(j)]) +
                1];
    for (std::size_t i = 0; i < m.node_count(); ++i)
      start[i + 1] += start[i];
    std::vector<Index> around(start.back());
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t s = 0; s < nseg; ++s)
      for (int j = 0; j < corners(s); ++j)
        around[fill[static_cast<std::size_t>(
            surface->segments[4 * s + static_cast<std::size_t>(j)])]++] = static_cast<Index>(s);
    // A tie holds its slave node on its segment: the two touch as if through the mesh (a
    // flange tied onto a flange lies within their thicknesses, and would be pushed apart).
    std::vector<std::vector<Index>> tied_to(m.node_count());
    for (const core::TiedInterface& t : m.tied) {
      for (std::size_t k = 0; k < t.slaves.size(); ++k) {
        for (Index q : t.segment[k]) {
          tied_to[static_cast<std::size_t>(t.slaves[k])].push_back(q);
          tied_to[static_cast<std::size_t>(q)].push_back(t.slaves[k]);
        }
      }
    }
    p.exclude_start.assign(1, 0);
    std::vector<Index> near;
    for (Index v : p.slave_nodes) {
      near.clear();
      const auto vi = static_cast<std::size_t>(v);
      const auto segments_near = [&](std::size_t x) {
        for (std::size_t a = start[x]; a < start[x + 1]; ++a) {
          const auto s = static_cast<std::size_t>(around[a]);
          for (int j = 0; j < corners(s); ++j) {
            const auto u =
                static_cast<std::size_t>(surface->segments[4 * s + static_cast<std::size_t>(j)]);
            near.insert(near.end(), around.begin() + static_cast<long>(start[u]),
                        around.begin() + static_cast<long>(start[u + 1]));
          }
        }
      };
      segments_near(vi);
      for (Index u : tied_to[vi])
        segments_near(static_cast<std::size_t>(u));
      std::sort(near.begin(), near.end());
      near.erase(std::unique(near.begin(), near.end()), near.end());
      p.exclude.insert(p.exclude.end(), near.begin(), near.end());
      p.exclude_start.push_back(p.exclude.size());
    }
    p.skip_rigid_pairs = true;
    return p;
  }

  law::Parameters penalty_law(const model::ContactDesc& c) {
    double fs = c.fs, fd = c.fd, dc = c.dc, vc = c.vc;
    if (fs == 0.0 && d.control_contact && d.control_contact->sfric > 0.0) {
      fs = d.control_contact->sfric;
      fd = d.control_contact->dfric;
      dc = d.control_contact->edc;
      vc = d.control_contact->vfc;
    }
    law::Parameters p;
    p.cn = 1.0;
    p.sigma_max = {1.0, 1.0, -1};
    p.eta = 1.0;
    p.beta0 = 0.0;  // no adhesion, ever: beta stays 0 (no healing either)
    p.mu = {fs * c.fsf, fs * c.fsf, -1};
    p.decay_dc = dc;
    p.dynamic_ratio = fs > 0.0 ? fd / fs : 1.0;
    p.vdc = c.vdc;
    p.friction_limit = vc * c.vsf;
    return p;
  }

  // A tied contact: each slave node within reach of a master segment follows it
  // (find_ties); nodes out of reach stay free, counted in a warning.
  void build_tie(const model::ContactDesc& c) {
    std::vector<Index> only, unused;
    const std::optional<Surface> slave = side_surface(c, c.sstyp, c.ssid, "SSID", only);
    if (!slave)
      return;
    const std::optional<Surface> master = side_surface(c, c.mstyp, c.msid, "MSID", unused);
    if (!master)
      return;
    // The slave nodes (a node set's, else the side's segments' nodes) with the mean thickness
    // of the slave side's shells around each.
    const std::size_t n = m.node_count();
    std::vector<double> thick(n, 0.0), count(n, 0.0);
    for (std::size_t k = 0; k < slave->size(); ++k) {
      const Index* q = &slave->segments[4 * k];
      for (int j = 0; j < (q[2] == q[3] ? 3 : 4); ++j) {
        thick[static_cast<std::size_t>(q[j])] += slave->thickness[k];
        count[static_cast<std::size_t>(q[j])] += 1.0;
      }
    }
    std::vector<Index> nodes = only;
    if (nodes.empty())
      for (std::size_t i = 0; i < n; ++i)
        if (count[i] > 0.0)
          nodes.push_back(static_cast<Index>(i));
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    std::vector<double> slave_t(nodes.size());
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const auto i = static_cast<std::size_t>(nodes[k]);
      slave_t[k] = count[i] > 0.0 ? thick[i] / count[i] : 0.0;
    }
    const std::vector<TieFound> found =
        find_ties(m, nodes, slave_t, master->segments, master->thickness, c.sst, c.mst);
    core::TiedInterface t;
    t.id = c.id;
    t.keyword = c.keyword;
    t.rotations = c.kind == model::ContactKind::tied_shell_edge_to_surface;
    std::size_t free = 0, not_shell = 0;
    core::GlobalId first_free = 0;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const TieFound& f = found[k];
      if (f.segment < 0) {
        if (free++ == 0)
          first_free = m.node_id[static_cast<std::size_t>(nodes[k])];
        continue;
      }
      const auto sg = static_cast<std::size_t>(f.segment);
      if (t.rotations && master->shell[sg] < 0) {
        ++not_shell;
        continue;
      }
      const Index* q = &master->segments[4 * sg];
      t.slaves.push_back(nodes[k]);
      t.segment.push_back({q[0], q[1], q[2], q[3]});
      t.weight.push_back(f.weight);
    }
    const std::string name = c.id != 0 ? fmt::format("tied contact {}", c.id) : "a tied contact";
    if (not_shell > 0) {
      error(c.card1, c.keyword, "MSID",
            fmt::format("{}: {} slave nodes lie on master faces of solids, which have no "
                        "rotations to tie a shell edge's to; name shell parts or segments",
                        name, not_shell));
    }
    if (free > 0) {
      warnings.push_back(
          {c.card1, c.keyword, "SSID",
           fmt::format("{}: {} of its {} slave nodes are out of reach of every master segment "
                       "(the first is node {}; reach 0.6 times the two sides' thicknesses, SST "
                       "and MST where given): they are not tied",
                       name, free, nodes.size(), first_free)});
    }
    m.tied.push_back(std::move(t));
  }

  void build() {
    index();
    const double slsfac =
        d.control_contact && d.control_contact->slsfac > 0.0 ? d.control_contact->slsfac : 0.1;
    const int shlthk = d.control_contact ? d.control_contact->shlthk : 0;
    // 0: the deck leaves PENOPT blank (a plain contact then takes LS-DYNA's 1, a cohesive
    // interface its own rule: core::ContactInterface::penopt).
    const int penopt_given = d.control_contact ? d.control_contact->penopt : 0;
    const int nsbcs = d.control_contact ? d.control_contact->nsbcs : 0;
    const bool thkchg = d.control_contact && d.control_contact->thkchg == 1;
    // The ties first: a single surface leaves the pairs they hold together out of its search.
    for (const model::ContactDesc& c : d.contacts)
      if (model::is_tied(c.kind))
        build_tie(c);
    std::unordered_map<int, const model::ContactDesc*> first_with_id;
    for (const model::ContactDesc& c : d.contacts) {
      if (c.id != 0) {
        const auto [it, fresh] = first_with_id.emplace(c.id, &c);
        if (!fresh) {
          warnings.push_back(
              {c.where, c.keyword, "CID",
               fmt::format("contact {} is also the id of the contact at {}:{}: both act, and "
                           "rcforc.csv and sleout.csv list both under that id (in deck order)",
                           c.id, it->second->where.file, it->second->where.line)});
        }
      }
      if (model::is_tied(c.kind))
        continue;
      core::ContactInterface ci;
      ci.id = c.id;
      ci.keyword = c.keyword;
      ci.kind = c.kind == model::ContactKind::one_way_surface_to_surface
                    ? core::ContactKind::one_way
                : c.kind == model::ContactKind::surface_to_surface ? core::ContactKind::two_way
                : c.kind == model::ContactKind::forming_one_way_surface_to_surface
                    ? core::ContactKind::forming
                : c.kind == model::ContactKind::automatic_one_way_surface_to_surface
                    ? core::ContactKind::automatic_one_way
                : c.kind == model::ContactKind::automatic_single_surface
                    ? core::ContactKind::single_surface
                    : core::ContactKind::automatic;
      if (c.tiebreak) {
        ci.tiebreak.option = c.tiebreak_option;
        ci.tiebreak.nfls = c.nfls;
        ci.tiebreak.sfls = c.sfls;
        ci.tiebreak.sfls_is_friction_limit = c.tiebreak_option == 4 && c.param == 1.0;
      }
      ci.penalty = c.soft == 1 ? core::PenaltyKind::mass : core::PenaltyKind::material;
      ci.sofscl = c.sofscl;
      ci.penopt = penopt_given > 0 ? penopt_given : 1;
      ci.maxpar = c.maxpar;
      ci.search_interval = c.bsort > 0 ? c.bsort : nsbcs;
      ci.ignore = c.ignore > 0 ? c.ignore : (d.control_contact ? d.control_contact->ignore : 0);
      ci.birth = c.birth;
      ci.death = c.death;
      if (c.thermal) {
        core::ContactHeat& h = ci.heat;
        h.enabled = true;
        h.k = c.k;
        h.frad = c.frad;
        h.h0 = c.h0;
        h.lmin = c.lmin;
        h.lmax = c.lmax;
        h.ftosa = c.ftosa;
        h.one_way = c.algo == 1;
        h.boundaries_off_in_contact = c.bc_flg == 1;
        h.friction_heat = d.control_contact && d.control_contact->frceng == 1;
        if (c.h0 < 0.0) {
          const int id = static_cast<int>(-c.h0);
          for (std::size_t i = 0; i < d.curves.size(); ++i)
            if (d.curves[i].id == id)
              h.h0_curve = static_cast<Index>(i);
          if (h.h0_curve < 0)
            errors.push_back({c.card1, c.keyword, "H0",
                              "H0 = " + std::to_string(c.h0) + ": curve " + std::to_string(id) +
                                  " (conductance against pressure) does not exist"});
        }
      }
      const model::UserInterfaceFrictionDesc* uif = nullptr;
      for (const auto& u : d.user_interface_frictions)
        if (c.id != 0 && u.contact_id == c.id)
          uif = &u;
      if (uif != nullptr && c.tiebreak) {
        error(uif->where, "*USER_INTERFACE_FRICTION", "NOSID",
              "contact " + std::to_string(c.id) + " (" + c.keyword +
                  ") is a tiebreak contact: its interface law is the tiebreak; name a contact "
                  "without _TIEBREAK to give it the cohesive law");
        continue;
      }
      if (uif != nullptr) {
        CohesiveLawBuild law = build_cohesive_law(d, *uif);
        if (!law.parameters) {
          for (auto& e : law.errors)
            errors.push_back(std::move(e));
          continue;
        }
        ci.cohesive = true;
        ci.law = *law.parameters;
        // A layer interface: a soft layer (a polymer core) must not make the whole interface
        // soft, or the press sinks the layers into each other.
        if (penopt_given == 0)
          ci.penopt = 0;
        if (c.fs != 0.0 || c.fd != 0.0 || c.dc != 0.0 || c.vc != 0.0 || c.vdc != 0.0) {
          warnings.push_back({c.card1, c.keyword, "FS",
                              "contact " + std::to_string(c.id) +
                                  " has a cohesive law (*USER_INTERFACE_FRICTION): its friction "
                                  "and damping come from the law's constants; FS, FD, DC, VC "
                                  "and VDC of the contact are not used"});
        }
      } else {
        ci.law = penalty_law(c);
      }
      // Rigid shells (tools) are offset only in automatic contacts or with SHLTHK = 2: a tool
      // mesh is the tool's surface.
      const bool rigid_offset = ci.kind == core::ContactKind::automatic ||
                                ci.kind == core::ContactKind::automatic_one_way ||
                                ci.kind == core::ContactKind::single_surface || shlthk == 2;
      if (ci.kind == core::ContactKind::single_surface) {
        if (uif != nullptr) {
          error(uif->where, "*USER_INTERFACE_FRICTION", "NOSID",
                "contact " + std::to_string(c.id) +
                    " is a single-surface contact: the cohesive law bonds one layer to another "
                    "through a ONE_WAY or FORMING_ONE_WAY contact");
          continue;
        }
        if (auto p = single_surface_pass(c, slsfac, rigid_offset, thkchg)) {
          ci.passes.push_back(std::move(*p));
          m.contacts.push_back(std::move(ci));
        }
        continue;
      }
      std::vector<Index> slave_only, master_only;
      auto slave = side_surface(c, c.sstyp, c.ssid, "SSID", slave_only);
      auto master = side_surface(c, c.mstyp, c.msid, "MSID", master_only);
      if (!slave || !master)
        continue;
      const bool two_way =
          ci.kind == core::ContactKind::two_way || ci.kind == core::ContactKind::automatic;
      if (two_way && ci.cohesive) {
        // Both passes would bond: every pair of layers would carry its adhesion twice.
        error(uif->where, "*USER_INTERFACE_FRICTION", "NOSID",
              "contact " + std::to_string(c.id) + " (" + c.keyword +
                  ") is two-way: the cohesive law acts once per slave node, so it needs a "
                  "ONE_WAY or FORMING_ONE_WAY contact (slave: the layer whose nodes carry the "
                  "law)");
        continue;
      }
      if (two_way && c.sstyp == model::ContactSideType::node_set) {
        error(c.card1, c.keyword, "SSTYP",
              "a two-way contact needs segments on its slave side: SSTYP 4 (node set) gives "
              "none; use a part, part set or segment set, or a ONE_WAY contact");
        continue;
      }
      // The layer surfaces of a cohesive interface move with the layers' thickness: the
      // law's gap is between them (else plastic thinning would open the interface).
      const bool follow = thkchg || ci.cohesive;
      core::ContactPass a;
      a.offsets_follow_thickness = follow;
      if (!fill_slaves(c, *slave, slave_only, slsfac * c.sfs, c.sst, c.sfst, rigid_offset, a))
        continue;
      fill_master(*master, slsfac * c.sfm, c.mst, c.sfmt, rigid_offset, a);
      if (ci.penopt == 1 && ci.penalty == core::PenaltyKind::material) {
        // PENOPT 1 takes the smaller side's penalty: a soft layer (a polymer core against
        // metal skins) makes the whole interface soft, and forming pressures then sink the
        // layers into each other by millimetres.
        const SidePenalty k = side_penalty(m, a);
        const double lo = std::min(k.slave, k.master), hi = std::max(k.slave, k.master);
        if (lo > 0.0 && hi > 10.0 * lo) {
          const bool master_soft = k.master < k.slave;
          warnings.push_back(
              {c.card1, c.keyword, master_soft ? "SFM" : "SFS",
               fmt::format("contact {}: PENOPT 1 takes the smaller penalty, the {} side's {:.3g} "
                           "per area, 1/{:.0f} of the {} side's; under a pressure p the layers "
                           "sink p / {:.3g} into each other. *CONTROL_CONTACT PENOPT 3 (or 2), "
                           "{} or SOFT = 1 make it stiffer (docs/contact.md)",
                           c.id, master_soft ? "master" : "slave", lo, hi / lo,
                           master_soft ? "slave" : "master", lo, master_soft ? "SFM" : "SFS")});
        }
      }
      ci.passes.push_back(std::move(a));
      const auto any_rigid = [](const Surface& s) {
        return std::any_of(s.rigid.begin(), s.rigid.end(), [](char r) { return r != 0; });
      };
      if (ci.cohesive && c.sstyp != model::ContactSideType::node_set && !slave->segments.empty() &&
          !any_rigid(*slave) && !any_rigid(*master)) {
        // The guard: the master's nodes kept out of the slave's surface (a one-way contact
        // lets a coarser master's nodes through a finer slave between its nodes). Between two
        // deformable layers only: a tool's mesh is its surface, as in any forming contact.
        core::ContactPass g;
        g.offsets_follow_thickness = follow;
        g.guard = true;
        if (!fill_slaves(c, *master, master_only, slsfac * c.sfm, c.mst, c.sfmt, rigid_offset, g))
          continue;
        fill_master(*slave, slsfac * c.sfs, c.sst, c.sfst, rigid_offset, g);
        g.slave_side_sign = -1;
        ci.passes.push_back(std::move(g));
      }
      if (two_way) {
        core::ContactPass b;
        b.offsets_follow_thickness = follow;
        if (!fill_slaves(c, *master, {}, slsfac * c.sfm, c.mst, c.sfmt, rigid_offset, b))
          continue;
        fill_master(*slave, slsfac * c.sfs, c.sst, c.sfst, rigid_offset, b);
        b.slave_side_sign = -1;
        ci.passes.push_back(std::move(b));
      }
      m.contacts.push_back(std::move(ci));
    }
  }
};

}  // namespace

// IGNORE = 0, LS-DYNA's default: the slave nodes that penetrate at t = 0 are moved out along
// the contact normal in the model definition (then the contacts are built again on the moved
// nodes); a few rounds, since a moved node may press into another surface. A warning per
// contact says how many moved and how far.
void remove_initial_penetrations(const model::ModelDesc& desc, core::Model& model,
                                 Diagnostics& warnings) {
  double size = 0.0;
  for (std::size_t i = 0; i < model.node_count(); ++i)
    size = std::max({size, std::abs(model.x0[i]), std::abs(model.y0[i]), std::abs(model.z0[i])});
  const double negligible = 1e-9 * size;
  struct Moved {
    std::size_t count = 0;
    double deepest = 0.0;
    core::GlobalId node = 0;
  };
  std::vector<Moved> moved(model.contacts.size());
  for (int round = 0; round < 4; ++round) {
    bool any = false;
    for (const contact::InitialPenetration& p : contact::initial_penetrations(model)) {
      if (p.depth <= negligible)
        continue;
      any = true;
      const auto i = static_cast<std::size_t>(p.node);
      model.x0[i] += p.move[0];
      model.y0[i] += p.move[1];
      model.z0[i] += p.move[2];
      Moved& mv = moved[p.interface];
      ++mv.count;
      if (p.depth > mv.deepest) {
        mv.deepest = p.depth;
        mv.node = model.node_id[i];
      }
    }
    if (!any)
      break;
    // The contacts' areas, stiffnesses and offsets from the moved nodes.
    model.contacts.clear();
    model.tied.clear();
    Diagnostics again_errors, again_warnings;
    ContactBuilder again{desc, model, again_errors, again_warnings, Geometry{model}, {}, {},
                         {},   {}};
    again.build();
  }
  // What the rounds could not clear is tracked at the start (core::ContactInterface).
  for (core::ContactInterface& c : model.contacts)
    c.leftovers_tracked = c.ignore == 0;
  // The interfaces in the model's order: the deck's contacts less the tied ones.
  std::vector<const model::ContactDesc*> interfaces;
  for (const model::ContactDesc& cd : desc.contacts)
    if (!model::is_tied(cd.kind))
      interfaces.push_back(&cd);
  for (std::size_t c = 0; c < moved.size() && c < interfaces.size(); ++c) {
    if (moved[c].count == 0)
      continue;
    const model::ContactDesc& cd = *interfaces[c];
    warnings.push_back(
        {cd.where, cd.keyword, "IGNORE",
         fmt::format("contact {}: {} slave node moves to clear penetrations at t = 0 (deepest "
                     "{:.4g} at node {}), as LS-DYNA does with IGNORE = 0; IGNORE = 1 tracks them "
                     "instead (docs/contact.md)",
                     cd.id, moved[c].count, moved[c].deepest, moved[c].node)});
  }
}

void build_contacts(const model::ModelDesc& desc, core::Model& model, Diagnostics& errors,
                    Diagnostics& warnings) {
  if (desc.contacts.empty())
    return;
  ContactBuilder b{desc, model, errors, warnings, Geometry{model}, {}, {}, {}, {}};
  b.build();
  if (errors.empty())
    remove_initial_penetrations(desc, model, warnings);
  drop_conflicting_slaves(desc, model, warnings);
}

void build_temperatures(const model::ModelDesc& desc, core::Model& model, Diagnostics& errors) {
  if (desc.initial_temperatures.empty() && desc.temperature_histories.empty())
    return;
  std::unordered_map<std::int64_t, Index> node;
  for (std::size_t i = 0; i < model.node_id.size(); ++i)
    node.emplace(model.node_id[i], static_cast<Index>(i));
  std::unordered_map<int, Index> curve;
  for (std::size_t i = 0; i < desc.curves.size(); ++i)  // model.curves is in deck order
    curve.emplace(desc.curves[i].id, static_cast<Index>(i));
  const auto targets = [&](model::NodeTarget t, int id, const model::SourceLocation& where,
                           const char* kw) {
    std::vector<Index> v;
    const auto add = [&](int n) {
      const auto it = node.find(n);
      if (it == node.end())
        errors.push_back({where, kw, "NID", "node " + std::to_string(n) + " does not exist"});
      else
        v.push_back(it->second);
    };
    if (t == model::NodeTarget::kNode) {
      add(id);
      return v;
    }
    if (id == 0) {  // *INITIAL_TEMPERATURE_SET NSID 0: every node
      for (std::size_t i = 0; i < model.node_count(); ++i)
        v.push_back(static_cast<Index>(i));
      return v;
    }
    for (const auto& s : desc.node_sets)
      if (s.id == id)
        for (int n : s.ids)
          add(n);
    return v;
  };
  model.temperature0.assign(model.node_count(), 0.0);
  for (const model::InitialTemperatureDesc& t : desc.initial_temperatures) {
    for (Index i : targets(t.target, t.target_id, t.where, "*INITIAL_TEMPERATURE"))
      model.temperature0[static_cast<std::size_t>(i)] = t.temperature;
  }
  for (const model::BoundaryTemperatureDesc& b : desc.temperature_histories) {
    Index c = -1;
    if (b.curve_id != 0) {
      const auto it = curve.find(b.curve_id);
      if (it == curve.end()) {
        errors.push_back({b.where, "*BOUNDARY_TEMPERATURE", "LCID",
                          "curve " + std::to_string(b.curve_id) + " does not exist"});
        continue;
      }
      c = it->second;
    }
    for (Index i : targets(b.target, b.target_id, b.where, "*BOUNDARY_TEMPERATURE"))
      model.temperature_histories.push_back({i, c, b.cmult, b.birth, b.death, b.loc});
  }
}

}  // namespace plyform::setup

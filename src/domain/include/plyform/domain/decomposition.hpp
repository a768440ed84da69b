#pragma once
// The split of a model into domains, one per MPI rank (docs/parallel.md). METIS partitions the
// graph of the deformable elements (edges: elements that share nodes), each element weighted by
// its cost (formulation, NIP, law) plus the contact work of the slave nodes it carries. Every
// contact between two deformable sides adds an edge from each slave node's element to the element
// of the master segment it faces at t = 0, heavier than an edge within a layer, so that the layers
// of a sandwich stacked over one another fall into the same domain (a split in plan view) and the
// interlayer contacts stay local. Rigid bodies are cheap and live on every rank.
//
// What each domain then holds: its elements; its nodes (a node is owned by the lowest domain among
// those whose elements touch it, and shared with the others); the contact slave nodes it owns; and
// the other domains' master segments its slave nodes can reach (ghosts, refreshed at every
// re-search once the exchange runs).

#include <cstddef>
#include <string>
#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::domain {

/// A deformable element of the model: its block (in Model::shell_blocks when `shell`, else in
/// Model::solid_blocks) and its index in the block.
struct ElementRef {
  bool shell = true;
  core::Index block = 0;
  core::Index element = 0;
};

/// What one domain holds.
struct DomainSummary {
  std::size_t elements = 0;        ///< deformable elements
  std::size_t nodes = 0;           ///< nodes its elements touch (owned and shared)
  std::size_t owned_nodes = 0;     ///< of those, the nodes it owns
  std::size_t shared_nodes = 0;    ///< of those, the nodes another domain's elements touch too
  std::size_t neighbours = 0;      ///< domains it shares nodes with (its messages per exchange)
  std::size_t slave_nodes = 0;     ///< contact slave nodes it owns, summed over the passes
  std::size_t ghost_segments = 0;  ///< other domains' master segments it needs, over the passes
  double cost = 0.0;               ///< its elements' and slave nodes' cost (BT element units)
};

/// The slave nodes and master segments of one contact pass, by domain.
struct PassHalo {
  std::vector<int> slave_owner;    ///< per slave node: its owner, -1 for a rigid body's node
  std::vector<int> segment_owner;  ///< per master segment: its element's domain, -1 if rigid
  /// Per domain d, the segments of other domains within reach of a slave node d owns:
  /// ghost[ghost_start[d] .. ghost_start[d + 1]), increasing.
  std::vector<std::size_t> ghost_start;
  std::vector<core::Index> ghost;
};

struct Decomposition {
  int domains = 1;
  std::vector<ElementRef> elements;  ///< the deformable elements: shell blocks', then solids'
  std::vector<int> element_domain;   ///< per element of `elements`
  std::vector<double> element_cost;  ///< per element of `elements`, with its slave nodes' share
  /// Per node: its owner, or -1 for a node no deformable element touches (a rigid body's node,
  /// on every rank, or an unused one).
  std::vector<int> node_owner;
  /// Per node, the domains whose elements touch it, increasing: node_domains[node_domain_start[n]
  /// .. node_domain_start[n + 1]).
  std::vector<std::size_t> node_domain_start;
  std::vector<int> node_domains;
  std::vector<std::vector<PassHalo>> contact;  ///< per contact interface, per pass
  std::vector<DomainSummary> summary;          ///< per domain
  double imbalance = 1.0;                      ///< the largest domain's cost over the mean
  /// The edges that join a slave node's element to its master segment's element across a contact
  /// between deformable sides, and how many of them the split cuts.
  std::size_t interface_edges = 0;
  std::size_t interface_edges_cut = 0;
};

/// Per-element cost in units of a Belytschko-Tsay shell with NIP 5 and J2 (about 150 ns a cycle
/// on this project's machine), from the measured figures in docs/parallel.md.
[[nodiscard]] double shell_cost(const core::Model& model, const core::ShellBlock& block);
[[nodiscard]] double solid_cost(const core::Model& model, const core::SolidBlock& block);
/// The cost of one slave node in one contact pass, in the same units.
inline constexpr double kSlaveNodeCost = 1.3;

/// How far from a master segment's box a slave node is within reach at t = 0: the two sides'
/// offsets plus the segment's longest edge (the room the contact's search leaves for the motion
/// between two searches).
[[nodiscard]] std::vector<double> segment_reach(const core::Model& model,
                                                const core::ContactPass& pass);

struct DecomposeResult {
  Decomposition decomposition;
  std::string error;  ///< empty on success
};

/// Splits `model` into `domains` domains (1 or more; no more than its deformable elements).
/// Deterministic: the same model and count give the same split.
[[nodiscard]] DecomposeResult decompose(const core::Model& model, int domains);

}  // namespace plyform::domain

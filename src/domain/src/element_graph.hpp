#pragma once
// The graph METIS splits (decomposition.hpp): the deformable elements as vertices weighted by
// cost, edges between elements that share nodes (weight: the nodes shared) and, across each
// contact between deformable sides, from a slave node's element to the element of the master
// segment it faces at t = 0 (weight kInterfaceEdgeWeight).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "plyform/domain/decomposition.hpp"

namespace plyform::domain::detail {

/// An edge across an interface outweighs an edge within a layer, so that a split through the
/// layers' stack (cutting every node of a region's interface) costs far more than a split in plan
/// view (cutting each layer along a line).
inline constexpr std::int32_t kInterfaceEdgeWeight = 4;

/// The master segments within reach of each slave node of one pass at t = 0 (CSR).
struct PassCandidates {
  std::vector<std::size_t> start;
  std::vector<core::Index> segments;
};

struct ElementGraph {
  std::vector<ElementRef> elements;
  std::vector<double> cost;  ///< per element: its own and its slave nodes' share
  /// Per node, the deformable elements that touch it (CSR).
  std::vector<std::size_t> node_start;
  std::vector<core::Index> node_elements;
  /// Per contact interface and pass: each segment's deformable element (-1: rigid) and the
  /// candidates of its slave nodes.
  std::vector<std::vector<std::vector<core::Index>>> segment_element;
  std::vector<std::vector<PassCandidates>> candidates;
  /// The interface edges (element pairs), each once.
  std::vector<std::array<core::Index, 2>> interface_edges;
  // The graph in METIS's CSR form.
  std::vector<std::int32_t> xadj, adjncy, adjwgt;
};

[[nodiscard]] ElementGraph element_graph(const core::Model& model);

/// The node indices of element `e`: 4 for a shell, 8 for a solid.
[[nodiscard]] std::span<const core::Index> element_nodes(const core::Model& model,
                                                         const ElementRef& e);

}  // namespace plyform::domain::detail

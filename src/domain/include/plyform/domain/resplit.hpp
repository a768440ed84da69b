#pragma once
// A running model split again with a target share of the cost per domain: the re-balancing of
// a run over several ranks (docs/parallel.md). The element graph is built once; each split is
// METIS's k-way over it with the shares as its target part weights, the same on every rank.

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "plyform/core/model.hpp"

namespace plyform::domain {

namespace detail {
struct ElementGraph;
}

/// A split's owners and costs.
struct OwnerSplit {
  /// Per node: the lowest domain whose elements touch it (its owner, decomposition.hpp), -1
  /// where no deformable element does.
  std::vector<int> node_owner;
  /// Per deformable element, in Decomposition::elements's order: its domain.
  std::vector<int> element_domain;
  std::vector<double> cost;  ///< per domain: its elements' and slave nodes' cost
  std::string error;         ///< empty on success
};

class Resplitter {
 public:
  explicit Resplitter(const core::Model& model);
  ~Resplitter();
  Resplitter(const Resplitter&) = delete;
  Resplitter& operator=(const Resplitter&) = delete;

  /// Splits into shares.size() domains, domain d taking about shares[d] of the cost (the shares
  /// are normalised; each must be positive). Deterministic.
  [[nodiscard]] OwnerSplit split(std::span<const double> shares) const;

 private:
  const core::Model* model_;
  std::unique_ptr<detail::ElementGraph> graph_;
};

}  // namespace plyform::domain

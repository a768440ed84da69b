#include "plyform/domain/resplit.hpp"

#include <algorithm>

#include "element_graph.hpp"
#include "metis_split.hpp"

namespace plyform::domain {

Resplitter::Resplitter(const core::Model& model)
    : model_(&model),
      graph_(std::make_unique<detail::ElementGraph>(detail::element_graph(model))) {}

Resplitter::~Resplitter() = default;

OwnerSplit Resplitter::split(std::span<const double> shares) const {
  OwnerSplit r;
  const auto domains = static_cast<int>(shares.size());
  detail::ElementGraph& g = *graph_;
  if (domains < 1 || g.elements.size() < shares.size()) {
    r.error = std::to_string(domains) + " domains for " + std::to_string(g.elements.size()) +
              " deformable elements: each domain needs at least one";
    return r;
  }
  std::vector<int>& part = r.element_domain;
  r.error = detail::metis_split(g, domains, shares, part);
  if (!r.error.empty())
    return r;
  r.cost.assign(shares.size(), 0.0);
  for (std::size_t e = 0; e < part.size(); ++e)
    r.cost[static_cast<std::size_t>(part[e])] += g.cost[e];
  const std::size_t nn = model_->node_count();
  r.node_owner.assign(nn, -1);
  for (std::size_t n = 0; n < nn; ++n) {
    for (std::size_t k = g.node_start[n]; k < g.node_start[n + 1]; ++k) {
      const int d = part[static_cast<std::size_t>(g.node_elements[k])];
      r.node_owner[n] = r.node_owner[n] < 0 ? d : std::min(r.node_owner[n], d);
    }
  }
  return r;
}

}  // namespace plyform::domain

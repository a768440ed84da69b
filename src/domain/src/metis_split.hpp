#pragma once
// METIS's k-way split of the element graph (decompose.cpp, resplit.cpp).

#include <span>
#include <string>
#include <vector>

#include "element_graph.hpp"

namespace plyform::domain::detail {

/// Splits `g` into `domains` parts into `part` (per element of g.elements). `shares`: each
/// part's target share of the cost (summing to 1; empty: equal shares). Deterministic (a fixed
/// seed): the same graph, count and shares give the same split. Returns an error, or empty.
std::string metis_split(ElementGraph& g, int domains, std::span<const double> shares,
                        std::vector<int>& part);

}  // namespace plyform::domain::detail

#include "metis_split.hpp"

#include <metis.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace plyform::domain::detail {

static_assert(sizeof(idx_t) == sizeof(std::int32_t), "plyform passes METIS 32-bit indices");

std::string metis_split(ElementGraph& g, int domains, std::span<const double> shares,
                        std::vector<int>& part) {
  const std::size_t ne = g.elements.size();
  part.assign(ne, 0);
  if (domains == 1)
    return {};
  std::vector<idx_t> vwgt(ne);
  for (std::size_t e = 0; e < ne; ++e)
    vwgt[e] = std::max<idx_t>(1, static_cast<idx_t>(std::lround(100.0 * g.cost[e])));
  idx_t nvtxs = static_cast<idx_t>(ne), ncon = 1, nparts = domains, objval = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;
  options[METIS_OPTION_NUMBERING] = 0;
  std::vector<real_t> tpwgts;
  if (!shares.empty()) {
    if (shares.size() != static_cast<std::size_t>(domains))
      return "one target share per domain is needed";
    double sum = 0.0;
    for (const double s : shares) {
      if (!(s > 0.0) || !std::isfinite(s))
        return "every domain's target share must be positive";
      sum += s;
    }
    // METIS asks for fractions summing to 1 (in its own float type).
    for (const double s : shares)
      tpwgts.push_back(static_cast<real_t>(s / sum));
  }
  std::vector<idx_t> where(ne, 0);
  const int status = METIS_PartGraphKway(
      &nvtxs, &ncon, g.xadj.data(), g.adjncy.data(), vwgt.data(), nullptr, g.adjwgt.data(), &nparts,
      tpwgts.empty() ? nullptr : tpwgts.data(), nullptr, options, &objval, where.data());
  if (status != METIS_OK)
    return "METIS could not split the element graph (status " + std::to_string(status) + ")";
  for (std::size_t e = 0; e < ne; ++e)
    part[e] = static_cast<int>(where[e]);
  return {};
}

}  // namespace plyform::domain::detail

#include "plyform/model/define_table_desc.hpp"

#include "plyform/model/curve_desc.hpp"

namespace plyform::model {

std::vector<double> effective_values(const DefineTableDesc& table) {
  const double sfa = effective_scale_factor(table.sfa);
  std::vector<double> v;
  v.reserve(table.values.size());
  for (double x : table.values)
    v.push_back(sfa * (x + table.offa));
  return v;
}

}  // namespace plyform::model

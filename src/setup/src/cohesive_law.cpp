#include "plyform/setup/cohesive_law.hpp"

#include <string>

#include "plyform/law/user_constants.hpp"

namespace plyform::setup {

namespace {
constexpr const char* kKeyword = "*USER_INTERFACE_FRICTION";
}

CohesiveLawBuild build_cohesive_law(const model::ModelDesc& model,
                                    const model::UserInterfaceFrictionDesc& uif) {
  std::vector<law::Curve> curves;
  curves.reserve(model.curves.size());
  for (const model::CurveDesc& c : model.curves) {
    std::vector<double> x, y;
    for (const model::CurvePoint& pt : model::effective_points(c)) {
      x.push_back(pt.x);
      y.push_back(pt.y);
    }
    curves.emplace_back(c.id, std::move(x), std::move(y));
  }

  CohesiveLawBuild out;
  auto built = law::from_user_constants(uif.constants, curves);
  for (const law::ConstantError& e : built.errors) {
    keyword::Diagnostic d;
    d.keyword = kKeyword;
    d.where = uif.where;
    if (e.index >= 1 && static_cast<std::size_t>(e.index) <= uif.constant_where.size()) {
      d.where = uif.constant_where[static_cast<std::size_t>(e.index - 1)];
    }
    d.field = e.index >= 1 ? "UC" + std::to_string(e.index) + " (" + e.name + ")" : e.name;
    d.message = e.message;
    out.errors.push_back(std::move(d));
  }
  if (out.errors.empty())
    out.parameters = std::move(built.parameters);
  return out;
}

}  // namespace plyform::setup

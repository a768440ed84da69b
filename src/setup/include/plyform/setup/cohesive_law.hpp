#pragma once
// *USER_INTERFACE_FRICTION -> the parameters of the interlayer law, with every error located
// at the card line of the constant it concerns.

#include <optional>
#include <vector>

#include "plyform/keyword/diagnostic.hpp"
#include "plyform/law/parameters.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::setup {

struct CohesiveLawBuild {
  std::optional<law::Parameters> parameters;  ///< set when there is no error
  std::vector<keyword::Diagnostic> errors;
};

/// Builds the law of one *USER_INTERFACE_FRICTION; its -N slots are resolved against the
/// model's *DEFINE_CURVEs (scale factors and offsets applied).
[[nodiscard]] CohesiveLawBuild build_cohesive_law(const model::ModelDesc& model,
                                                  const model::UserInterfaceFrictionDesc& uif);

}  // namespace plyform::setup

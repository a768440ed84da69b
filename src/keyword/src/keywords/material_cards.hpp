#pragma once
// Fields and checks shared by the *MAT_ keywords.

#include <string>
#include <string_view>

#include <fmt/format.h>

#include "common_cards.hpp"

namespace plyform::keyword {

inline constexpr FieldSpec kMaterialIdField{.name = "MID",
                                            .type = FieldType::kInteger,
                                            .min_value = 1,
                                            .unit = "-",
                                            .description = "material id",
                                            .required = true};
inline constexpr FieldSpec kDensityField{.name = "RO",
                                         .type = FieldType::kReal,
                                         .min_value = 0.0,
                                         .unit = "mass/length^3",
                                         .description = "density, > 0",
                                         .required = true};
inline constexpr FieldSpec kYoungsModulusField{.name = "E",
                                               .type = FieldType::kReal,
                                               .min_value = 0.0,
                                               .unit = "stress",
                                               .description = "Young's modulus, > 0",
                                               .required = true};
inline constexpr FieldSpec kPoissonRatioField{.name = "PR",
                                              .type = FieldType::kReal,
                                              .min_value = -1.0,
                                              .max_value = 0.5,
                                              .unit = "-",
                                              .description = "Poisson's ratio",
                                              .max_exclusive = true};

/// Fails with "<FIELD> must be > 0" unless value > 0.
inline void require_positive(KeywordInput& in, int line, std::string_view field, double value) {
  if (!(value > 0.0)) {
    in.fail(line, std::string(field), fmt::format("{} must be > 0, got {}", field, value));
  }
}

}  // namespace plyform::keyword

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

/// The Cowper-Symonds pair (C and P, or SRC and SRP) of a J2 law: both > 0 (the yield stress
/// scaled by 1 + (rate / C)^(1 / P)) or both 0 (no rate effect); one alone is an error on the
/// missing one.
inline void require_rate_pair(KeywordInput& in, int line, std::string_view c_field, double c,
                              std::string_view p_field, double p) {
  if ((c > 0.0) != (p > 0.0)) {
    in.fail(line, std::string(c > 0.0 ? p_field : c_field),
            fmt::format("{} = {}, {} = {}: the Cowper-Symonds factor needs both (or neither, "
                        "no rate effect)",
                        c_field, c, p_field, p));
  }
}

/// VP of a law with Cowper-Symonds rates: 0 (the yield stress scaled by the factor of the
/// total strain rate) is what plyform does; the other formulations are errors.
inline void require_rate_scaling(KeywordInput& in, int line, double vp) {
  if (vp != 0.0) {
    in.fail(line, "VP",
            fmt::format("VP = {} is not supported (1: the viscoplastic formulation, -1: the "
                        "deviatoric strain rate); use VP = 0, the yield stress scaled by the "
                        "Cowper-Symonds factor of the total strain rate",
                        vp));
  }
}

}  // namespace plyform::keyword

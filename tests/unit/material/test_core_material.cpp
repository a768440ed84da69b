// material::density, bulk_modulus, shear_modulus and the dilatational wave speed.

#include <gtest/gtest.h>

#include <cmath>

#include "plyform/core/material.hpp"
#include "plyform/material/constitutive.hpp"
#include "plyform/material/law_registry.hpp"

namespace plyform::material {
namespace {

TEST(CoreMaterial, ElasticModuli) {
  const core::Material m = core::ElasticMaterial{7.85e-9, 210000.0, 0.3};
  EXPECT_DOUBLE_EQ(material::density(m), 7.85e-9);
  EXPECT_DOUBLE_EQ(material::shear_modulus(m), 210000.0 / 2.6);
  EXPECT_DOUBLE_EQ(material::bulk_modulus(m), 210000.0 / 1.2);
  // Constrained modulus E (1 - nu) / ((1 + nu) (1 - 2 nu)).
  const double c = std::sqrt(210000.0 * 0.7 / (1.3 * 0.4) / 7.85e-9);
  EXPECT_NEAR(dilatational_wave_speed(m), c, 1e-12 * c);
}

TEST(CoreMaterial, MooneyRivlinModuli) {
  const core::Material m = core::MooneyRivlinMaterial{1.1e-9, 0.49, 0.4, 0.1};
  const double g = 1.0;  // 2 (A + B)
  const double k = 2.0 * g * 1.49 / (3.0 * 0.02);
  EXPECT_DOUBLE_EQ(material::density(m), 1.1e-9);
  EXPECT_NEAR(material::shear_modulus(m), g, 1e-15);
  EXPECT_NEAR(material::bulk_modulus(m), k, 1e-12 * k);
  // The same K from the linearised energy: 28 A / 3 + 64 B / 3 + 8 D.
  const double d = (0.4 * (5 * 0.49 - 2) + 0.1 * (11 * 0.49 - 5)) / (2 * (1 - 2 * 0.49));
  EXPECT_NEAR(material::bulk_modulus(m), 28 * 0.4 / 3 + 64 * 0.1 / 3 + 8 * d, 1e-10 * k);
  const double c = std::sqrt((k + 4.0 / 3.0 * g) / 1.1e-9);
  EXPECT_NEAR(dilatational_wave_speed(m), c, 1e-12 * c);
}

}  // namespace
}  // namespace plyform::material

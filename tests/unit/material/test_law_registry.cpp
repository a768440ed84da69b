// The registry of material laws: every member of core::Material has its law, with LS-DYNA's
// keyword and number, and the kernels' support follows the laws' traits.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "plyform/material/law_registry.hpp"

namespace plyform {
namespace {

TEST(LawRegistry, EveryMaterialHasItsKeywordAndNumber) {
  const struct {
    core::Material m;
    const char* keyword;
    int number;
    bool solids, shells;
    std::size_t history;
  } cases[] = {
      {core::ElasticMaterial{}, "*MAT_ELASTIC", 1, true, true, 0},
      {core::OrthotropicElasticMaterial{}, "*MAT_ORTHOTROPIC_ELASTIC", 2, false, true, 0},
      {core::PowerLawPlasticity{}, "*MAT_POWER_LAW_PLASTICITY", 18, true, true, 0},
      {core::RigidMaterial{}, "*MAT_RIGID", 20, false, false, 0},
      {core::PiecewiseLinearPlasticity{}, "*MAT_PIECEWISE_LINEAR_PLASTICITY", 24, true, true, 0},
      {core::MooneyRivlinMaterial{}, "*MAT_MOONEY-RIVLIN_RUBBER", 27, true, false, 0},
      {core::ElasticPlasticThermal{}, "*MAT_ELASTIC_PLASTIC_THERMAL", 4, true, true, 0},
      {core::ReinforcedThermoplastic{}, "*MAT_REINFORCED_THERMOPLASTIC", 249, false, true, 14},
      {core::PlasticKinematic{}, "*MAT_PLASTIC_KINEMATIC", 3, true, true, 6},
      {core::TransverselyAnisotropicPlastic{}, "*MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC", 37,
       false, true, 0},
      {core::Barlat89Plastic{}, "*MAT_3-PARAMETER_BARLAT", 36, false, true, 0},
      {core::Hill3RPlastic{}, "*MAT_HILL_3R", 122, false, true, 0},
  };
  std::set<std::string> keywords;
  for (const auto& c : cases) {
    const material::LawInfo& info = material::law_info(c.m);
    EXPECT_EQ(info.keyword, c.keyword);
    EXPECT_EQ(info.number, c.number) << c.keyword;
    EXPECT_EQ(material::law_for_solids(c.m), c.solids) << c.keyword;
    EXPECT_EQ(material::law_for_shells(c.m), c.shells) << c.keyword;
    EXPECT_EQ(material::history_per_point(c.m), c.history) << c.keyword;
    keywords.insert(std::string(info.keyword));
  }
  EXPECT_EQ(keywords.size(), std::variant_size_v<core::Material>);
}

TEST(LawRegistry, IsotropicModuliAreTheClosedForms) {
  core::PiecewiseLinearPlasticity law;
  law.density = 7.85e-9;
  law.young = 210000.0;
  law.poisson = 0.3;
  law.sigy = 250.0;
  law.etan = 1000.0;
  const core::Material steel = law;
  EXPECT_DOUBLE_EQ(material::bulk_modulus(steel), 210000.0 / (3.0 * (1.0 - 0.6)));
  EXPECT_DOUBLE_EQ(material::shear_modulus(steel), 210000.0 / 2.6);
  EXPECT_DOUBLE_EQ(material::density(steel), 7.85e-9);
}

// The messages that say which laws a part may use list the registry's laws for the element.
TEST(LawRegistry, LawKeywordsForSolidsAndShells) {
  const std::string solids = material::law_keywords(true);
  const std::string shells = material::law_keywords(false);
  EXPECT_NE(solids.find("*MAT_MOONEY-RIVLIN_RUBBER"), std::string::npos) << solids;
  EXPECT_EQ(solids.find("*MAT_HILL_3R"), std::string::npos) << solids;
  EXPECT_NE(shells.find("*MAT_3-PARAMETER_BARLAT"), std::string::npos) << shells;
  EXPECT_NE(shells.find("*MAT_HILL_3R"), std::string::npos) << shells;
  EXPECT_EQ(shells.find("*MAT_MOONEY-RIVLIN_RUBBER"), std::string::npos) << shells;
  EXPECT_TRUE(shells.ends_with(" or *MAT_RIGID")) << shells;
}

}  // namespace
}  // namespace plyform

#pragma once
// Decks of the dynain tests (test_deck_dynain*.cpp): *MAT_PIECEWISE_LINEAR_PLASTICITY (bilinear
// J2) shells in free format, and the dynain file read back by plyform's own reader, keyed by
// element id.

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "plyform/keyword/read_deck.hpp"

namespace plyform::test {

constexpr double kDynainE = 210000.0, kDynainNu = 0.3, kDynainRho = 7.85e-9;
constexpr double kDynainSigmaY = 200.0, kDynainEt = 2000.0;

/// *PART 1 with *SECTION_SHELL (ELFORM, NIP, thickness h) and the bilinear J2 material.
inline std::string j2_part(int elform, int nip, double h) {
  std::ostringstream os;
  os.precision(17);
  os << "*PART\nsheet\n1,1,1\n*SECTION_SHELL\n1," << elform << ",0.8333," << nip << "\n"
     << h << "," << h << "," << h << "," << h << "\n"
     << "*MAT_PIECEWISE_LINEAR_PLASTICITY\n1," << kDynainRho << "," << kDynainE << "," << kDynainNu
     << "," << kDynainSigmaY << "," << kDynainEt << "\n0,0\n";
  return os.str();
}

/// One shell of a dynain file as plyform's reader gives it.
struct DynainShell {
  int part = 0;
  std::array<int, 4> nodes{};
  std::array<double, 4> thickness{};
  model::InitialStressShellDesc stress;
  model::InitialStrainShellDesc strain;
  bool has_stress = false, has_strain = false;
};

struct Dynain {
  std::map<int, std::array<double, 3>> nodes;
  std::map<int, DynainShell> shells;
};

/// Reads `file` with plyform's keyword reader (it must read without an error).
inline Dynain read_dynain(const std::filesystem::path& file) {
  Dynain d;
  const keyword::ReadResult r = keyword::read_deck(file);
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front().to_string());
  for (const model::NodeDesc& n : r.model.nodes)
    d.nodes[n.id] = {n.x, n.y, n.z};
  for (const model::ElementShellDesc& e : r.model.shells) {
    DynainShell& s = d.shells[e.id];
    s.part = e.part_id;
    s.nodes = e.nodes;
    EXPECT_TRUE(e.has_thickness_card) << e.id;
    s.thickness = e.thickness;
  }
  for (const model::InitialStressShellDesc& i : r.model.initial_shell_stresses) {
    d.shells[i.element_id].stress = i;
    d.shells[i.element_id].has_stress = true;
  }
  for (const model::InitialStrainShellDesc& i : r.model.initial_shell_strains) {
    d.shells[i.element_id].strain = i;
    d.shells[i.element_id].has_strain = true;
  }
  return d;
}

}  // namespace plyform::test

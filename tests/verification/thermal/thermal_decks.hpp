#pragma once
// Decks of the heat-transfer verification tests, as text: a strip of hexahedra or of thin
// shells along x, and a cube or a square plate with heat boundaries. SI units (m, s, kg, K):
// steel-like, rho 7800, c 500, k 50.

#include <sstream>
#include <string>

namespace plyform::test {

inline constexpr double kRho = 7800.0, kHeatCapacity = 500.0, kConductivity = 50.0;

/// The deck's controls: thermal only (SOLN 1) or coupled (2), the end time, the thermal step,
/// theta, the speed-up factor and the state interval.
struct ThermalControls {
  int soln = 1;
  double end_time = 1.0;
  double step = 0.1;
  double theta = 0.5;
  double tsf = 1.0;
  double state_dt = 0.0;
  int solver = 11;
};

inline std::string thermal_header(const ThermalControls& c) {
  std::ostringstream os;
  os.precision(10);
  os << "*KEYWORD\n*CONTROL_TERMINATION\n" << c.end_time << "\n";
  os << "*CONTROL_SOLUTION\n" << c.soln << "\n";
  os << "*CONTROL_THERMAL_SOLVER\n1,0," << c.solver << "\n0,0,0,0,0,,," << c.tsf << "\n";
  os << "*CONTROL_THERMAL_TIMESTEP\n0," << c.theta << "," << c.step << "\n";
  if (c.state_dt > 0.0)
    os << "*DATABASE_BINARY_D3PLOT\n" << c.state_dt << "\n";
  os << "*DATABASE_GLSTAT\n" << (c.state_dt > 0.0 ? c.state_dt : c.end_time) << "\n";
  os << "*MAT_ELASTIC\n1," << kRho << ",2.0e11,0.3\n";
  os << "*MAT_THERMAL_ISOTROPIC\n1,0.0\n" << kHeatCapacity << "," << kConductivity << "\n";
  return os.str();
}

/// A strip [0, length] along x of n hexahedra with an a x a cross-section (node ids
/// 4 i + 2 j + k + 1), insulated except where the caller adds boundaries. Node sets 1 and 2:
/// the ends x = 0 and x = length.
inline std::string hex_strip(int n, double length, double a) {
  std::ostringstream os;
  os.precision(12);
  os << "*PART\nstrip\n1,1,1,0,0,0,0,1\n*SECTION_SOLID\n1,1\n*NODE\n";
  const auto id = [](int i, int j, int k) { return 4 * i + 2 * j + k + 1; };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= 1; ++j)
      for (int k = 0; k <= 1; ++k)
        os << id(i, j, k) << "," << length * i / n << "," << a * j << "," << a * k << "\n";
  os << "*ELEMENT_SOLID\n";
  for (int i = 0; i < n; ++i)
    os << i + 1 << ",1," << id(i, 0, 0) << "," << id(i + 1, 0, 0) << "," << id(i + 1, 1, 0) << ","
       << id(i, 1, 0) << "," << id(i, 0, 1) << "," << id(i + 1, 0, 1) << "," << id(i + 1, 1, 1)
       << "," << id(i, 1, 1) << "\n";
  for (int s = 1; s <= 2; ++s) {
    const int i = s == 1 ? 0 : n;
    os << "*SET_NODE_LIST\n"
       << s << "\n"
       << id(i, 0, 0) << "," << id(i, 1, 0) << "," << id(i, 0, 1) << "," << id(i, 1, 1) << "\n";
  }
  return os.str();
}

/// The same strip of n thin quadrilateral shells (width a, thickness t) in the z = 0 plane
/// (node ids 2 i + j + 1). Node sets 1 and 2: the ends.
inline std::string shell_strip(int n, double length, double a, double t) {
  std::ostringstream os;
  os.precision(12);
  os << "*PART\nstrip\n1,1,1,0,0,0,0,1\n*SECTION_SHELL\n1,2,0.8333,2\n"
     << t << "," << t << "," << t << "," << t << "\n*NODE\n";
  const auto id = [](int i, int j) { return 2 * i + j + 1; };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= 1; ++j)
      os << id(i, j) << "," << length * i / n << "," << a * j << ",0.0\n";
  os << "*ELEMENT_SHELL\n";
  for (int i = 0; i < n; ++i)
    os << i + 1 << ",1," << id(i, 0) << "," << id(i + 1, 0) << "," << id(i + 1, 1) << ","
       << id(i, 1) << "\n";
  for (int s = 1; s <= 2; ++s) {
    const int i = s == 1 ? 0 : n;
    os << "*SET_NODE_LIST\n" << s << "\n" << id(i, 0) << "," << id(i, 1) << "\n";
  }
  return os.str();
}

}  // namespace plyform::test

namespace plyform::test {

/// Two a x a blocks stacked along z, one hexahedron each: part 1 on [0, t1], part 2 on
/// [t1 + gap, t1 + gap + t2] (its own nodes, 9..16), each with its thermal material (TMID 1,
/// 2: both steel-like with conductivity k), in a _THERMAL contact of part 2 (slave) on part 1
/// with the closed-gap conductance h0, LMIN, LMAX and ALGO given.
inline std::string stacked_blocks(double a, double t1, double t2, double gap, double k, double h0,
                                  double lmin, double lmax, int algo, int bc_flg = 0) {
  std::ostringstream os;
  os.precision(12);
  os << "*MAT_THERMAL_ISOTROPIC\n2,0.0\n" << kHeatCapacity << "," << k << "\n";
  os << "*PART\nlower\n1,1,1,0,0,0,0,2\n*PART\nupper\n2,1,1,0,0,0,0,2\n*SECTION_SOLID\n1,1\n";
  os << "*NODE\n";
  const double z[4] = {0.0, t1, t1 + gap, t1 + gap + t2};
  int id = 1;
  for (int layer = 0; layer < 4; ++layer)
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {a, 0.0}, {a, a}, {0.0, a}})
      os << id++ << "," << x << "," << y << "," << z[layer] << "\n";
  os << "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n2,2,9,10,11,12,13,14,15,16\n";
  os << "*CONTACT_SURFACE_TO_SURFACE_THERMAL\n2,1,3,3\n0,0\n0,0\n";
  os << "0,"
     << "0," << h0 << "," << lmin << "," << lmax << ",0.5," << bc_flg << "," << algo << "\n";
  os << "*SET_NODE_LIST\n1\n1,2,3,4,5,6,7,8\n*SET_NODE_LIST\n2\n9,10,11,12,13,14,15,16\n";
  return os.str();
}

}  // namespace plyform::test

#pragma once
// Runtime material parameters (consistent units). One struct per law; a block of elements
// carries one, dispatched once per block. Each member's law (update, moduli, name, history) is
// its unit in src/material/include/plyform/material/laws/, listed in law_registry.hpp.

#include <array>
#include <variant>
#include <vector>

#include "plyform/core/curve_table.hpp"
#include "plyform/core/load_curve.hpp"

namespace plyform::core {

/// *MAT_ELASTIC (001): isotropic, hypoelastic with the Jaumann rate for large deformation.
struct ElasticMaterial {
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
};

/// *MAT_MOONEY-RIVLIN_RUBBER (027), LS-DYNA's compressible form:
/// W = A (I1 - 3) + B (I2 - 3) + C (III^-2 - 1) + D (III - 1)^2,
/// C = A/2 + B, D = (A (5 nu - 2) + B (11 nu - 5)) / (2 (1 - 2 nu)).
struct MooneyRivlinMaterial {
  double density = 0.0;
  double poisson = 0.0;
  double a = 0.0;
  double b = 0.0;
};

/// Isotropic hardening curve of a plasticity law: yield stress against effective plastic
/// strain, piecewise linear, extrapolated with the last slope.
struct HardeningCurve {
  std::vector<double> plastic_strain;
  std::vector<double> yield_stress;
};

/// *MAT_PIECEWISE_LINEAR_PLASTICITY (024): J2 (von Mises) plasticity with isotropic hardening,
/// the yield stress from `curve` when it has points, else bilinear SIGY + E_p eps_p with the
/// plastic modulus E_p = E ETAN / (E - ETAN).
struct PiecewiseLinearPlasticity {
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
  double sigy = 0.0;
  double etan = 0.0;
  HardeningCurve curve;
  /// C, P: Cowper-Symonds scaling of the yield stress by 1 + (rate / C)^(1 / P) (both > 0;
  /// rate sqrt(D : D)); 0 and 0: none.
  double rate_c = 0.0;
  double rate_p = 0.0;
  /// LCSS naming a *DEFINE_TABLE: a yield curve per strain rate (the table's values, strictly
  /// increasing; the natural logarithm of the rate when the first is negative, LS-DYNA's
  /// convention), read linearly between the two curves around a point's rate sqrt(D : D) and
  /// as the first or last curve outside them. Empty: none (curve and rates above).
  std::vector<double> rate_values{};
  std::vector<HardeningCurve> rate_curves{};
  bool log_rates = false;
};

/// *MAT_POWER_LAW_PLASTICITY (018): J2 with sigma_y = k (eps_yp + eps_p)^n, eps_yp the strain
/// at first yield: (sigy / k)^(1/n) when SIGY > 0, else the intersection (E / k)^(1/(n - 1)).
struct PowerLawPlasticity {
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
  double k = 0.0;
  double n = 0.0;
  double sigy = 0.0;
  /// SRC, SRP: Cowper-Symonds scaling as *MAT_024's C, P.
  double rate_c = 0.0;
  double rate_p = 0.0;
};

/// *MAT_ELASTIC_PLASTIC_THERMAL (004): J2 plasticity with bilinear isotropic hardening whose
/// constants are tabulated against temperature (2..8 points, increasing temperatures): linear
/// between the points. sigma_y(eps_p, T) = SIGY(T) + E_p(T) eps_p, E_p = E ETAN / (E - ETAN),
/// hypoelastic with E(T), nu(T) at the end of the step; alpha(T) is the thermal expansion
/// (the element kernels apply it, core::ShellBlock::expansion). A temperature outside the table
/// stops the run (LS-DYNA's meaning).
struct ElasticPlasticThermal {
  double density = 0.0;
  std::vector<double> temperature;
  std::vector<double> young, poisson, alpha, sigy, etan;
};

/// *MAT_ORTHOTROPIC_ELASTIC (002): elastic constants in the material axes a, b, c. For shells
/// the axes follow AOPT: 0 = the element's local axes (a along nodes 1-2), 2 = the global
/// vector `a` projected on the shell (with `d` as LS-DYNA's second vector).
struct OrthotropicElasticMaterial {
  double density = 0.0;
  double ea = 0.0, eb = 0.0, ec = 0.0;
  double prba = 0.0, prca = 0.0, prcb = 0.0;
  double gab = 0.0, gbc = 0.0, gca = 0.0;
  int aopt = 0;
  double a[3] = {1.0, 0.0, 0.0};
  double d[3] = {0.0, 1.0, 0.0};
};

/// *MAT_RIGID (020): the part moves as one rigid body. E and nu only scale contact stiffness.
/// CMO/CON1/CON2: the constraints of the body's centre of mass (LS-DYNA codes).
struct RigidMaterial {
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
  double cmo = 0.0;
  int con1 = 0;
  int con2 = 0;
};

/// *MAT_REINFORCED_THERMOPLASTIC (249), shells: a ply of fibre families in a thermoplastic
/// matrix. The stress is the sum of the matrix's (isotropic, hypoelastic, E and nu against
/// temperature, optionally J2 with a yield curve or a table of yield curves over temperature),
/// each family's fibre stress along its current direction (tension only) and the shear stress
/// between neighbouring families against their shear angle (the change of the angle between
/// them), with locking. Curves of a family or a shear pair may be tables over temperature: a
/// CurveTable with one value is a plain curve. Derivation: docs/materials.md.
struct ReinforcedThermoplastic {
  struct Fibre {
    double alpha = 0.0;    ///< angle from the material axis a about the normal, radians
    double modulus = 0.0;  ///< EF: nominal fibre stress per unit fibre strain (no curve)
    CurveTable stress;     ///< LCEF: nominal stress against engineering fibre strain (empty: EF)
    double g23 = 0.0;      ///< transverse shear modulus across the fibres
    double g31 = 0.0;      ///< transverse shear modulus along the fibres
  };
  struct Shear {
    double modulus = 0.0;       ///< G: linear shear modulus; METH 3 the elastic (unloading) slope
    CurveTable stress;          ///< LCG: shear stress against the shear angle, radians (empty: G)
    double lock_angle = 0.0;    ///< ALOC, radians (0: no locking)
    double lock_modulus = 0.0;  ///< GLOC
    int meth = 2;               ///< 2 elastic curve, 3 elasto-plastic curve (with a curve only)
  };
  double density = 0.0;
  double young = 0.0;      ///< EM
  LoadCurve young_of_t;    ///< LCEM (empty: EM)
  double poisson = 0.0;    ///< PRM
  LoadCurve poisson_of_t;  ///< LCPRM (empty: PRM)
  CurveTable yield;  ///< LCSIGY: yield stress against eps_p (over temperature); empty: elastic
  int families = 2;  ///< NFIB
  std::array<Fibre, 3> fibre{};
  std::array<Shear, 2> shear{};  ///< between families (1, 2) and (2, 3)
  int aopt = 0;                  ///< 0 edge 1-2, 2 global vector a, 3 v x normal
  double a[3] = {1.0, 0.0, 0.0};
  double v[3] = {0.0, 0.0, 0.0};
  double angle = 0.0;  ///< MANGL, radians (AOPT 0 and 3)
};

/// *MAT_PLASTIC_KINEMATIC (003): J2 plasticity with bilinear mixed hardening. The plastic
/// modulus E_p = E ETAN / (E - ETAN) is split by BETA: the yield stress (the radius of the
/// yield surface) is k (SIGY + BETA E_p eps_p), the back stress (its centre) moves by
/// (1 - BETA) 2/3 E_p d eps^p; BETA 0 is kinematic, 1 isotropic hardening. k is the
/// Cowper-Symonds factor 1 + (eps_rate / SRC)^(1 / SRP) (1 when SRC or SRP is 0), eps_rate =
/// sqrt(D : D) of the total rate of deformation. Derivation: docs/materials.md.
struct PlasticKinematic {
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
  double sigy = 0.0;
  double etan = 0.0;
  double beta = 0.0;
  double src = 0.0;  ///< Cowper-Symonds C, 1/time (0: no rate effect)
  double srp = 0.0;  ///< Cowper-Symonds P (0: no rate effect)
};

/// *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (037), shells: isotropic elasticity, Hill's
/// 1948 yield function with normal anisotropy r (plane stress, in-plane isotropic):
/// sigma_eq^2 = sxx^2 + syy^2 - 2r/(1 + r) sxx syy + 2(1 + 2r)/(1 + r) sxy^2, associated flow,
/// isotropic hardening from `curve` when it has points, else SIGY + ETAN eps_p (LS-DYNA's ETAN
/// of this law is the plastic hardening modulus, not a tangent modulus). r = 1 is von Mises.
/// Derivation: docs/materials.md.
struct TransverselyAnisotropicPlastic {
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
  double sigy = 0.0;
  double etan = 0.0;
  double r = 1.0;
  HardeningCurve curve;
};

/// The hardening rules of the sheet-metal laws' HR field (*MAT_036, *MAT_122): the yield
/// stress of the reference (rolling, 0 degree) direction against the effective plastic strain.
struct SheetHardening {
  enum class Rule {
    kLinear = 1,  ///< HR 1: sigy + hp eps_p, hp = E ETAN / (E - ETAN) (P2 SIGY, P1 ETAN)
    kSwift = 2,   ///< HR 2: k (e0 + eps_p)^n (P1 k, P2 n)
    kCurve = 3,   ///< HR 3: the curve LCID
    kVoce = 4,    ///< HR 4: a - b exp(-c eps_p) (P1 a, P2 b, P3 c)
  };
  Rule rule = Rule::kLinear;
  double sigy = 0.0;
  double hp = 0.0;
  double k = 0.0;
  double n = 0.0;
  double e0 = 0.0;
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
  HardeningCurve curve;
};

/// Material axes of an orthotropic shell law (LS-DYNA's AOPT 0, 2, 3; see
/// material::MaterialAxes).
struct ShellAxes {
  int aopt = 0;
  double a[3] = {1.0, 0.0, 0.0};
  double v[3] = {0.0, 0.0, 1.0};
  double angle = 0.0;  ///< BETA, radians (AOPT 0 and 3)
};

/// *MAT_3-PARAMETER_BARLAT (036), shells: isotropic elasticity, the Barlat-Lian 1989 yield
/// function in the material axes (a rolling, b transverse):
/// 2 sigma_y^m = a |K1 + K2|^m + a |K1 - K2|^m + c |2 K2|^m, K1 = (s_aa + h s_bb) / 2,
/// K2 = sqrt(((s_aa - h s_bb) / 2)^2 + p^2 s_ab^2), associated flow, isotropic hardening
/// (SheetHardening), Cowper-Symonds scaling of the yield stress. Derivation: docs/materials.md.
struct Barlat89Plastic {
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
  SheetHardening hardening;
  double m = 8.0;
  double a = 1.0, c = 1.0, h = 1.0, p = 1.0;
  double rate_c = 0.0;  ///< Cowper-Symonds C (0: no rate effect)
  double rate_p = 0.0;  ///< Cowper-Symonds P
  ShellAxes axes;
};

/// *MAT_HILL_3R (122), shells: isotropic elasticity, Hill's 1948 yield function with the three
/// Lankford ratios R00, R45, R90, in the material axes (plane stress, G + H = 1):
/// sigma_y^2 = s_aa^2 - 2 H s_aa s_bb + (F + H) s_bb^2 + 2 N s_ab^2, H = R00 / (1 + R00),
/// F = H / R90, N = (F + G)(R45 + 1/2); associated flow, isotropic hardening (SheetHardening).
struct Hill3RPlastic {
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
  SheetHardening hardening;
  double r00 = 1.0, r45 = 1.0, r90 = 1.0;
  ShellAxes axes;
};

using Material = std::variant<ElasticMaterial, MooneyRivlinMaterial, PiecewiseLinearPlasticity,
                              PowerLawPlasticity, OrthotropicElasticMaterial, RigidMaterial,
                              ElasticPlasticThermal, ReinforcedThermoplastic, PlasticKinematic,
                              TransverselyAnisotropicPlastic, Barlat89Plastic, Hill3RPlastic>;

// The law of each member (its kernel, moduli and name): material/law_registry.hpp.

}  // namespace plyform::core

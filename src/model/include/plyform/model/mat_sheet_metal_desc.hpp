#pragma once
// The metal plasticity keywords of real decks: *MAT_PLASTIC_KINEMATIC (*MAT_003) and
// *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (*MAT_037). Values as written; the reader
// rejects what plyform does not implement (element erosion, the viscoplastic rate form, the
// elastic modulus from curves).

#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *MAT_PLASTIC_KINEMATIC (*MAT_003): J2 plasticity with bilinear hardening, kinematic to
/// isotropic by BETA, Cowper-Symonds scaling of the yield stress.
struct MatPlasticKinematicDesc {
  int id = 0;            ///< MID
  std::string title;     ///< from the _TITLE option; empty otherwise
  double density = 0.0;  ///< RO, mass / length^3
  double young = 0.0;    ///< E, stress
  double poisson = 0.0;  ///< PR
  double sigy = 0.0;     ///< SIGY: yield stress, stress
  double etan = 0.0;     ///< ETAN: tangent modulus, stress (0 <= ETAN < E)
  double beta = 0.0;     ///< BETA: 0 kinematic, 1 isotropic hardening, between: mixed
  double src = 0.0;      ///< SRC: Cowper-Symonds C, 1/time (0: no rate effect)
  double srp = 0.0;      ///< SRP: Cowper-Symonds P (0: no rate effect)
  double fs = 1.0e20;    ///< FS: plastic strain at element erosion (blank, 0: 1e20, none)
  double vp = 0.0;       ///< VP: 0 scales the yield stress (1, viscoplastic, is rejected)
  SourceLocation where;  ///< the line of card 1
};

/// *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (*MAT_037), shells: Hill's 1948 yield
/// function with normal anisotropy R, hardening by ETAN or the curve HLCID.
struct MatTransverselyAnisotropicDesc {
  int id = 0;             ///< MID
  std::string title;      ///< from the _TITLE option; empty otherwise
  double density = 0.0;   ///< RO, mass / length^3
  double young = 0.0;     ///< E, stress
  double poisson = 0.0;   ///< PR
  double sigy = 0.0;      ///< SIGY: yield stress, stress (ignored with HLCID)
  double etan = 0.0;      ///< ETAN: plastic hardening modulus, stress (ignored with HLCID)
  double r = 0.0;         ///< R: the normal anisotropy (Lankford) ratio; < 0: |R| (stabilised)
  int hlcid = 0;          ///< HLCID: *DEFINE_CURVE of yield stress against eps_p (0: none)
  int idscale = 0;        ///< IDSCALE (card 2): curve of E against strain; must be 0
  double ea = 0.0;        ///< EA (card 2): E against strain; must be 0
  double coe = 0.0;       ///< COE (card 2): E against strain; must be 0
  int icfld = 0;          ///< ICFLD (card 2): forming limit curve for output; kept as written
  double strainlt = 0.0;  ///< STRAINLT (card 2): strain averaging; must be 0
  SourceLocation where;   ///< the line of card 1
};

/// The hardening fields shared by *MAT_036 and *MAT_122 (HR with P1, P2, P3, LCID, E0, SPI).
struct SheetHardeningDesc {
  int hr = 1;        ///< 1 linear, 2 Swift k (e0 + eps_p)^n, 3 curve LCID, 4 Voce
  double p1 = 0.0;   ///< HR 1: ETAN; HR 2: k; HR 4: a
  double p2 = 0.0;   ///< HR 1: SIGY; HR 2: n; HR 4: b
  double p3 = 0.0;   ///< HR 4: c (*MAT_036 only)
  int lcid = 0;      ///< HR 3: curve of yield stress against eps_p
  double e0 = 0.0;   ///< HR 2: the plastic strain at yield (0: from SPI)
  double spi = 0.0;  ///< HR 2 with E0 = 0 (*MAT_036): 0 (E/k)^(1/(n-1)), <= 0.02 itself, else
                     ///< (SPI/k)^(1/n)
};

/// The material axes of an orthotropic shell card (AOPT and its vectors; BETA in degrees).
struct ShellAxesDesc {
  int aopt = 0;
  double a[3] = {0.0, 0.0, 0.0};
  double v[3] = {0.0, 0.0, 0.0};
  double d[3] = {0.0, 0.0, 0.0};
  double beta = 0.0;
};

/// *MAT_3-PARAMETER_BARLAT (*MAT_036), shells: the Barlat-Lian 1989 yield function.
struct MatBarlat89Desc {
  int id = 0;
  std::string title;
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
  SheetHardeningDesc hardening;
  double m = 0.0;    ///< M: the exponent (6 BCC, 8 FCC)
  double r00 = 0.0;  ///< R00 (or AB with PB > 0)
  double r45 = 0.0;  ///< R45 (or CB with PB > 0)
  double r90 = 0.0;  ///< R90 (or HB with PB > 0)
  double c = 0.0;    ///< C: Cowper-Symonds C (0: no rate effect)
  double p = 0.0;    ///< P: Cowper-Symonds P
  double pb = 0.0;   ///< PB > 0: the coefficients a, c, h, p given as AB, CB, HB, PB
  ShellAxesDesc axes;
  SourceLocation where;
};

/// *MAT_HILL_3R (*MAT_122), shells: Hill 1948 with three Lankford ratios.
struct MatHill3RDesc {
  int id = 0;
  std::string title;
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
  SheetHardeningDesc hardening;
  double r00 = 0.0;
  double r45 = 0.0;
  double r90 = 0.0;
  ShellAxesDesc axes;
  SourceLocation where;
};

}  // namespace plyform::model

#pragma once
// The metal plasticity keywords of real decks: *MAT_PLASTIC_KINEMATIC (*MAT_003) and
// *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (*MAT_037). Values as written; the reader
// rejects what plyform does not implement (element erosion, the viscoplastic rate form, R or
// the elastic modulus from curves).

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
  double etan = 0.0;      ///< ETAN: tangent modulus, stress (ignored with HLCID)
  double r = 0.0;         ///< R: the normal anisotropy (Lankford) ratio, > 0
  int hlcid = 0;          ///< HLCID: *DEFINE_CURVE of yield stress against eps_p (0: none)
  int idscale = 0;        ///< IDSCALE (card 2): curve of E against strain; must be 0
  double ea = 0.0;        ///< EA (card 2): E against strain; must be 0
  double coe = 0.0;       ///< COE (card 2): E against strain; must be 0
  int icfld = 0;          ///< ICFLD (card 2): forming limit curve for output; kept as written
  double strainlt = 0.0;  ///< STRAINLT (card 2): strain averaging; must be 0
  SourceLocation where;   ///< the line of card 1
};

}  // namespace plyform::model

#pragma once
// The card fields the sheet-metal laws (*MAT_036, *MAT_122) share, as their parameters: the
// hardening rule HR and the material axes.

#include <cmath>
#include <numbers>

#include "plyform/core/material.hpp"
#include "plyform/material/laws/law_traits.hpp"
#include "plyform/model/mat_sheet_metal_desc.hpp"

namespace plyform::material {

/// HR 1: SIGY P2 with the plastic modulus E P1 / (E - P1); HR 2: k P1, n P2, the plastic
/// strain at yield e0 = E0, or with E0 = 0 from SPI: (E/k)^(1/(n - 1)) (SPI 0, the elastic
/// line's intersection), SPI itself (SPI <= 0.02), (SPI/k)^(1/n) (SPI the initial yield
/// stress); HR 3: the curve LCID; HR 4: a P1, b P2, c P3.
inline core::SheetHardening sheet_hardening(const model::SheetHardeningDesc& c, double young,
                                            const DeckCurve& curve) {
  using Rule = core::SheetHardening::Rule;
  core::SheetHardening h;
  switch (c.hr) {
    case 2:
      h.rule = Rule::kSwift;
      h.k = c.p1;
      h.n = c.p2;
      if (c.e0 > 0.0)
        h.e0 = c.e0;
      else if (c.spi == 0.0)
        h.e0 = std::pow(young / c.p1, 1.0 / (c.p2 - 1.0));
      else if (c.spi <= 0.02)
        h.e0 = c.spi;
      else
        h.e0 = std::pow(c.spi / c.p1, 1.0 / c.p2);
      break;
    case 3: {
      h.rule = Rule::kCurve;
      const core::LoadCurve& lc = curve(c.lcid);
      h.curve.plastic_strain = lc.x;
      h.curve.yield_stress = lc.y;
      break;
    }
    case 4:
      h.rule = Rule::kVoce;
      h.a = c.p1;
      h.b = c.p2;
      h.c = c.p3;
      break;
    default:
      h.rule = Rule::kLinear;
      h.sigy = c.p2;
      h.hp = young * c.p1 / (young - c.p1);
      break;
  }
  return h;
}

inline core::ShellAxes shell_axes(const model::ShellAxesDesc& c) {
  core::ShellAxes a;
  a.aopt = c.aopt;
  for (int k = 0; k < 3; ++k) {
    a.a[k] = c.a[k];
    a.v[k] = c.v[k];
  }
  a.angle = c.beta * std::numbers::pi / 180.0;
  return a;
}

inline MaterialAxes material_axes(const core::ShellAxes& a) {
  return {a.aopt, a.a, a.v, a.angle};
}

}  // namespace plyform::material

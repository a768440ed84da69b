#pragma once
// Where a fit starts when no deck gives the constants, read off the curves themselves: the
// quasi-static relations of the law (peak sigma_max at g_c = sigma_max / C_N), a moderate
// rate number Lambda for eta, and half healing over the measured holds for zeta.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "plyform/fit/free_constants.hpp"
#include "plyform/fit/measured_curve.hpp"

namespace plyform::fit {

/// A complete UC vector (UC1..UC24) for the curves; `notes` says what was chosen and why.
[[nodiscard]] std::vector<std::optional<double>> default_start(
    std::span<const MeasuredCurve> curves, std::vector<std::string>& notes);

/// A free positive constant that starts at 0 (ZETA's default: no healing) cannot be fitted in
/// log form; it starts instead at the value the curves suggest, with a note. Others unchanged.
void complete_start(std::span<const FreeConstant> free, std::span<const MeasuredCurve> curves,
                    std::vector<std::optional<double>>& uc, std::vector<std::string>& notes);

}  // namespace plyform::fit

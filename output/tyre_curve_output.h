#pragma once
// Writes a tyre's force curve (motostab tyre): DIR/forces.csv and plots of Fy and Mz against slip.
#include <filesystem>
#include <string>
#include <vector>

#include "tyres/magic_formula.h"

namespace motostab::output {

/// One operating point and the forces there (ISO-W signs, tyres/magic_formula.h).
struct TyreCurvePoint {
  tyres::TyreSlip slip;
  tyres::TyreForces forces;
};

/// Pinned CSV columns of forces.csv (17 significant digits).
const std::vector<std::string>& getTyreCurveColumns();

/// DIR/forces.csv (columns fz_N, slip_angle_rad, camber_rad, slip_ratio, fx_N, fy_N, mz_Nm, mx_Nm,
/// my_Nm) and DIR/{fy,mz}_vs_slip.{png,svg,gp} (slip angle in degrees). `title` names the tyre.
void writeTyreCurve(const std::filesystem::path& dir, const std::string& title, const std::vector<TyreCurvePoint>& points);

}  // namespace motostab::output

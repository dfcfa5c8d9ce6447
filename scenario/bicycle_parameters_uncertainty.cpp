#include "scenario/bicycle_parameters_uncertainty.h"

#include <cmath>
#include <sstream>

#include "io/csv.h"
#include "scenario/bicycle_parameters.h"

namespace motostab::scenario {

using io::formatNumber;


std::map<std::string, double> readBicycleParameterSigmas(const std::string& file) {
  std::map<std::string, double> out;
  for (const auto& [name, p] : readBicycleParameterFile(file))
    if (p.sigma > 0) out[name] = p.sigma;
  return out;
}

std::pair<std::string, double> getScenarioPathOfBicycleParameter(const std::string& name) {
  static const std::map<std::string, std::string> fixed{
      {"w", "geometry.wheelbase_m"}, {"c", "geometry.trail_m"}, {"g", "gravity_mps2"},
      {"rR", "rear_wheel.radius_m"}, {"mR", "rear_wheel.mass_kg"}, {"IRxx", "rear_wheel.diametral_inertia_kgm2"},
      {"IRyy", "rear_wheel.spin_inertia_kgm2"}, {"rF", "front_wheel.radius_m"}, {"mF", "front_wheel.mass_kg"},
      {"IFxx", "front_wheel.diametral_inertia_kgm2"}, {"IFyy", "front_wheel.spin_inertia_kgm2"}};
  if (name == "lam") return {"geometry.steer_axis_tilt_deg", 180.0 / M_PI};
  if (const auto it = fixed.find(name); it != fixed.end()) return {it->second, 1.0};
  // Frames: B rear (with rider), H front; m, x/y/z (CoM), Ixx..Iyz. Sign changes of the frame
  // conversion (y, z, I_xy, I_xz) leave a standard deviation unchanged.
  if (name.size() == 2 && (name.back() == 'B' || name.back() == 'H')) {
    const std::string body = name.back() == 'B' ? "rear_frame" : "front_frame";
    if (name[0] == 'm') return {body + ".mass_kg", 1.0};
    if (name[0] == 'x') return {body + ".com_m[0]", 1.0};
    if (name[0] == 'y') return {body + ".com_m[1]", 1.0};
    if (name[0] == 'z') return {body + ".com_m[2]", 1.0};
  }
  if (name.size() == 4 && name[0] == 'I' && (name[1] == 'B' || name[1] == 'H')) {
    const std::string axes = name.substr(2);
    if (axes == "xx" || axes == "yy" || axes == "zz" || axes == "xy" || axes == "xz" || axes == "yz")
      return {std::string(name[1] == 'B' ? "rear_frame" : "front_frame") + ".inertia_kgm2." + axes, 1.0};
  }
  return {"", 0.0};
}

std::string formatBicycleParametersUncertainty(const std::map<std::string, double>& sigmas) {
  std::ostringstream y;
  for (const auto& [name, sigma] : sigmas) {
    const auto [path, factor] = getScenarioPathOfBicycleParameter(name);
    if (path.empty() || !(sigma > 0)) continue;
    y << "  " << path << ": " << formatNumber(sigma * factor, 15) << "  # " << name << "\n";
  }
  const std::string body = y.str();
  return body.empty() ? "" : "# Standard deviations from the file's +/- values (docs/uncertainty.md).\nuncertainty:\n" + body;
}

}  // namespace motostab::scenario

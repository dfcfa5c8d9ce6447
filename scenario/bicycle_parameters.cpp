#include "scenario/bicycle_parameters.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "io/csv.h"
#include "io/input_error.h"
#include "io/number.h"

namespace motostab {

std::map<std::string, double> readBicycleParameters(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError({file, 0, 0, ""}, "cannot open parameter file");
  std::map<std::string, double> out;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    const auto eq = line.find('=');
    std::string key = eq == std::string::npos ? "" : line.substr(0, eq);
    key.erase(0, key.find_first_not_of(" \t"));
    key.erase(key.find_last_not_of(" \t") + 1);
    if (key.empty()) throw InputError({file, lineNo, 0, ""}, "expected 'name = value+/-sigma'");
    std::stringstream values(line.substr(eq + 1));
    std::string item;
    double sum = 0;
    int count = 0;
    while (std::getline(values, item, ',')) {
      const std::string v = item.substr(0, item.find("+/-"));
      const auto x = parseFiniteNumber(v);
      if (!x) throw InputError({file, lineNo, 0, key}, "not a finite number: '" + v + "'");
      sum += *x;
      ++count;
    }
    if (count == 0) throw InputError({file, lineNo, 0, key}, "no value");
    out[key] = sum / count;
  }
  return out;
}

std::string convertBicycleParametersToScenario(const std::string& file, const std::string& name) {
  const auto p = readBicycleParameters(file);
  auto get = [&](const std::string& k) {
    const auto it = p.find(k);
    if (it == p.end()) throw InputError({file, 0, 0, k}, "missing parameter");
    return it->second;
  };
  auto opt = [&](const std::string& k, double fallback) { return p.count(k) ? p.at(k) : fallback; };
  auto num = [](double v) { return formatNumber(v, 15); };
  std::ostringstream y;
  y << "# Imported from " << file << " (BicycleParameters benchmark format, Moore et al. 2010).\n"
    << "# Benchmark frame (y right, z down) converted to the design frame (y left, z up): z and I_xz change sign.\n"
    << "name: " << name << "\n"
    << "description: imported benchmark parameters\n"
    << "gravity_mps2: " << num(get("g")) << "\n"
    << "speeds_mps: {start: 0, stop: 10, step: 0.1}\n"
    << "geometry:\n"
    << "  wheelbase_m: " << num(get("w")) << "\n"
    << "  trail_m: " << num(get("c")) << "\n"
    << "  steer_axis_tilt_deg: " << num(get("lam") * 180.0 / M_PI) << "\n";
  auto body = [&](const char* key, const char* s) {
    const std::string S(s);
    y << key << ":\n"
      << "  mass_kg: " << num(get("m" + S)) << "\n"
      << "  com_m: [" << num(get("x" + S)) << ", " << num(-opt("y" + S, 0)) << ", " << num(-get("z" + S)) << "]\n"
      << "  inertia_kgm2: {xx: " << num(get("I" + S + "xx")) << ", yy: " << num(get("I" + S + "yy"))
      << ", zz: " << num(get("I" + S + "zz")) << ", xy: " << num(-opt("I" + S + "xy", 0))
      << ", xz: " << num(-get("I" + S + "xz")) << ", yz: " << num(opt("I" + S + "yz", 0)) << "}\n";
  };
  auto wheel = [&](const char* key, const char* s) {
    const std::string S(s);
    const double diametral = get("I" + S + "xx");
    if (p.count("I" + S + "zz") && std::abs(p.at("I" + S + "zz") - diametral) > 1e-12)
      throw InputError({file, 0, 0, "I" + S + "zz"}, "wheel must be a body of revolution (I" + S + "zz = I" + S + "xx)");
    y << key << ":\n"
      << "  radius_m: " << num(get("r" + S)) << "\n"
      << "  crown_radius_m: 0\n"
      << "  mass_kg: " << num(get("m" + S)) << "\n"
      << "  spin_inertia_kgm2: " << num(get("I" + S + "yy")) << "\n"
      << "  diametral_inertia_kgm2: " << num(diametral) << "\n";
  };
  body("rear_frame", "B");
  body("front_frame", "H");
  wheel("rear_wheel", "R");
  wheel("front_wheel", "F");
  y << "contact: {model: rolling_no_slip}\n";
  return y.str();
}

}  // namespace motostab

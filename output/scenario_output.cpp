#include "output/scenario_output.h"

#include <iomanip>
#include <sstream>

#include "output/writer_tools.h"
#include "scenario/plausibility.h"
#include "scenario/whole_vehicle.h"
#include "vehicle/vehicle_model.h"

namespace motostab::output {

using scenario::AssumedValue;
using scenario::BodySpec;
using scenario::NamedBody;
using scenario::Scenario;
using scenario::ScenarioWarning;
using scenario::VehicleTable;

namespace {

nlohmann::json makeBodyJson(const BodySpec& b) {
  const auto& I = b.inertia;
  return {{"mass_kg", b.mass},
          {"com_m", {b.com[0], b.com[1], b.com[2]}},
          {"inertia_kgm2", {{"xx", I.xx}, {"yy", I.yy}, {"zz", I.zz}, {"xy", I.xy}, {"xz", I.xz}, {"yz", I.yz}}}};
}

nlohmann::json makeVehicleJson(const VehicleTable& t) {
  const auto& I = t.total.inertia;
  return {{"mass_kg", t.total.mass},
          {"cog_m", {t.total.com[0], t.total.com[1], t.total.com[2]}},
          {"inertia_about_cog_kgm2",
           {{"roll_xx", I.xx}, {"pitch_yy", I.yy}, {"yaw_zz", I.zz}, {"product_xz", I.xz}, {"xy", I.xy}, {"yz", I.yz}}},
          {"static_wheel_loads_N", {{"rear", t.wheelLoads[0]}, {"front", t.wheelLoads[1]}}},
          {"wheelbase_m", t.wheelbase},
          {"steer_axis_tilt_deg", t.steerAxisTiltDeg},
          {"trail_m", t.trail},
          {"normal_trail_m", t.normalTrail},
          {"fork_offset_m", t.forkOffset}};
}

std::string formatBody(const BodySpec& b) {
  std::ostringstream os;
  const auto& I = b.inertia;
  os << std::fixed << std::setprecision(4) << std::setw(9) << b.mass << " kg  CoM [" << b.com[0] << ", " << b.com[1] << ", "
     << b.com[2] << "] m  xx " << I.xx << ", yy " << I.yy << ", zz " << I.zz << ", xy " << I.xy << ", xz " << I.xz << ", yz "
     << I.yz << " kg m^2";
  return os.str();
}

}  // namespace

nlohmann::json makeScenarioJson(const Scenario& s) {
  nlohmann::json j;
  j["name"] = s.name;
  j["file"] = s.sourceFile;
  j["overrides"] = s.overrides;
  j["vehicle"] = makeVehicleJson(scenario::calcVehicleTable(s));
  j["rear_frame"] = makeBodyJson(s.rearFrame);
  j["rear_frame"]["derived_from_total"] = s.hasTotal;
  j["bodies"] = nlohmann::json::array();
  for (const NamedBody& b : vehicle::listModelBodies(s)) {
    nlohmann::json body = makeBodyJson(b.body);
    body["name"] = b.name;
    j["bodies"].push_back(body);
  }
  j["assumed"] = nlohmann::json::array();
  for (const AssumedValue& a : s.assumed) j["assumed"].push_back({{"key", a.key}, {"value", a.value}, {"source", a.source}});
  j["warnings"] = nlohmann::json::array();
  for (const ScenarioWarning& w : s.warnings)
    j["warnings"].push_back({{"check", scenario::getCheckName(w.check)},
                             {"key", w.where.key},
                             {"line", w.where.line},
                             {"column", w.where.column},
                             {"message", w.message}});
  return j;
}

void writeScenarioJson(const std::filesystem::path& dir, const Scenario& s) {
  writeFileAtomically(dir / "scenario.json", makeScenarioJson(s).dump(2) + "\n");
}

std::string formatVehicleTable(const Scenario& s) {
  const VehicleTable t = scenario::calcVehicleTable(s);
  const auto& I = t.total.inertia;
  const double weight = t.wheelLoads[0] + t.wheelLoads[1];
  std::ostringstream os;
  os << std::fixed << std::setprecision(4);
  os << "Whole vehicle with rider (design frame: origin at the rear contact, x forward, z up; about the CoG)\n"
     << "  total mass               " << t.total.mass << " kg\n"
     << "  centre of gravity        x " << t.total.com[0] << " m from the rear contact, height " << t.total.com[2]
     << " m, y " << t.total.com[1] << " m\n"
     << "  roll, pitch, yaw inertia " << I.xx << ", " << I.yy << ", " << I.zz << " kg m^2 (xx, yy, zz about the CoG)\n"
     << "  product of inertia       xz " << I.xz << " kg m^2 (tensor component -sum m x z, z up); xy " << I.xy << ", yz "
     << I.yz << "\n"
     << std::setprecision(1) << "  static wheel loads       rear " << t.wheelLoads[0] << " N, front " << t.wheelLoads[1]
     << " N (" << (weight > 0 ? 100 * t.wheelLoads[1] / weight : 0.0) << " % front)\n"
     << std::setprecision(4) << "  wheelbase                " << t.wheelbase << " m\n"
     << "  steer-axis tilt          " << t.steerAxisTiltDeg << " deg (caster, from vertical)\n"
     << "  trail, normal trail      " << t.trail << " m, " << t.normalTrail << " m\n"
     << "  fork offset              " << t.forkOffset << " m\n"
     << "Bodies (mass; CoM in the design frame; inertia about the CoM, design axes)\n";
  const std::vector<NamedBody> bodies = vehicle::listModelBodies(s);
  for (const NamedBody& b : bodies)
    os << "  " << std::left << std::setw(17) << b.name << std::right << formatBody(b.body) << "\n";
  if (s.hasTotal)
    os << "  rear_frame is derived: the total minus every other body"
       << (bodies.front().body.mass != s.rearFrame.mass ? " (with the whole rider: " + formatBody(s.rearFrame) + ")" : "")
       << "\n";
  if (!s.assumed.empty()) os << "Assumed values (not given in the scenario)\n";
  for (const AssumedValue& a : s.assumed) os << "  " << a.key << " = " << a.value << "; " << a.source << "\n";
  return os.str();
}

}  // namespace motostab::output

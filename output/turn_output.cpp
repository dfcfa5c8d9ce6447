#include "output/turn_output.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "output/writer_tools.h"

namespace motostab::output {

using analysis::HandsFreeTurn;
using analysis::TrimResult;
using analysis::restoreTrim;
using analysis::TurnFigures;
using analysis::calcTurnFigures;
using vehicle::CoordinateIndices;
using vehicle::Input;
using vehicle::VehicleModel;

nlohmann::json makeTrimJson(const VehicleModel& model, const TrimResult& trim) {
  const CoordinateIndices& ix = model.getIndices();
  const SimTK::State& s = trim.state;
  const TurnFigures f = calcTurnFigures(model, s);
  nlohmann::json j;
  j["speed_mps"] = f.speed;
  j["roll_rad"] = s.getQ()[ix.roll];
  j["steer_rad"] = s.getQ()[ix.steer];
  j["pitch_rad"] = s.getQ()[ix.pitch];
  j["steer_torque_Nm"] = model.getInput(s, Input::SteerTorque);
  j["drive_torque_Nm"] = model.getInput(s, Input::DriveTorque);
  j["yaw_rate_radps"] = f.yawRate;
  j["path_radius_m"] = std::isfinite(f.pathRadius) ? nlohmann::json(f.pathRadius) : nlohmann::json(nullptr);
  j["lateral_acceleration_mps2"] = f.lateralAcceleration;
  j["residual"] = trim.residualNorm;
  j["iterations"] = trim.iterations;
  nlohmann::json tyres = nlohmann::json::object();
  const auto names = model.getContactOutputNames();
  const auto values = model.calcContactOutputs(s);
  for (size_t k = 0; k < names.size(); ++k) tyres[names[k]] = values[k];
  j["tyres"] = tyres;
  return j;
}

void writeTrimJson(const std::filesystem::path& dir, const VehicleModel& model, const TrimResult& trim) {
  writeFileAtomically(dir / "trim.json", formatJson(makeTrimJson(model, trim), "trim.json"));
}

std::string formatTrimTable(const VehicleModel& model, const TrimResult& trim) {
  const nlohmann::json j = makeTrimJson(model, trim);
  constexpr double kDeg = 180 / M_PI;
  std::ostringstream os;
  os << std::setprecision(6);
  auto row = [&](const std::string& name, double value, const std::string& unit) {
    os << "  " << std::left << std::setw(22) << name << std::right << std::setw(14) << value << " " << unit << "\n";
  };
  row("speed", j["speed_mps"], "m/s");
  row("roll", j["roll_rad"].get<double>() * kDeg, "deg");
  row("steer", j["steer_rad"].get<double>() * kDeg, "deg");
  row("pitch", j["pitch_rad"].get<double>() * kDeg, "deg");
  row("steer torque", j["steer_torque_Nm"], "N m");
  row("drive torque", j["drive_torque_Nm"], "N m");
  row("yaw rate", j["yaw_rate_radps"], "rad/s");
  if (j["path_radius_m"].is_null()) os << "  " << std::left << std::setw(22) << "path radius" << std::right << std::setw(14) << "inf" << " m\n";
  else row("path radius", j["path_radius_m"], "m");
  row("lateral acceleration", j["lateral_acceleration_mps2"], "m/s^2");
  for (const auto& [name, value] : j["tyres"].items()) row(name, value.get<double>(), "");
  row("residual", j["residual"], "");
  return os.str();
}

nlohmann::json makeHandsFreeJson(const VehicleModel& model, const std::vector<HandsFreeTurn>& turns, size_t defaultIndex) {
  nlohmann::json list = nlohmann::json::array();
  for (size_t i = 0; i < turns.size(); ++i) {
    nlohmann::json t = makeTrimJson(model, restoreTrim(model, turns[i].trim));
    t["continues_from_straight_running"] = turns[i].continuesFromStraight;
    t["default"] = i == defaultIndex;
    list.push_back(t);
  }
  nlohmann::json j = makeTrimJson(model, restoreTrim(model, turns.at(defaultIndex).trim));
  j["continues_from_straight_running"] = turns[defaultIndex].continuesFromStraight;
  j["hands_free_turns"] = list;
  return j;
}

void writeHandsFreeJson(const std::filesystem::path& dir, const VehicleModel& model, const std::vector<HandsFreeTurn>& turns,
                        size_t defaultIndex) {
  writeFileAtomically(dir / "trim.json", makeHandsFreeJson(model, turns, defaultIndex).dump(2) + "\n");
}

std::string formatHandsFreeTable(const VehicleModel& model, const std::vector<HandsFreeTurn>& turns, size_t defaultIndex) {
  constexpr double kDeg = 180 / M_PI;
  std::ostringstream os;
  os << "  " << std::setw(12) << "speed (m/s)" << std::setw(13) << "steer (deg)" << std::setw(20) << "steer torque (N m)"
     << std::setw(17) << "path radius (m)" << "  from straight running\n";
  for (size_t i = 0; i < turns.size(); ++i) {
    const nlohmann::json j = makeTrimJson(model, restoreTrim(model, turns[i].trim));
    os << (i == defaultIndex ? "* " : "  ") << std::setprecision(6) << std::setw(12) << j["speed_mps"].get<double>()
       << std::setw(13) << j["steer_rad"].get<double>() * kDeg << std::setw(20) << j["steer_torque_Nm"].get<double>()
       << std::setw(17) << (j["path_radius_m"].is_null() ? INFINITY : j["path_radius_m"].get<double>()) << "  "
       << (turns[i].continuesFromStraight ? "yes" : "no") << "\n";
  }
  os << "  (* the default: the turn continuing from straight running, or the one nearest --speed)\n";
  return os.str();
}

}  // namespace motostab::output

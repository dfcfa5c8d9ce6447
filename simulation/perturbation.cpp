#include "simulation/perturbation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "io/csv.h"
#include "io/input_error.h"
#include "io/number.h"

namespace motostab::simulation {

using io::InputError;
using io::parseFiniteNumber;
using io::splitFields;


namespace {

[[noreturn]] void fail(const std::string& spec, const std::string& why) {
  throw InputError({"command line", 0, 0, "--perturb"}, "'" + spec + "': " + why + "\n  expected one of:\n" + getPerturbationSyntax());
}

double parseNumber(const std::string& spec, const std::string& field, const std::string& what) {
  const auto v = parseFiniteNumber(field);
  if (!v) fail(spec, what + " '" + field + "' is not a finite number");
  return *v;
}

void checkFieldCount(const std::string& spec, const std::vector<std::string>& f, size_t lo, size_t hi) {
  if (f.size() < lo || f.size() > hi) {
    std::ostringstream os;
    os << "'" << f[0] << "' takes " << lo - 1;
    if (hi != lo) os << " or " << hi - 1;
    os << " fields after the kind, got " << f.size() - 1;
    fail(spec, os.str());
  }
}

void parsePulse(const std::string& spec, const std::vector<std::string>& f, size_t first, Perturbation& p) {
  p.amplitude = parseNumber(spec, f[first], "amplitude");
  p.start = parseNumber(spec, f[first + 1], "start time");
  p.duration = parseNumber(spec, f[first + 2], "duration");
  if (p.start < 0) fail(spec, "start time must be >= 0");
  if (!(p.duration > 0)) fail(spec, "duration must be > 0");
  if (f.size() > first + 3) {
    const std::string& shape = f[first + 3];
    if (shape == "halfsine") p.shape = PulseShape::HalfSine;
    else if (shape == "rect" || shape == "rectangular") p.shape = PulseShape::Rectangular;
    else fail(spec, "unknown pulse shape '" + shape + "' (halfsine or rect)");
  }
}

}  // namespace

std::string getPerturbationSyntax() {
  return "    steer-torque:AMPLITUDE_Nm:START_s:DURATION_s[:halfsine|:rect]\n"
         "    lateral-force:BODY:AMPLITUDE_N:START_s:DURATION_s[:halfsine|:rect]"
         "  (BODY: rear_frame, front_frame, rear_wheel, front_wheel)\n"
         "    roll-rate:VALUE_rad_per_s\n"
         "    steer-rate:VALUE_rad_per_s\n"
         "    road-step:WHEEL:OFFSET_m:START_s  (WHEEL: rear_wheel, front_wheel; force-based tyres only)";
}

double Perturbation::calcPulseValue(double t) const {
  if (shape == PulseShape::HalfSine) return amplitude * std::sin(M_PI * (t - start) / duration);
  return amplitude;
}

std::vector<double> Perturbation::getSwitchTimes() const {
  if (!isPulse()) return {};
  return {start, start + duration};
}

Perturbation parsePerturbation(const std::string& spec) {
  const auto f = splitFields(spec, ':');
  if (f.empty() || f[0].empty()) fail(spec, "empty perturbation");
  Perturbation p;
  p.spec = spec;
  const std::string& kind = f[0];
  if (kind == "steer-torque") {
    p.kind = PerturbationKind::SteerTorque;
    checkFieldCount(spec, f, 4, 5);
    parsePulse(spec, f, 1, p);
  } else if (kind == "lateral-force") {
    p.kind = PerturbationKind::LateralForce;
    checkFieldCount(spec, f, 5, 6);
    p.body = f[1];
    if (p.body != "rear_frame" && p.body != "front_frame" && p.body != "rear_wheel" && p.body != "front_wheel")
      fail(spec, "unknown body '" + p.body + "'");
    parsePulse(spec, f, 2, p);
  } else if (kind == "roll-rate" || kind == "steer-rate") {
    p.kind = kind == "roll-rate" ? PerturbationKind::RollRate : PerturbationKind::SteerRate;
    checkFieldCount(spec, f, 2, 2);
    p.amplitude = parseNumber(spec, f[1], "rate");
  } else if (kind == "road-step") {
    p.kind = PerturbationKind::RoadStep;
    checkFieldCount(spec, f, 4, 4);
    p.body = f[1];
    if (p.body != "rear_wheel" && p.body != "front_wheel") fail(spec, "unknown wheel '" + p.body + "'");
    p.wheel = p.body == "front_wheel" ? plugins::WheelSide::Front : plugins::WheelSide::Rear;
    p.amplitude = parseNumber(spec, f[2], "offset");
    p.start = parseNumber(spec, f[3], "start time");
    if (p.start < 0) fail(spec, "start time must be >= 0");
  } else {
    fail(spec, "unknown perturbation kind '" + kind + "'");
  }
  return p;
}

double getFreeResponseStart(const std::vector<Perturbation>& perturbations) {
  double t = 0;
  for (const auto& p : perturbations)
    if (p.isPulse()) t = std::max(t, p.start + p.duration);
  return t;
}

}  // namespace motostab::simulation

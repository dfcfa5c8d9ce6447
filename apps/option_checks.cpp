#include "apps/option_checks.h"

#include <cmath>
#include <sstream>

#include "io/csv.h"
#include "io/number.h"
#include "io/result_error.h"
#include "scenario/scenario.h"

namespace motostab::cli {

using io::InputError;
using io::InputLocation;

namespace {
constexpr double kMaxRollDeg = 89;
constexpr int kMaxThreads = 256;
}  // namespace

std::string NumberRange::describe() const {
  std::ostringstream os;
  os << (excludeLow ? "(" : "[") << low << ", " << high << "]";
  return os.str();
}

void checkNumber(double value, const NumberRange& range, const InputLocation& where) {
  if (!range.contains(value)) throw InputError(where, "expected a finite number in " + range.describe());
}

void checkSpeedRange(double start, double stop, double step, const InputLocation& where) {
  std::string why;
  scenario::countSpeeds(start, stop, step, why);
  if (!why.empty()) throw InputError(where, "START:STOP:STEP " + why);
}

void checkMapPoints(double start, double stop, double step, size_t rolls, const InputLocation& speedsWhere) {
  std::string why;
  const long speeds = scenario::countSpeeds(start, stop, step, why);
  if (!why.empty()) throw InputError(speedsWhere, "START:STOP:STEP " + why);
  const double points = static_cast<double>(speeds) * static_cast<double>(rolls);
  if (points > kMaxMapPoints)
    throw InputError(speedsWhere, "a speed x roll map of " + std::to_string(speeds) + " speeds x " + std::to_string(rolls) +
                                      " roll angles (--roll-deg) has " + io::formatNumber(points, 6) + " points; at most " +
                                      std::to_string(kMaxMapPoints) + " (each keeps a trim and a linear model): fewer "
                                      "speeds or roll angles");
}

bool isRollInRange(double deg) { return std::abs(deg) < kMaxRollDeg; }

void checkRoll(double deg, const InputLocation& where) {
  if (!isRollInRange(deg)) throw InputError(where, "not a roll angle strictly between -89 and 89 deg");
}

std::vector<double> makeRollAngles(double first, double last, double step, const InputLocation& where) {
  std::vector<double> out;
  if (isRollInRange(first) && isRollInRange(last) && last >= first && step > 0 && std::isfinite(step) &&
      (last - first) / step <= 1000) {
    const long n = static_cast<long>(std::floor((last - first) / step + 1e-9));
    for (long i = 0; i <= n; ++i) out.push_back((first + i * step) * M_PI / 180);
  }
  if (out.empty())
    throw InputError(where,
                     "expected PHI or A:B:STEP in degrees, each strictly between -89 and 89, with B >= A, STEP > 0 "
                     "and at most 1000 angles");
  return out;
}

void checkTurnSpeeds(double slowest, const InputLocation& where) {
  if (slowest > 0) return;
  throw InputError(where, "steady turns (--roll-deg) need speeds above 0 m/s: start the speed grid above 0, e.g. --speeds 1:40:1");
}

void checkThreads(int threads, const InputLocation& where) {
  if (threads < 1 || threads > kMaxThreads) throw InputError(where, "worker threads: expected 1 to 256");
}

std::vector<std::string> labelModesOfModel(const analysis::LinearModel& lin) {
  std::vector<std::string> labels;
  for (const analysis::ModeLabel label : lin.labels.empty() ? analysis::labelModes(lin) : lin.labels)
    labels.push_back(analysis::toString(label));
  return labels;
}

std::vector<analysis::HandsFreeTurn> calcHandsFreeTurns(const vehicle::VehicleModel& model, double start, double stop,
                                                       double step, const analysis::TrimOptions& options,
                                                       const InputLocation& rollWhere, const InputLocation& speedsWhere) {
  std::vector<double> speeds;
  for (double v : analysis::makeSpeedGrid(start, stop, step))
    if (v > 0) speeds.push_back(v);
  const bool upright = !options.isTurn() || options.roll == 0;
  if (speeds.size() < 2 || upright)
    throw InputError(upright ? rollWhere : speedsWhere,
                     "a hands-free turn needs a nonzero roll and at least two positive speeds to search");
  try {
    return analysis::calcHandsFreeTurns(model, speeds, options);
  } catch (const analysis::NoTurnError& e) {
    // valid input, no turn: a result error (exit 3) with what to try
    throw io::ResultError(std::string(e.what()) + "; widen " + speedsWhere.key + " or change " + rollWhere.key);
  }
}

void checkStudyOptions(const studies::StudyOptions& opt, const InputLocation& shapeWhere, const InputLocation& speedsWhere) {
  for (const double v : opt.shapeSpeeds)
    if (v < opt.sweep.start || v > opt.sweep.stop) {
      InputLocation where = shapeWhere;
      if (where.key.empty()) where.key = std::to_string(v);
      throw InputError(where, "a mode-shape speed must lie within the swept speeds " + std::to_string(opt.sweep.start) +
                                  " to " + std::to_string(opt.sweep.stop) + " m/s");
    }
  if (opt.sweep.trim.isTurn()) checkTurnSpeeds(opt.sweep.start, speedsWhere);
}

simulation::SimulationOptions makeSimulationOptions(simulation::SimulationOptions o, const std::vector<std::string>& perturbations,
                                                    const std::string& speedControl, const std::string& integrator,
                                                    double fallLimitDeg, double rollDeg) {
  for (const auto& spec : perturbations) o.perturbations.push_back(simulation::parsePerturbation(spec));
  o.speedControl = simulation::parseSpeedControl(speedControl);
  o.integrator = simulation::parseIntegratorKind(integrator);
  o.fallRollLimit = fallLimitDeg * M_PI / 180;
  if (rollDeg != 0) {
    if (!(o.speed > 0)) throw InputError({"command line", 0, 0, "--speed"}, "a steady turn (--roll-deg) needs a speed above 0 m/s");
    o.trim.roll = rollDeg * M_PI / 180;
  }
  return o;
}

uncertainty::SamplingMethod parseSamplingMethod(const std::string& name, const InputLocation& where) {
  if (name == "mc") return uncertainty::SamplingMethod::MonteCarlo;
  if (name == "sobol") return uncertainty::SamplingMethod::Sobol;
  throw InputError(where, "expected mc or sobol");
}

std::vector<double> makeSlipAngles(double first, double last, double step, const InputLocation& where) {
  const bool ok = std::isfinite(first) && std::isfinite(last) && std::isfinite(step) && last >= first && step > 0 &&
                  (last - first) / step <= 1e5;
  if (!ok)
    throw InputError(where, "expected A:B:STEP in degrees, finite, with A <= B, STEP > 0 and at most 1e5 points");
  std::vector<double> out;
  const int n = static_cast<int>(std::floor((last - first) / step + 1e-9));
  for (int i = 0; i <= n; ++i) out.push_back(first + i * step);
  return out;
}

TirForceLaw loadTirForCurve(const std::string& path, std::ostream& warnings) {
  TirForceLaw t{tyres::TirFile::load(path), nullptr};
  const auto source = tyres::makeTirSource(t.file, nullptr);
  t.law = tyres::makeTyreForceLaw(t.file.getFitType() == 62 ? tyres::MagicFormulaVariant::MF62 : tyres::MagicFormulaVariant::MF61,
                                  *source);
  const std::string unused = tyres::describeUnused(*source, path);
  if (!unused.empty()) warnings << "warning: " << unused << "\n";
  return t;
}

std::vector<output::TyreCurvePoint> calcTyreCurve(const tyres::TyreForceLaw& law, double fz, const std::vector<double>& slipDeg,
                                                  double camber, double slipRatio, double speed) {
  std::vector<output::TyreCurvePoint> points;
  for (double deg : slipDeg) {
    output::TyreCurvePoint p;
    p.slip = {fz, slipRatio, deg * M_PI / 180, camber, speed};
    p.forces = law.calcForces(p.slip);
    const auto& f = p.forces;
    for (const auto& [name, v] : {std::pair{"Fx", f.Fx}, {"Fy", f.Fy}, {"Mx", f.Mx}, {"My", f.My}, {"Mz", f.Mz}})
      if (!std::isfinite(v))  // outputs are checked before they are written
        throw io::ResultError("the tyre law gives " + std::string(name) + " = " + io::formatNumber(v, 6) +
                              " at slip angle " + io::formatNumber(deg, 6) + " deg: its coefficients give no finite force there");
    points.push_back(p);
  }
  return points;
}

}  // namespace motostab::cli

// Sampled outputs of a simulation and the integration loop that produces them on the output grid.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "io/input_error.h"
#include "simulation/simulation_detail.h"

namespace motostab::simulation::detail {

using io::InputError;
using vehicle::Input;
using vehicle::VehicleModel;

using SimTK::State;

std::vector<std::string> listColumns(const VehicleModel& model, const SimulationOptions& opt) {
  std::vector<std::string> columns{"time"};
  for (const auto& n : model.getQNames()) columns.push_back(n);
  for (const auto& n : model.getUNames()) columns.push_back(n);
  for (const auto& n : model.getZNames()) columns.push_back(n);
  for (const char* n : {"steer_torque", "drive_torque", "lateral_force", "forward_speed", "energy"}) columns.push_back(n);
  for (const auto& n : model.getContactOutputNames()) columns.push_back(n);
  for (const auto& n : model.getExtensionOutputNames()) columns.push_back(n);
  for (const auto& c : opt.extraOutputs) columns.push_back(c.name);
  return columns;
}

std::vector<double> SampleRecorder::makeRow(double t, const SimTK::Vector& y, int segment) {
  w_.setTime(t);
  w_.updY() = y;
  force_.setSegment(w_, segment);
  model_.getSystem().realize(w_, SimTK::Stage::Dynamics);
  std::vector<double> row{t};
  for (int i = 0; i < w_.getNQ(); ++i) row.push_back(w_.getQ()[i]);
  for (int i = 0; i < w_.getNU(); ++i) row.push_back(w_.getU()[i]);
  for (int i = 0; i < w_.getNZ(); ++i) row.push_back(w_.getZ()[i]);
  row.push_back(model_.getInput(w_, Input::SteerTorque) + force_.calcPulses(w_, PerturbationKind::SteerTorque));
  row.push_back(model_.getInput(w_, Input::DriveTorque) + force_.calcControlTorque(w_));
  row.push_back(force_.calcPulses(w_, PerturbationKind::LateralForce));
  row.push_back(calcHeadingSpeed(model_, w_));
  row.push_back(model_.getSystem().calcEnergy(w_));
  for (double v : model_.calcContactOutputs(w_)) row.push_back(v);
  for (double v : model_.calcExtensionOutputs(w_)) row.push_back(v);
  for (const auto& c : opt_.extraOutputs) row.push_back(c.calc(model_, w_));
  return row;
}

/// Appends a sample; false when the run ends there (non-finite state or a fall).
bool SampleRecorder::record(double t, const SimTK::Vector& y, int segment) {
  res_.rows.push_back(makeRow(t, y, segment));
  res_.endTime = t;
  const double roll = res_.rows.back()[rollColumn_];
  for (double v : res_.rows.back())
    if (!std::isfinite(v)) {
      res_.status = SimulationStatus::Failed;
      res_.message = "the state became non-finite at t = " + std::to_string(t) + " s";
      return false;
    }
  if (std::abs(roll) > opt_.fallRollLimit) {
    std::ostringstream os;
    os << "fell: |roll| = " << std::abs(roll) * 180 / M_PI << " deg exceeds the limit "
       << opt_.fallRollLimit * 180 / M_PI << " deg at t = " << t << " s";
    res_.status = SimulationStatus::Fell;
    res_.message = os.str();
    return false;
  }
  if (opt_.progress) opt_.progress(t);
  return true;
}

StepperOptions makeStepperOptions(const VehicleModel& model, const SimulationOptions& opt, const State& s) {
  StepperOptions so;
  so.kind = opt.integrator;
  so.accuracy = opt.accuracy;
  so.constraintTolerance = opt.constraintTolerance;
  so.projectEveryStep = opt.projectEveryStep;
  so.maxStep = opt.maxStep;
  so.cyclicY = model.getCyclicQ();  // y starts with q
  if (resolveIntegratorKind(so.kind, s) == IntegratorKind::Rosenbrock && hasConstraints(s))
    throw InputError({"command line", 0, 0, "--integrator"},
                     "ROS34PW2 integrates models without constraints only (force-based tyres); this model has "
                     "rolling constraints: use auto or RungeKuttaMerson");
  return so;
}

// Integrates to opt.duration, recording samples on the output grid from cubic Hermite interpolation
// of y between internal steps (y and ydot at both ends; the same order as Simbody's own
// interpolation, without its State copies), and switching segments at their starts.
void integrate(Stepper& integ, const VehicleModel& model, const PerturbationForce& force, const SimulationOptions& opt,
               const std::vector<double>& segmentStarts, SampleRecorder& recorder) {
  int segment = 0, nextReport = 1;
  const int reports = static_cast<int>(std::ceil(opt.duration / opt.outputStep - 1e-9));
  auto getReportTime = [&](int k) { return std::min(k * opt.outputStep, opt.duration); };
  double t0 = integ.getTime();
  SimTK::Vector y0 = integ.getY(), yd0 = integ.getYDot();
  bool running = recorder.record(t0, y0, segment);
  SimTK::Vector y(y0.size());
  while (running && nextReport <= reports) {
    const double tEvent = segment + 1 < static_cast<int>(segmentStarts.size()) ? segmentStarts[segment + 1]
                                                                               : SimTK::Infinity;
    integ.step(opt.duration, tEvent);
    const double t1 = integ.getTime();
    if (!(t1 > t0)) continue;
    const SimTK::Vector& y1 = integ.getY();
    const SimTK::Vector& yd1 = integ.getYDot();
    const double h = t1 - t0, eps = 1e-12 * std::max(1.0, t1);
    // Samples strictly inside the step (a sample at t1 waits for a pulse switch at t1).
    for (double tr; running && nextReport <= reports && (tr = getReportTime(nextReport)) < t1 - eps; ++nextReport) {
      const double x = (tr - t0) / h, x2 = x * x, x3 = x2 * x;
      for (int i = 0; i < y.size(); ++i)
        y[i] = (2 * x3 - 3 * x2 + 1) * y0[i] + (x3 - 2 * x2 + x) * h * yd0[i] + (3 * x2 - 2 * x3) * y1[i] +
               (x3 - x2) * h * yd1[i];
      running = recorder.record(tr, y, segment);
    }
    t0 = t1, y0 = y1, yd0 = yd1;
    if (t1 >= tEvent) {  // switch pulses on or off (samples are right-continuous)
      force.setSegment(integ.updState(), ++segment);
      applyRoadSteps(model, integ.updState(), opt.perturbations, segmentStarts[segment]);
      integ.reinitialize();
      y0 = integ.getY(), yd0 = integ.getYDot();
    }
    if (running && nextReport <= reports && getReportTime(nextReport) <= t1 + eps) {
      running = recorder.record(getReportTime(nextReport), integ.getY(), segment);  // after any road step
      ++nextReport;
    }
  }
}

}  // namespace motostab::simulation::detail

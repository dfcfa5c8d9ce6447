#include "simulation/simulation.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <memory>
#include <sstream>

#include "analysis/linearize.h"
#include "analysis/state_function.h"
#include "io/csv.h"
#include "io/input_error.h"

namespace motostab::simulation {

using analysis::StateFunction;
using analysis::TrimResult;
using analysis::calcTrim;
using analysis::chooseDependentColumns;
using io::InputError;
using io::extractColumn;
using plugins::BuildContext;
using plugins::PluginRegistry;
using plugins::makeBuiltinRegistry;
using scenario::Scenario;
using scenario::calcMassSummary;
using vehicle::CoordinateIndices;
using vehicle::Input;
using vehicle::ModelExtension;
using vehicle::VehicleModel;

using SimTK::State;
using SimTK::Vec3;

namespace {

/// Rear wheel centre velocity along the heading (yaw) direction, m/s.
double calcHeadingSpeed(const VehicleModel& model, const State& s) {
  const CoordinateIndices& ix = model.getIndices();
  const double yaw = s.getQ()[ix.yaw];
  return std::cos(yaw) * s.getU()[ix.x] + std::sin(yaw) * s.getU()[ix.y];
}

// Time-varying perturbation forces and the PI speed controller as one Force::Custom element.
// Pulses switch on and off only between integration segments (a discrete variable holds the
// segment index), so no integrator step straddles a discontinuity.
class PerturbationForce : public SimTK::Force::Custom::Implementation {
 public:
  PerturbationForce(SimTK::GeneralForceSubsystem& forces, const VehicleModel& model, std::vector<Perturbation> pulses,
                    std::vector<double> segmentStarts, bool speedControl, double kp, double ki, double targetSpeed)
      : forces_(forces), model_(model), pulses_(std::move(pulses)), segmentStarts_(std::move(segmentStarts)),
        speedControl_(speedControl), kp_(kp), ki_(ki), targetSpeed_(targetSpeed) {}

  void realizeTopology(State& s) const override {
    segmentIndex_ = forces_.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<int>(0));
    if (speedControl_) zIndex_ = forces_.allocateZ(s, SimTK::Vector(1, 0.0));
  }

  void setSegment(State& s, int k) const {
    SimTK::Value<int>::updDowncast(forces_.updDiscreteVariable(s, segmentIndex_)) = k;
  }

  int getSegment(const State& s) const {
    return SimTK::Value<int>::downcast(forces_.getDiscreteVariable(s, segmentIndex_));
  }

  /// Sum of the active pulses of `kind` (on `body` for lateral forces, "" = any body).
  double calcPulses(const State& s, PerturbationKind kind, const std::string& body = "") const {
    const double t0 = segmentStarts_[getSegment(s)];  // pulses are constant in on/off state over a segment
    double sum = 0;
    for (const auto& p : pulses_)
      if (p.kind == kind && (body.empty() || p.body == body) && p.start <= t0 && t0 < p.start + p.duration)
        sum += p.calcPulseValue(s.getTime());
    return sum;
  }

  /// Controller part of the drive torque, N m (0 without speed control).
  double calcControlTorque(const State& s) const {
    if (!speedControl_) return 0;
    return kp_ * (targetSpeed_ - calcHeadingSpeed(model_, s)) + ki_ * forces_.getZ(s)[zIndex_];
  }

  void calcForce(const State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces, SimTK::Vector_<Vec3>&,
                 SimTK::Vector& mobilityForces) const override {
    const double tau = calcPulses(s, PerturbationKind::SteerTorque);
    if (tau != 0) model_.getFrontFrame().applyOneMobilityForce(s, 0, tau, mobilityForces);
    for (const char* name : {"rear_frame", "front_frame", "rear_wheel", "front_wheel"}) {
      const double f = calcPulses(s, PerturbationKind::LateralForce, name);
      if (f == 0) continue;
      const SimTK::MobilizedBody& b = getBody(name);
      b.applyForceToBodyPoint(s, b.getBodyMassCenterStation(s), Vec3(0, f, 0), bodyForces);
    }
    if (speedControl_) {
      model_.getRearWheel().applyOneMobilityForce(s, 0, calcControlTorque(s), mobilityForces);
      forces_.updZDot(s)[zIndex_] = targetSpeed_ - calcHeadingSpeed(model_, s);
    }
  }
  SimTK::Real calcPotentialEnergy(const State&) const override { return 0; }

 private:
  const SimTK::MobilizedBody& getBody(const std::string& name) const {
    if (name == "rear_frame") return model_.getRearFrame();
    if (name == "front_frame") return model_.getFrontFrame();
    if (name == "rear_wheel") return model_.getRearWheel();
    return model_.getFrontWheel();
  }

  SimTK::GeneralForceSubsystem& forces_;
  const VehicleModel& model_;  // complete by the time forces are evaluated
  std::vector<Perturbation> pulses_;
  std::vector<double> segmentStarts_;
  bool speedControl_;
  double kp_, ki_, targetSpeed_;
  mutable SimTK::DiscreteVariableIndex segmentIndex_;
  mutable SimTK::ZIndex zIndex_;
};

void checkOptions(const SimulationOptions& o) {
  auto bad = [](const std::string& key, const std::string& why) { throw InputError({"command line", 0, 0, key}, why); };
  if (!(o.speed >= 0) || !std::isfinite(o.speed)) bad("--speed", "must be a finite speed >= 0 m/s");
  if (!(o.duration > 0) || !std::isfinite(o.duration)) bad("--duration", "must be > 0 s");
  if (!(o.outputStep > 0)) bad("--output-step", "must be > 0 s");
  if (!(o.accuracy > 0 && o.accuracy < 1)) bad("--accuracy", "must be in (0, 1)");
  if (!(o.maxStep >= 0)) bad("maxStep", "must be >= 0 s (0: the integrator's default)");
  if (!(o.fallRollLimit > 0)) bad("--fall-limit", "must be > 0");
}

}  // namespace

SpeedControl parseSpeedControl(const std::string& name) {
  const std::string n = toLowerCase(name);
  if (n == "none") return SpeedControl::None;
  if (n == "pi") return SpeedControl::PI;
  throw InputError({"command line", 0, 0, "--speed-control"}, "unknown speed control '" + name + "' (none or pi)");
}

int SimulationResult::getColumnIndex(const std::string& name) const {
  for (size_t j = 0; j < columns.size(); ++j)
    if (columns[j] == name) return static_cast<int>(j);
  throw std::out_of_range("simulation result has no column '" + name + "'");
}

std::vector<double> SimulationResult::getColumn(const std::string& name) const {
  return extractColumn(rows, getColumnIndex(name));
}

void checkPerturbations(const VehicleModel& model, const std::vector<Perturbation>& perturbations) {
  const std::string& contact = model.getScenario().contact.model;
  for (const auto& p : perturbations) {
    if (p.kind != PerturbationKind::RoadStep) continue;
    SimTK::State probe = model.getDefaultState();
    if (model.applyLateralRoadStep(probe, p.body, p.amplitude)) continue;
    if (contact == "rolling_no_slip")
      throw InputError({"command line", 0, 0, "--perturb"}, "'" + p.spec + "': needs a force-based tyre model; the contact model "
                                                "'rolling_no_slip' is a rolling constraint without lateral compliance");
    throw InputError({"command line", 0, 0, "--perturb"},
                     "'" + p.spec + "': the contact model '" + contact + "' takes no road displacement input under " + p.body +
                         " (a relaxation_linear tyre needs a relaxation length > 0)");
  }
}

// Applies the road steps that start at time t (s).
void applyRoadSteps(const VehicleModel& model, State& s, const std::vector<Perturbation>& perturbations, double t) {
  for (const auto& p : perturbations)
    if (p.kind == PerturbationKind::RoadStep && std::abs(p.start - t) < 1e-12) model.applyLateralRoadStep(s, p.body, p.amplitude);
}

void applyInitialRates(const VehicleModel& model, State& s, const std::vector<Perturbation>& perturbations) {
  const CoordinateIndices& ix = model.getIndices();
  double dRoll = 0, dSteer = 0;
  for (const auto& p : perturbations) {
    if (p.kind == PerturbationKind::RollRate) dRoll += p.amplitude;
    if (p.kind == PerturbationKind::SteerRate) dSteer += p.amplitude;
  }
  if (dRoll == 0 && dSteer == 0) return;
  s.updU()[ix.roll] += dRoll;
  s.updU()[ix.steer] += dSteer;

  // Velocity errors are affine in u: unit differences give their exact Jacobian G.
  const StateFunction fn(model);
  Eigen::VectorXd err0, err;
  fn.calcConstraintErrors(s, err0);
  const int mp = s.getNQErr(), mv = static_cast<int>(err0.size()) - mp, nu = model.getNumU();
  if (mv == 0) return;
  Eigen::MatrixXd G(mv, nu);
  for (int j = 0; j < nu; ++j) {
    const double base = s.getU()[j];
    s.updU()[j] = base + 1.0;
    fn.calcConstraintErrors(s, err);
    s.updU()[j] = base;
    G.col(j) = (err - err0).tail(mv);
  }
  // Dependent rates, greedily in priority order keeping full rank; roll, steer and x rates stay.
  std::vector<int> priority{ix.height, ix.pitch, ix.rearSpin, ix.frontSpin, ix.y, ix.yaw};
  for (int j = 0; j < nu; ++j)
    if (j != ix.roll && j != ix.steer && j != ix.x && std::find(priority.begin(), priority.end(), j) == priority.end())
      priority.push_back(j);
  const std::vector<int> dep = chooseDependentColumns(G, priority);
  if (static_cast<int>(dep.size()) != mv)
    throw std::runtime_error("initial rates: the velocity constraints cannot be solved for the dependent rates");
  Eigen::MatrixXd Gdep(mv, mv);
  for (int k = 0; k < mv; ++k) Gdep.col(k) = G.col(dep[k]);
  const Eigen::VectorXd du = Gdep.partialPivLu().solve(-err0.tail(mv));
  for (int k = 0; k < mv; ++k) s.updU()[dep[k]] += du[k];
  fn.calcConstraintErrors(s, err);
  if (err.tail(mv).lpNorm<Eigen::Infinity>() > 1e-9)
    throw std::runtime_error("initial rates: velocity constraint error remains after the solve");
}

SimulationResult runSimulation(const Scenario& scenario, const SimulationOptions& options) {
  PluginRegistry registry = makeBuiltinRegistry();
  return runSimulation(scenario, registry, options);
}

namespace {

// Segment boundaries: pulse switch times and road-step times inside (0, duration), from 0. Switch
// times closer than 1e-12 s (e.g. 0.1 + 0.2 and 0.3) are one switch, at the later time: a pulse
// ending there is then off, and a road step there is applied once.
std::vector<double> calcSegmentStarts(const SimulationOptions& opt) {
  std::vector<double> segmentStarts{0.0};
  for (const auto& p : opt.perturbations)
    if (p.isPulse())
      for (double t : p.getSwitchTimes())
        if (t > 0 && t < opt.duration) segmentStarts.push_back(t);
  for (const auto& p : opt.perturbations)
    if (p.kind == PerturbationKind::RoadStep && p.start > 0 && p.start < opt.duration) segmentStarts.push_back(p.start);
  std::sort(segmentStarts.begin(), segmentStarts.end());
  std::vector<double> merged;
  for (double t : segmentStarts)
    if (!merged.empty() && t - merged.back() < 1e-12) merged.back() = t;
    else merged.push_back(t);
  return merged;
}

std::vector<Perturbation> listPulses(const SimulationOptions& opt) {
  std::vector<Perturbation> pulses;
  for (const auto& p : opt.perturbations)
    if (p.isPulse()) pulses.push_back(p);
  return pulses;
}

// The trim of the bare model carried over to the model with the perturbation force: q, u, the
// contact states and the trim inputs, at time 0 in segment 0.
State makeInitialState(const VehicleModel& model, const VehicleModel& trimModel, const TrimResult& trim,
                       const PerturbationForce& force) {
  State s = model.getDefaultState();
  s.updQ() = trim.state.getQ();
  s.updU() = trim.state.getU();
  for (int i = 0; i < trimModel.getNumZ(); ++i) s.updZ()[i] = trim.state.getZ()[i];
  for (Input in : {Input::SteerTorque, Input::DriveTorque, Input::RollTorque})
    model.setInput(s, in, trimModel.getInput(trim.state, in));
  s.setTime(0);
  force.setSegment(s, 0);
  return s;
}

std::vector<std::string> listColumns(const VehicleModel& model, const SimulationOptions& opt) {
  std::vector<std::string> columns{"time"};
  for (const auto& n : model.getQNames()) columns.push_back(n);
  for (const auto& n : model.getUNames()) columns.push_back(n);
  for (const auto& n : model.getZNames()) columns.push_back(n);
  for (const char* n : {"steer_torque", "drive_torque", "lateral_force", "forward_speed", "energy"}) columns.push_back(n);
  for (const auto& n : model.getContactOutputNames()) columns.push_back(n);
  if (model.hasSteerController()) columns.push_back("steer_controller_torque");
  for (const auto& c : opt.extraOutputs) columns.push_back(c.name);
  return columns;
}

// Output rows from sampled states, evaluated on one working State (assigning y costs less than
// copying a State); record() also ends the run on a non-finite value or a fall.
class SampleRecorder {
 public:
  SampleRecorder(const VehicleModel& model, const PerturbationForce& force, const SimulationOptions& opt,
                 const State& s, SimulationResult& res)
      : model_(model), force_(force), opt_(opt), w_(s), res_(res) {}

  std::vector<double> makeRow(double t, const SimTK::Vector& y, int segment) {
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
    if (model_.hasSteerController()) row.push_back(model_.calcSteerControllerTorque(w_));
    for (const auto& c : opt_.extraOutputs) row.push_back(c.calc(model_, w_));
    return row;
  }

  /// Appends a sample; false when the run ends there (non-finite state or a fall).
  bool record(double t, const SimTK::Vector& y, int segment) {
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

 private:
  const VehicleModel& model_;
  const PerturbationForce& force_;
  const SimulationOptions& opt_;
  State w_;
  SimulationResult& res_;
  const int rollColumn_ = res_.getColumnIndex("roll");
};

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

}  // namespace

SimulationResult runSimulation(const Scenario& scenario, PluginRegistry& registry, const SimulationOptions& opt) {
  checkOptions(opt);
  // The trim runs on the bare model: the controller's integral state would make it singular.
  PluginRegistry trimRegistry = registry;  // a copy: the caller's registry gains the libraries below
  const VehicleModel trimModel(scenario, trimRegistry);
  checkPerturbations(trimModel, opt.perturbations);
  const TrimResult trim = calcTrim(trimModel, opt.speed, opt.trim);

  const std::vector<Perturbation> pulses = listPulses(opt);
  const std::vector<double> segmentStarts = calcSegmentStarts(opt);
  const bool control = opt.speedControl == SpeedControl::PI;
  const double massRadius = calcMassSummary(scenario).mass * scenario.rearWheel.radius;
  const PerturbationForce* force = nullptr;
  ModelExtension extension = [&](BuildContext& ctx, const VehicleModel& m) {
    auto* impl = new PerturbationForce(ctx.forces, m, pulses, segmentStarts, control, opt.speedGainP * massRadius,
                                       opt.speedGainI * massRadius,
                                       trim.turn ? calcHeadingSpeed(trimModel, trim.state) : opt.speed);
    SimTK::Force::Custom(ctx.forces, impl);  // the subsystem owns impl
    force = impl;
    return control ? std::vector<std::string>{"speed_control_integral"} : std::vector<std::string>{};
  };
  const VehicleModel model(scenario, registry, {extension});

  State s = makeInitialState(model, trimModel, trim, *force);
  SimulationResult res;
  res.columns = listColumns(model, opt);
  res.numQ = model.getNumQ();
  SampleRecorder recorder(model, *force, opt, s, res);
  res.trimRow = recorder.makeRow(0, s.getY(), 0);
  applyInitialRates(model, s, opt.perturbations);
  applyRoadSteps(model, s, opt.perturbations, 0.0);

  const auto wall0 = std::chrono::steady_clock::now();
  const StepperOptions so = makeStepperOptions(model, opt, s);
  std::unique_ptr<Stepper> integ;
  try {
    integ = makeStepper(model.getSystem(), s, so);
    res.integrator = integ->getName();
    integrate(*integ, model, *force, opt, segmentStarts, recorder);
  } catch (const std::exception& e) {
    res.status = SimulationStatus::Failed;
    std::ostringstream os;
    os << "integration failed after t = " << res.endTime << " s: " << e.what();
    res.message = os.str();
  }
  res.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  if (integ) res.steps = integ->getNumSteps();
  return res;
}

}  // namespace motostab::simulation

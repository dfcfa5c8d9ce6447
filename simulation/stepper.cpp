#include "simulation/stepper.h"

#include <algorithm>
#include <cctype>

#include "io/input_error.h"
#include "simulation/rosenbrock.h"

namespace motostab::simulation {

using io::InputError;


std::string toLowerCase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

IntegratorKind parseIntegratorKind(const std::string& name) {
  const std::string n = toLowerCase(name);
  if (n == "auto") return IntegratorKind::Auto;
  if (n == "ros34pw2" || n == "rosenbrock") return IntegratorKind::Rosenbrock;
  if (n == "rkm" || n == "rungekuttamerson") return IntegratorKind::RungeKuttaMerson;
  if (n == "rk3" || n == "rungekutta3") return IntegratorKind::RungeKutta3;
  if (n == "cpodes") return IntegratorKind::CPodes;
  if (n == "verlet") return IntegratorKind::Verlet;
  throw InputError({"command line", 0, 0, "--integrator"},
                   "unknown integrator '" + name + "' (auto, ROS34PW2, RungeKuttaMerson, RungeKutta3, CPodes or Verlet)");
}

std::string getIntegratorName(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::Auto: return "auto";
    case IntegratorKind::Rosenbrock: return "ROS34PW2";
    case IntegratorKind::RungeKuttaMerson: return "RungeKuttaMerson";
    case IntegratorKind::RungeKutta3: return "RungeKutta3";
    case IntegratorKind::CPodes: return "CPodes";
    case IntegratorKind::Verlet: return "Verlet";
  }
  return "?";
}

bool hasConstraints(const SimTK::State& s) { return s.getNQErr() + s.getNUErr() + s.getNUDotErr() > 0; }

IntegratorKind resolveIntegratorKind(IntegratorKind kind, const SimTK::State& state) {
  if (kind != IntegratorKind::Auto) return kind;
  return hasConstraints(state) ? IntegratorKind::RungeKuttaMerson : IntegratorKind::Rosenbrock;
}

namespace {

class SimbodyStepper : public Stepper {
 public:
  SimbodyStepper(const SimTK::MultibodySystem& system, const SimTK::State& initial, const StepperOptions& o)
      : system_(system), kind_(o.kind) {
    switch (o.kind) {
      case IntegratorKind::RungeKutta3: integ_ = std::make_unique<SimTK::RungeKutta3Integrator>(system); break;
      case IntegratorKind::CPodes: integ_ = std::make_unique<SimTK::CPodesIntegrator>(system); break;
      case IntegratorKind::Verlet: integ_ = std::make_unique<SimTK::VerletIntegrator>(system); break;
      default: integ_ = std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system);
    }
    integ_->setAccuracy(o.accuracy);
    integ_->setConstraintTolerance(o.constraintTolerance > 0 ? o.constraintTolerance : o.accuracy);
    integ_->setProjectEveryStep(o.projectEveryStep);
    if (o.maxStep > 0) integ_->setMaximumStepSize(o.maxStep);
    integ_->setReturnEveryInternalStep(true);
    integ_->initialize(initial);
  }
  void step(double tEnd, double tEvent) override {
    if (integ_->stepTo(tEnd, tEvent) == SimTK::Integrator::EndOfSimulation)
      throw std::runtime_error("the integrator ended the simulation at t = " + std::to_string(integ_->getTime()));
  }
  double getTime() const override { return integ_->getAdvancedTime(); }
  const SimTK::Vector& getY() const override { return integ_->getAdvancedState().getY(); }
  const SimTK::Vector& getYDot() override {
    system_.realize(integ_->getAdvancedState(), SimTK::Stage::Acceleration);
    return integ_->getAdvancedState().getYDot();
  }
  SimTK::State& updState() override { return integ_->updAdvancedState(); }
  void reinitialize() override { integ_->reinitialize(SimTK::Stage::Position, false); }
  int getNumSteps() const override { return integ_->getNumStepsTaken(); }
  std::string getName() const override { return getIntegratorName(kind_); }

 private:
  const SimTK::MultibodySystem& system_;
  IntegratorKind kind_;
  std::unique_ptr<SimTK::Integrator> integ_;
};

// ROS34PW2 on y = [q; u; z]: each f call assigns y to a working State and realizes Acceleration.
class RosenbrockAdapter : public Stepper {
 public:
  RosenbrockAdapter(const SimTK::MultibodySystem& system, const SimTK::State& initial, const StepperOptions& o)
      : system_(system), state_(initial), stepper_(makeRhs(), makeOptions(o)) {
    reinitialize();
  }
  void step(double tEnd, double tEvent) override {
    stepper_.step(std::min(tEnd, tEvent));
    sync();
  }
  double getTime() const override { return stepper_.getTime(); }
  const SimTK::Vector& getY() const override { return y_; }
  const SimTK::Vector& getYDot() override { return yDot_; }
  SimTK::State& updState() override { return state_; }
  void reinitialize() override {
    work_ = state_;
    const SimTK::Vector& y = state_.getY();
    Eigen::VectorXd ye(y.size());
    for (int i = 0; i < y.size(); ++i) ye[i] = y[i];
    stepper_.reinitialize(state_.getTime(), ye);
    sync();
  }
  int getNumSteps() const override { return stepper_.getNumSteps(); }
  std::string getName() const override { return getIntegratorName(IntegratorKind::Rosenbrock); }

 private:
  static RosenbrockOptions makeOptions(const StepperOptions& o) {
    RosenbrockOptions r;
    r.relativeTolerance = o.accuracy;
    if (o.maxStep > 0) r.maxStep = o.maxStep;
    r.constantColumns = o.cyclicY;
    return r;
  }
  RosenbrockStepper::Rhs makeRhs() {
    return [this](double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
      work_.setTime(t);
      SimTK::Vector& wy = work_.updY();
      for (int i = 0; i < wy.size(); ++i) wy[i] = y[i];
      system_.realize(work_, SimTK::Stage::Acceleration);
      const SimTK::Vector& d = work_.getYDot();
      ydot.resize(d.size());
      for (int i = 0; i < d.size(); ++i) ydot[i] = d[i];
    };
  }
  // The working State carries the discrete variables of state_ (segment index, inputs).
  void sync() {
    const Eigen::VectorXd& y = stepper_.getY();
    const Eigen::VectorXd& f = stepper_.getYDot();
    y_.resize(static_cast<int>(y.size()));
    yDot_.resize(static_cast<int>(f.size()));
    for (int i = 0; i < y_.size(); ++i) y_[i] = y[i], yDot_[i] = f[i];
    state_.setTime(stepper_.getTime());
    state_.updY() = y_;
  }

  const SimTK::MultibodySystem& system_;
  SimTK::State state_, work_{state_};
  RosenbrockStepper stepper_;
  SimTK::Vector y_, yDot_;
};

}  // namespace

std::unique_ptr<Stepper> makeStepper(const SimTK::MultibodySystem& system, const SimTK::State& initial,
                                     const StepperOptions& options) {
  StepperOptions o = options;
  o.kind = resolveIntegratorKind(options.kind, initial);
  if (o.kind == IntegratorKind::Rosenbrock && hasConstraints(initial))
    throw io::InputError({"command line", 0, 0, "--integrator"},
                         "ROS34PW2 integrates models without constraints only; this model has constraints (rolling "
                         "without slip): choose auto or RungeKuttaMerson");
  if (o.kind == IntegratorKind::Rosenbrock) return std::make_unique<RosenbrockAdapter>(system, initial, o);
  return std::make_unique<SimbodyStepper>(system, initial, o);
}

}  // namespace motostab::simulation

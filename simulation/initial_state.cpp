// The initial state of a simulation: the trim carried over, initial rate offsets and road steps.
#include <algorithm>

#include "analysis/linearize.h"
#include "analysis/state_function.h"
#include "io/input_error.h"
#include "io/result_error.h"
#include "simulation/simulation_detail.h"

namespace motostab::simulation {

using analysis::StateFunction;
using analysis::TrimResult;
using analysis::chooseDependentColumns;
using io::InputError;
using vehicle::CoordinateIndices;
using vehicle::Input;
using vehicle::VehicleModel;

using SimTK::State;

void checkPerturbations(const VehicleModel& model, const std::vector<Perturbation>& perturbations) {
  const std::string& contact = model.getScenario().contact.model;
  for (const auto& p : perturbations) {
    if (p.kind != PerturbationKind::RoadStep) continue;
    SimTK::State probe = model.getDefaultState();
    if (model.applyLateralRoadStep(probe, p.wheel, p.amplitude)) continue;
    if (contact == "rolling_no_slip")
      throw InputError({"command line", 0, 0, "--perturb"}, "'" + p.spec + "': needs a force-based tyre model; the contact model "
                                                "'rolling_no_slip' is a rolling constraint without lateral compliance");
    throw InputError({"command line", 0, 0, "--perturb"},
                     "'" + p.spec + "': the contact model '" + contact + "' takes no road displacement input under " + p.body +
                         " (a relaxation_linear tyre needs a relaxation length > 0)");
  }
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
    throw io::ResultError("initial rates: the velocity constraints cannot be solved for the dependent rates");
  Eigen::MatrixXd Gdep(mv, mv);
  for (int k = 0; k < mv; ++k) Gdep.col(k) = G.col(dep[k]);
  const Eigen::VectorXd du = Gdep.partialPivLu().solve(-err0.tail(mv));
  for (int k = 0; k < mv; ++k) s.updU()[dep[k]] += du[k];
  fn.calcConstraintErrors(s, err);
  if (err.tail(mv).lpNorm<Eigen::Infinity>() > 1e-9)
    throw io::ResultError("initial rates: velocity constraint error remains after the solve");
}

namespace detail {

// Applies the road steps that start at time t (s).
void applyRoadSteps(const VehicleModel& model, State& s, const std::vector<Perturbation>& perturbations, double t) {
  for (const auto& p : perturbations)
    if (p.kind == PerturbationKind::RoadStep && std::abs(p.start - t) < 1e-12) model.applyLateralRoadStep(s, p.wheel, p.amplitude);
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

}  // namespace detail

}  // namespace motostab::simulation

#pragma once
// Shared by the simulation tests: the linear model's prediction exp(A t) x0 as the independent
// reference for the nonlinear response.
#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>

#include "analysis/linearize.h"
#include "simulation/perturbation.h"
#include "simulation/simulation.h"

namespace motostab::simulation {

using analysis::LinearModel;
using analysis::calcTrim;
using analysis::linearize;
using scenario::Scenario;
using vehicle::VehicleModel;


inline LinearModel linearizeScenarioAt(const Scenario& scenario, double speed) {
  const VehicleModel model(scenario);
  return linearize(model, calcTrim(model, speed));
}

/// A 2 s coasting run from the trim at `speed` (m/s) after a small roll- and steer-rate kick
/// (1e-4 and -2e-4 rad/s), sampled every 10 ms, at integrator accuracy `accuracy`.
inline SimulationOptions makeSmallRateKick(double speed, double accuracy) {
  SimulationOptions o;
  o.speed = speed;
  o.duration = 2;
  o.outputStep = 0.01;
  o.speedControl = SpeedControl::None;
  o.accuracy = accuracy;
  o.perturbations = {parsePerturbation("roll-rate:1e-4"), parsePerturbation("steer-rate:-2e-4")};
  return o;
}

/// Deviation of column `name` from the trim at sample k.
inline double getDeviation(const SimulationResult& r, size_t k, const std::string& name) {
  const int j = r.getColumnIndex(name);
  return r.rows[k][j] - r.trimRow[j];
}

/// x0 read from the first sample by linear-state name.
inline Eigen::VectorXd readInitialDeviation(const SimulationResult& r, const LinearModel& lin) {
  Eigen::VectorXd x0(lin.states.size());
  for (size_t i = 0; i < lin.states.size(); ++i) x0[i] = getDeviation(r, 0, lin.states[i].name);
  return x0;
}

/// max_k |state(t_k) - [exp(A t_k) x0]_state| / max_k |[exp(A t_k) x0]_state|; `maxRef` gets the denominator.
inline double calcRelativeDeviationFromLinear(const SimulationResult& r, const LinearModel& lin, const Eigen::VectorXd& x0,
                                              const std::string& name, double& maxRef) {
  const int i = lin.findState(name);
  double maxErr = 0;
  maxRef = 0;
  for (size_t k = 0; k < r.rows.size(); ++k) {
    const double ref = (lin.A * r.rows[k][0]).exp().row(i).dot(x0);
    maxErr = std::max(maxErr, std::abs(getDeviation(r, k, name) - ref));
    maxRef = std::max(maxRef, std::abs(ref));
  }
  return maxErr / maxRef;
}

}  // namespace motostab::simulation

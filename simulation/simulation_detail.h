#pragma once
// Internal stages of runSimulation: initial state (initial_state.cpp), output sampling and integration (sampling.cpp).
#include <string>
#include <vector>

#include "simulation/perturbation_force.h"
#include "simulation/simulation.h"
#include "simulation/stepper.h"

namespace motostab::simulation::detail {

// Applies the road steps that start at time t (s).
void applyRoadSteps(const vehicle::VehicleModel& model, SimTK::State& s, const std::vector<Perturbation>& perturbations, double t);

// The trim of the bare model carried over to the model with the perturbation force: q, u, the
// contact states and the trim inputs, at time 0 in segment 0.
SimTK::State makeInitialState(const vehicle::VehicleModel& model, const vehicle::VehicleModel& trimModel, const analysis::TrimResult& trim,
                              const PerturbationForce& force);

// The output columns: time, q, u, z, the standard channels, the contact outputs and the extra outputs.
std::vector<std::string> listColumns(const vehicle::VehicleModel& model, const SimulationOptions& opt);

// Output rows from sampled states, evaluated on one working State (assigning y costs less than
// copying a State); record() also ends the run on a non-finite value or a fall.
class SampleRecorder {
 public:
  SampleRecorder(const vehicle::VehicleModel& model, const PerturbationForce& force, const SimulationOptions& opt,
                 const SimTK::State& s, SimulationResult& res)
      : model_(model), force_(force), opt_(opt), w_(s), res_(res) {}

  std::vector<double> makeRow(double t, const SimTK::Vector& y, int segment);

  /// Appends a sample; false when the run ends there (non-finite state or a fall).
  bool record(double t, const SimTK::Vector& y, int segment);

 private:
  const vehicle::VehicleModel& model_;
  const PerturbationForce& force_;
  const SimulationOptions& opt_;
  SimTK::State w_;
  SimulationResult& res_;
  const int rollColumn_ = res_.getColumnIndex("roll");
};

// Integrator options from the simulation options; InputError for ROS34PW2 on a model with constraints.
StepperOptions makeStepperOptions(const vehicle::VehicleModel& model, const SimulationOptions& opt, const SimTK::State& s);

// Integrates to opt.duration, recording samples on the output grid from cubic Hermite interpolation
// of y between internal steps (y and ydot at both ends; the same order as Simbody's own
// interpolation, without its State copies), and switching segments at their starts.
void integrate(Stepper& integ, const vehicle::VehicleModel& model, const PerturbationForce& force, const SimulationOptions& opt,
               const std::vector<double>& segmentStarts, SampleRecorder& recorder);

}  // namespace motostab::simulation::detail

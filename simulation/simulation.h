#pragma once
// Nonlinear time-domain simulation of a scenario from its straight-running trim, with perturbations
// (simulation/perturbation.h), speed control, a fall limit and sampled outputs. See docs/simulation.md.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "analysis/trim.h"
#include "simulation/perturbation.h"
#include "simulation/stepper.h"

namespace motostab::simulation {

enum class SpeedControl {
  None,  ///< coast: no drive torque beyond the trim's
  PI     ///< drive torque = trim torque + Kp e + Ki integral(e), e = target - forward speed
};

SpeedControl parseSpeedControl(const std::string& name);  ///< "none" or "pi"; InputError otherwise

/// An extra output column evaluated on every sample (state realized to Dynamics), e.g. a tyre force
/// once contact plugins expose them. Units are the channel's own.
struct OutputChannel {
  std::string name;
  std::function<double(const vehicle::VehicleModel& model, const SimTK::State& state)> calc;
};

/// The most output samples (duration / outputStep) of a run: every sample is kept in memory and written
/// (about 3 kB each for a 20-state motorcycle, measured: 1e5 samples take about 0.3 GB).
constexpr double kMaxOutputSamples = 1e5;

struct SimulationOptions {
  double speed = 5;          ///< trim (and target) forward speed, m/s
  double duration = 10;      ///< simulated time, s
  double outputStep = 0.01;  ///< sampling interval of the outputs, s
  std::vector<Perturbation> perturbations;
  SpeedControl speedControl = SpeedControl::PI;
  /// PI gains per unit of vehicle mass m and rear radius r: Kp = gainP m r (N m per m/s),
  /// Ki = gainI m r (N m per m). gainP is a time constant of about 1 s on a bicycle.
  double speedGainP = 1.0;   ///< 1/s
  double speedGainI = 0.25;  ///< 1/s^2
  IntegratorKind integrator = IntegratorKind::Auto;
  double accuracy = 1e-6;            ///< integrator relative accuracy
  double constraintTolerance = 0;    ///< constraint projection tolerance; <= 0: equal to accuracy
  bool projectEveryStep = false;     ///< project onto the constraints after every step
  double maxStep = 0;                ///< largest internal step, s; 0: integrator default (ROS34PW2 0.05 s, Simbody none)
  double fallRollLimit = M_PI / 3;   ///< |roll| beyond this ends the run as a fall, rad (60 deg)
  analysis::TrimOptions trim;
  /// Extra columns appended after the standard ones, in this order.
  std::vector<OutputChannel> extraOutputs;
  /// Called after every output sample with the simulated time (s); for progress bars.
  std::function<void(double time)> progress;
};

enum class SimulationStatus {
  Completed,  ///< reached the duration
  Fell,       ///< |roll| exceeded the fall limit; samples end there
  Failed      ///< integrator or model error; samples end at the last good one
};

/// Sampled time histories. Columns: time (s); every q (rad, m) and u (rad/s, m/s) by model name;
/// every z by name; steer_torque (total applied, N m); drive_torque (total, N m); lateral_force
/// (sum of lateral-force pulses, N); forward_speed (rear wheel centre along the heading, m/s);
/// energy (kinetic + gravitational, J); the contact outputs; the model extensions' outputs (e.g.
/// steer_controller_torque, N m, the steer_controller's applied torque, not included in steer_torque);
/// then SimulationOptions::extraOutputs.
struct SimulationResult {
  SimulationStatus status = SimulationStatus::Completed;
  std::string message;                      ///< why a run ended early (fall or failure), else empty
  std::vector<std::string> columns;
  int numQ = 0;                             ///< q columns follow "time": columns[1 .. numQ]
  std::vector<std::vector<double>> rows;    ///< rows[k][j]: sample k, column j
  std::vector<double> trimRow;              ///< the trim in the same columns (time 0, no perturbation)
  double endTime = 0;                       ///< last sample time, s
  int steps = 0;                            ///< integrator steps taken
  std::string integrator;                   ///< the integrator used (Auto resolved)
  double wallSeconds = 0;                   ///< wall-clock time of the integration, s

  /// Index of a named column; throws std::out_of_range naming it if absent.
  int getColumnIndex(const std::string& name) const;
  std::vector<double> getColumn(const std::string& name) const;
};

/// Throws InputError for perturbations `model` cannot take (e.g. road-step on rolling_no_slip,
/// which needs a force-based tyre model).
void checkPerturbations(const vehicle::VehicleModel& model, const std::vector<Perturbation>& perturbations);

/// Trims `scenario` at options.speed, applies the initial rate offsets (dependent rates re-solved
/// from the velocity constraints, the named rates, the other independent rates and forward speed
/// kept), and integrates for options.duration. Bad options are InputErrors (also more than
/// kMaxOutputSamples output samples); a trim failure throws
/// TrimError; a fall or an integration failure ends the run with the samples so far.
SimulationResult runSimulation(const scenario::Scenario& scenario, const SimulationOptions& options);
/// Same, loading plugins into `registry` (from makeBuiltinRegistry() by default).
SimulationResult runSimulation(const scenario::Scenario& scenario, plugins::PluginRegistry& registry, const SimulationOptions& options);

/// Sets the initial rate offsets of `perturbations` on `state` (rad/s added to roll_rate or
/// steer_rate) and re-solves the velocity constraints for the dependent rates, keeping the
/// perturbed rates, roll_rate, steer_rate and the forward speed vx. Throws io::ResultError if the
/// constraints cannot be solved.
void applyInitialRates(const vehicle::VehicleModel& model, SimTK::State& state, const std::vector<Perturbation>& perturbations);

}  // namespace motostab::simulation

#pragma once
// Steer controller (`steer_controller`): linear state feedback on the steer torque, as used for
// balance-assist and steer-by-wire bicycles, electronic steering dampers and rider models (steer
// torque as feedback of roll and steer angles and rates: Moore 2012, "Human control of a bicycle",
// PhD thesis, UC Davis; the balance-assist law T = k (v0 - v) roll_rate: Haitjema 2023, TU Delft).
// Signs are those of ISO 8855 and the vehicle model (vehicle/vehicle_model.h): roll phi > 0 leans right,
// steer delta > 0 steers left, the torque T > 0 turns the front frame to the left (its reaction acts
// on the rear frame). Steering INTO the fall (to the right when falling to the right) therefore needs
// NEGATIVE roll and roll-rate gains.
//
// Law, with v the forward speed of the rear wheel centre along the rear frame's heading (m/s):
//   u(t) = f(v) g (k_phi phi + k_phid phi' + k_delta delta + k_deltad delta')        (N m)
//   f(v) = 1 (no schedule) | max(v0 - v, 0) (`below_mps: v0`) | linear interpolation of the table,
//          held constant beyond its first and last speeds (`table`)
// Delay (delay_s = tau > 0): the first-order Pade approximant of exp(-s tau),
//   Y(s)/U(s) = (1 - s tau/2) / (1 + s tau/2) = -1 + 2 / (1 + s tau/2),
// realised with one auxiliary state z (N m):  z' = (2/tau) (2 u - z),   y = z - u.
// Chosen over the lag 1/(1 + s tau) because it is all-pass like the delay it stands for (gain 1 at
// every frequency; phase -2 atan(omega tau/2), matching -omega tau to third order), so a fitted delay
// does not masquerade as a change of gain. Its step response starts at -1 (the non-minimum-phase zero):
// a sudden jump in the fed-back state first kicks the torque the wrong way, as no real delay does.
// Saturation (torque_limit_Nm = L): T = clamp(y, -L, L) (y = u without delay).
//
// Linearisation: the law is linear in the states and their rates, so linearize/sweep see it exactly;
// with a delay, z is a state of the linear model (trimmed to 2 u = its static value, so y = u at the
// trim). The schedule's speed dependence enters only multiplied by states that are zero in straight
// running, so it does not couple to the forward speed at an upright trim. The clamp is inactive at
// the trim unless |y_trim| >= L: then the finite differences see its flat part (zero gain there).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "plugins/plugin_api.h"

namespace motostab::extensions {

/// The shortest delay, s: a tenth of a millisecond, below any rider's or actuator's (human reaction
/// ~0.1-0.3 s, electric steer actuators ~1-10 ms). The Pade pole -2/tau of a shorter delay swamps
/// every other root (1e-300 s gives -2e300 1/s and loses the weave).
constexpr double kMinSteerDelay = 1e-4;

/// The section `steer_controller: {roll_angle_Nm_per_rad?, roll_rate_Nms_per_rad?, steer_angle_Nm_per_rad?,
/// steer_rate_Nms_per_rad?, gain_factor?, schedule: {below_mps: v0} | {table: [[v, f], ...]}?, delay_s?,
/// torque_limit_Nm?}`: the law above.
struct SteerControllerParams {
  enum class Schedule { None, Below, Table };
  double rollAngleGain = 0;   ///< k_phi, N m/rad (per m/s with a `below_mps` schedule)
  double rollRateGain = 0;    ///< k_phid, N m s/rad (likewise)
  double steerAngleGain = 0;  ///< k_delta, N m/rad
  double steerRateGain = 0;   ///< k_deltad, N m s/rad
  double gainFactor = 1;      ///< g, dimensionless (> 0): scales every gain
  Schedule schedule = Schedule::None;
  double scheduleBelow = 0;   ///< v0, m/s: f = v0 - v for v < v0, else 0
  std::vector<std::array<double, 2>> scheduleTable;  ///< (v m/s, f) sorted by v: f interpolated linearly
  double delay = 0;           ///< tau, s (0: none, else >= kMinSteerDelay): first-order Pade delay
  double torqueLimit = 0;     ///< N m (> 0 when given; 0: none): |T| <= limit
};

/// The section's declared fields: `steer_controller` and its `schedule` (first and last).
const std::vector<io::SectionFields>& getSteerControllerFields();

/// Reads and checks the section (the caller finishes `m`). The table needs at least two rows with
/// strictly increasing speeds; a negative delay or one between 0 and kMinSteerDelay, a non-positive
/// limit or gain factor are errors.
SteerControllerParams readSteerController(io::YamlMap& m);

/// The scalar keys of the section (gains, gain_factor, delay_s, torque_limit_Nm), for readers that
/// set them per measurement (diagnosis/measured_data.h).
const std::vector<std::string>& getSteerControllerScalarKeys();

/// The states the controller reads: roll (rad), roll rate (rad/s), steer (rad), steer rate (rad/s),
/// forward speed v (m/s).
struct SteerControllerInputs {
  double roll = 0, rollRate = 0, steer = 0, steerRate = 0, speed = 0;
};

/// The schedule factor f(v) (dimensionless; m/s for `below_mps`), as above.
double calcScheduleFactor(const SteerControllerParams& spec, double speed);

/// The undelayed, unsaturated law u (N m), as above.
double calcSteerControllerCommand(const SteerControllerParams& spec, const SteerControllerInputs& x);

/// The applied torque T = clamp(y, -L, L) (N m) for the (delayed) command y.
double calcSaturatedTorque(const SteerControllerParams& spec, double command);

/// The controller element of one model: reads the states, writes the delay state's derivative.
class SteerController {
 public:
  SteerController(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& rearFrame,
                  const SimTK::MobilizedBody& frontFrame, const SteerControllerParams& spec);
  /// Allocates the delay state (if any); called from the force element's realizeTopology.
  void allocateState(SimTK::State& state) const;
  /// The fed-back states of `state` (realized to Velocity).
  SteerControllerInputs getInputs(const SimTK::State& state) const;
  /// The applied torque T (N m) in `state` (realized to Velocity).
  double calcTorque(const SimTK::State& state) const;
  /// Applies T to the steer mobility and writes z' (delay); state realized to Velocity.
  void apply(const SimTK::State& state, SimTK::Vector& mobilityForces) const;
  const SteerControllerParams& getSpec() const { return spec_; }

 private:
  double calcDelayedCommand(const SimTK::State& state, double command) const;

  SimTK::GeneralForceSubsystem& forces_;
  SimTK::MobilizedBody rear_, front_;
  SteerControllerParams spec_;
  mutable SimTK::ZIndex zIndex_;
};

/// The extension with these parameters (typed constructor). Its output `steer_controller_torque`
/// (N m) is the applied torque T, not included in the model's steer_torque input.
std::unique_ptr<plugins::ExtensionModel> makeSteerController(const SteerControllerParams& params);

/// Registers `steer_controller`.
void registerSteerController(plugins::PluginRegistrar& registry);

}  // namespace motostab::extensions

#pragma once
// A single-track vehicle assembled in Simbody from a Scenario: rear frame (with rider) on a 6-DOF
// Bushing mobilizer, front frame on a revolute steer axis, two wheels on revolute spin joints, and
// a contact plugin per wheel. Coordinates (ground: x forward, y left, z up):
//   q = yaw, roll, pitch (body-fixed z-x-y of the rear frame), height, x, y of the rear wheel centre,
//       then steer, rear and front wheel spin angles, and, with a swingarm, the optional rear
//       suspension angle `suspension_pitch` and the compliance coordinates `swingarm_*`; then the
//       coordinates of the model extensions (extensions/: `rider_lean`, `fork_bending`, `fork_torsion`).
//       Every u is the corresponding qdot. z: the contact model's states, then the extensions' (e.g.
//       `steer_controller_delay`).
// The model extensions are plugins (plugins/plugin_api.h ExtensionModel), one per extension section
// of the scenario, called at each assembly stage in the registry's order.
// Every state has a role (plugins/state_role.h: roll, steer, tyre lag, swingarm twist, ...), reported
// by the element that adds it; the analysis reads roles, names are for files and people.
// Signs: roll > 0 leans right, yaw > 0 turns left, steer > 0 steers left, pitch > 0 nose down.
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "Simbody.h"
#include "plugins/builtin.h"
#include "scenario/scenario.h"

namespace motostab::vehicle {

using plugins::AuxiliaryState;
using plugins::NamedMobilizer;
using plugins::StateKind;
using plugins::StateRole;
using plugins::WheelSide;
using plugins::isComplianceRole;
using plugins::kNumStateRoles;

/// One state of the model (a q, u or z): its name, role, kind and wheel.
struct StateInfo {
  std::string name;
  StateRole role = StateRole::Other;
  StateKind kind = StateKind::Coordinate;
  WheelSide wheel = WheelSide::None;
};

/// Generalized coordinates with a role in trim and linearisation (indices into q; u alike).
struct CoordinateIndices {
  int yaw = -1, roll = -1, pitch = -1, height = -1, x = -1, y = -1;
  int steer = -1, rearSpin = -1, frontSpin = -1;
  std::vector<int> compliance;  ///< swingarm compliance coordinates, if any
  std::vector<int> extension;   ///< the model extensions' coordinates (rider_lean, suspension_pitch, fork_bending, ...)
};

/// Model inputs: generalized forces the trim may solve for and B is taken against.
enum class Input { SteerTorque = 0, DriveTorque = 1, RollTorque = 2 };
constexpr int kNumInputs = 3;

class VehicleModel;

/// Adds elements (perturbation forces, controllers) to a model while it is assembled, after the
/// bodies and contacts and before Simbody's topology is realized. Returns any z states it
/// allocates (name and role), in allocation order.
using ModelExtension = std::function<std::vector<AuxiliaryState>(plugins::BuildContext& context, const VehicleModel& model)>;

class VehicleModel {
 public:
  /// Builds the Simbody system; loads the scenario's plugin libraries into `registry` first.
  VehicleModel(const scenario::Scenario& scenario, plugins::PluginRegistry& registry, const std::vector<ModelExtension>& extensions = {});
  /// Same, with the built-in registry.
  explicit VehicleModel(const scenario::Scenario& scenario);
  /// A new, independent model built like this one: same scenario, a copy of the plugin registry it
  /// was built with (loaded libraries included) and the same extensions, called again. For worker
  /// threads, which must not share Simbody caches.
  std::unique_ptr<VehicleModel> makeReplica() const;
  VehicleModel(const VehicleModel&) = delete;
  VehicleModel& operator=(const VehicleModel&) = delete;

  const scenario::Scenario& getScenario() const { return scenario_; }
  const SimTK::MultibodySystem& getSystem() const { return system_; }
  const SimTK::SimbodyMatterSubsystem& getMatter() const { return matter_; }
  /// A state at the design pose (upright, at rest), realized to Instance.
  const SimTK::State& getDefaultState() const { return defaultState_; }

  int getNumQ() const { return nq_; }
  int getNumU() const { return nq_; }
  int getNumZ() const { return static_cast<int>(zNames_.size()); }
  const std::vector<std::string>& getQNames() const { return qNames_; }
  const std::vector<std::string>& getUNames() const { return uNames_; }
  const std::vector<std::string>& getZNames() const { return zNames_; }
  /// Every q, u and z with its role (kind Coordinate, Rate, Auxiliary), in state order.
  const std::vector<StateInfo>& getQStates() const { return qStates_; }
  const std::vector<StateInfo>& getUStates() const { return uStates_; }
  const std::vector<StateInfo>& getZStates() const { return zStates_; }
  const CoordinateIndices& getIndices() const { return idx_; }
  /// Coordinates that never enter the equations of straight running: x, y, wheel spin angles.
  std::vector<int> getCyclicQ() const { return {idx_.x, idx_.y, idx_.rearSpin, idx_.frontSpin}; }

  static std::vector<std::string> getInputNames() { return {"steer_torque", "drive_torque", "roll_torque"}; }
  /// Sets an input (N m): steer torque acts between front and rear frames, drive torque between
  /// rear frame and rear wheel, roll torque on the rear frame about ground x.
  void setInput(SimTK::State& state, Input which, double value) const;
  double getInput(const SimTK::State& state, Input which) const;

  /// Steps the road's lateral position under a wheel by `offset` (m) in the state; false when the
  /// contact model has no road input (e.g. a rolling constraint).
  bool applyLateralRoadStep(SimTK::State& state, WheelSide wheel, double offset) const;

  /// The contact point of a wheel as its contact model gives it (ContactModel::calcContactPoint), in
  /// ground. State realized to Position; realized to Velocity the rate is the wheel's, else it is that of
  /// a wheel at rest (zero angular velocity).
  plugins::ContactPoint calcContactPoint(const SimTK::State& state, WheelSide wheel) const;

  /// Named contact outputs of both wheels (tyre forces, slips; none for rolling constraints).
  std::vector<std::string> getContactOutputNames() const;
  /// Their values, state realized to Velocity.
  std::vector<double> calcContactOutputs(const SimTK::State& state) const;

  /// Named outputs of the model extensions (e.g. steer_controller_torque, N m), in their order.
  std::vector<std::string> getExtensionOutputNames() const;
  /// Their values, state realized to Velocity.
  std::vector<double> calcExtensionOutputs(const SimTK::State& state) const;
  /// Writes what each model extension adds, one or more lines each (ExtensionModel::describe).
  void describeExtensions(std::ostream& out) const;
  /// Every body as the model is built (listModelBodies).
  std::vector<scenario::NamedBody> listBodies() const;

  /// Forward speed: velocity of the rear wheel centre along ground x, m/s.
  double getForwardSpeed(const SimTK::State& state) const { return state.getU()[idx_.x]; }

  const SimTK::MobilizedBody& getRearFrame() const { return rearFrame_; }
  const SimTK::MobilizedBody& getFrontFrame() const { return frontFrame_; }
  const SimTK::MobilizedBody& getRearWheel() const { return rearWheel_; }
  const SimTK::MobilizedBody& getFrontWheel() const { return frontWheel_; }

 private:
  void build(plugins::PluginRegistry& registry, const std::vector<ModelExtension>& extensions);

  scenario::Scenario scenario_;
  plugins::PluginRegistry registry_;                 ///< as used by build(), for replicas
  std::vector<ModelExtension> extensions_;  ///< as used by build(), for replicas
  SimTK::MultibodySystem system_;
  SimTK::SimbodyMatterSubsystem matter_;
  SimTK::GeneralForceSubsystem forces_;
  SimTK::MobilizedBody rearFrame_, frontFrame_, rearWheel_, frontWheel_;
  SimTK::Force::DiscreteForces inputs_;
  std::vector<std::unique_ptr<plugins::ContactModel>> contacts_;
  std::unique_ptr<plugins::SwingarmModel> swingarm_;
  std::vector<std::unique_ptr<plugins::ExtensionModel>> extensionModels_;
  std::vector<plugins::WheelSite> wheelSites_;
  SimTK::State defaultState_;
  int nq_ = 0;
  CoordinateIndices idx_;
  std::vector<std::string> qNames_, uNames_, zNames_;
  std::vector<StateInfo> qStates_, uStates_, zStates_;
};

/// Every body of the model of `scenario` as it is built, in D, without building it (its extension
/// sections read, built-in and from its plugin libraries): `rear_frame` (without what the extensions
/// took from it), the extensions' bodies taken from it (`rider_upper_body`), `front_frame` (with the
/// rider's grips, without a fork's hub carrier), the bodies taken from it (`fork_carrier`), the wheels and
/// the swingarm. InputError as building the model.
std::vector<scenario::NamedBody> listModelBodies(const scenario::Scenario& scenario);

}  // namespace motostab::vehicle

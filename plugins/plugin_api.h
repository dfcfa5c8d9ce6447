#pragma once
// The motostab plugin API: the narrow, versioned interface a plugin sees. A plugin is a named
// factory with its own validated parameters (a strict YamlMap of its scenario section). Built-in
// plugins live in tyres/ and swingarm/; third-party plugins are shared libraries that define
// MOTOSTAB_PLUGIN_ENTRY (see docs/plugins.md). This header needs Simbody and the YAML reader only,
// not the scenario model; the registry that loads libraries is plugins/plugin_registry.h.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "Simbody.h"

#include "io/yaml_map.h"
#include "plugins/contact_geometry.h"
#include "plugins/state_role.h"

/// Version of this interface. A library built against another version is refused at load; bump it
/// whenever a type in this header changes layout or meaning.
#define MOTOSTAB_PLUGIN_API_VERSION 5

namespace motostab::plugins {

/// One wheel as a contact model sees it. The wheel body's origin is the wheel centre and its
/// spin axis is the body y axis.
struct WheelSite {
  std::string name;              ///< "rear_wheel" or "front_wheel" (for names of outputs and states)
  WheelSide side = WheelSide::None;  ///< which wheel it is
  SimTK::MobilizedBody wheel;
  double radius = 0;             ///< outer rolling radius, m
  double crownRadius = 0;        ///< tyre crown (cross-section) radius, m; 0 = knife edge
  double staticLoad = 0;         ///< static vertical load of the upright vehicle at rest, N
};

/// What a plugin may add to while the vehicle is assembled.
struct BuildContext {
  SimTK::MultibodySystem& system;
  SimTK::SimbodyMatterSubsystem& matter;
  SimTK::GeneralForceSubsystem& forces;
  double gravity = 9.81;  ///< m/s^2
};

/// The common interface of every wheel-ground contact model (constraint or tyre force).
class ContactModel {
 public:
  virtual ~ContactModel() = default;
  /// Adds the contact of one wheel with flat ground (z = 0) to the system.
  virtual void addWheel(BuildContext& context, const WheelSite& wheel) = 0;
  /// Where `wheel` meets the ground when its centre frame has orientation R_GW and angular velocity
  /// w_GW_G (rad/s, ground frame): the centre-to-contact vector and its rate (plugins/contact_geometry.h).
  /// The trims use it (the speed of a turn is that of the rear contact point; a roll step keeps both
  /// contact points at their heights), whatever the model. Default: the toroidal wheel of wheel.radius
  /// and wheel.crownRadius (calcTorusContact), as every built-in model; override for another shape.
  virtual ContactPoint calcContactPoint(const WheelSite& wheel, const SimTK::Rotation& R_GW, const SimTK::Vec3& w_GW_G) const {
    return calcTorusContact(R_GW, w_GW_G, wheel.radius, wheel.crownRadius);
  }
  /// The auxiliary states (z) this model allocates for a wheel, in allocation order: name and role
  /// (a tyre's relaxation state is StateRole::TyreLag with the wheel's side).
  virtual std::vector<AuxiliaryState> getStates(const WheelSite& wheel) const { return {}; }
  /// Applies a step of the road's lateral position under `wheel` (m, towards +y) to the state, as
  /// at the instant the wheel meets it. Returns false if the model has no road input.
  virtual bool applyLateralRoadStep(SimTK::State& state, const WheelSite& wheel, double offset) const { return false; }
  /// Names (with units) of the quantities calcOutputs reports for a wheel, e.g. forces and slips.
  virtual std::vector<std::string> getOutputNames(const WheelSite& wheel) const { return {}; }
  /// Their values in a state realized to Velocity.
  virtual std::vector<double> calcOutputs(const SimTK::State& state, const WheelSite& wheel) const { return {}; }
};

/// Makes a contact model from its scenario parameters (the `contact` mapping; `model` is consumed).
using ContactModelFactory = std::function<std::unique_ptr<ContactModel>(io::YamlMap& params)>;

/// Where a swingarm model is attached: the body it hangs from (the rear frame, or the massless
/// suspension link turning about the pivot when the scenario has a rear suspension), the swingarm
/// frame S in that body's frame (origin at the pivot, x towards the rear hub, z up; the parent's
/// axes are the design frame's at the design pose), the hub in S, and the swingarm body (mass
/// properties in S).
struct SwingarmSite {
  SimTK::MobilizedBody rearFrame;
  SimTK::Transform X_RS;
  SimTK::Vec3 p_SH;
  SimTK::Body::Rigid body;
};

/// What a swingarm model built: the body that carries the rear wheel, the hub frame in it (axes
/// parallel to the design frame at the design pose), and its one-DOF compliance mobilizers with the
/// names and roles of their coordinates (StateRole::SwingarmBending, ..., or Compliance).
struct SwingarmAssembly {
  SimTK::MobilizedBody hubCarrier;
  SimTK::Transform X_CH;
  std::vector<NamedMobilizer> coordinates;
};

/// The common interface of swingarm compliance models (seed sec. 4: rigid, bending, torsion, twist).
class SwingarmModel {
 public:
  virtual ~SwingarmModel() = default;
  virtual SwingarmAssembly addSwingarm(BuildContext& context, const SwingarmSite& site) = 0;
};

/// Makes a swingarm model from the scenario's `swingarm` mapping (pivot, mass properties and
/// `compliance` are consumed by the loader; the plugin reads its own keys).
using SwingarmModelFactory = std::function<std::unique_ptr<SwingarmModel>(io::YamlMap& params)>;

/// What a plugin's entry point registers into: factories by name. Names are unique across all
/// plugins (built-in and loaded); a duplicate is reported when the registration is committed.
class PluginRegistrar {
 public:
  virtual ~PluginRegistrar() = default;
  virtual void addContactModel(const std::string& name, ContactModelFactory factory) = 0;
  virtual void addSwingarmModel(const std::string& name, SwingarmModelFactory factory) = 0;
};

}  // namespace motostab::plugins

/// Entry point a plugin library defines: MOTOSTAB_PLUGIN_ENTRY { registry.addContactModel(...); }.
/// It also exports the API version the library was built against, checked before registration.
#define MOTOSTAB_PLUGIN_ENTRY                                                          \
  extern "C" int motostab_plugin_api_version() { return MOTOSTAB_PLUGIN_API_VERSION; } \
  extern "C" void motostab_register_plugins(motostab::plugins::PluginRegistrar& registry)

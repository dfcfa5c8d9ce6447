#pragma once
// The motostab plugin API: the narrow, versioned interface a plugin sees. A plugin is a named
// factory with its own validated parameters (a strict YamlMap of its scenario section). Three kinds:
// contact models (tyres/), swingarm models (swingarm/compliance/) and model extensions (extensions/:
// steer damper, rider lean, fork compliance, ...). Third-party plugins are shared libraries that define
// MOTOSTAB_PLUGIN_ENTRY (see docs/plugins.md). This header needs Simbody, the YAML reader and the
// body mass properties of scenario/body_spec.h only, not the scenario model; the registry that loads
// libraries is plugins/plugin_registry.h.
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "Simbody.h"

#include "io/field.h"
#include "io/yaml_map.h"
#include "plugins/contact_geometry.h"
#include "plugins/state_role.h"
#include "scenario/body_spec.h"

/// Version of this interface. A library built against another version is refused at load; bump it
/// whenever a type in this header changes layout or meaning.
#define MOTOSTAB_PLUGIN_API_VERSION 9

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

/// Where a swingarm model is attached: the body it hangs from (the rear frame, or the carrier a model
/// extension put at the pivot, e.g. the rear suspension's link turning about the pivot), the swingarm
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

/// The vehicle as a model extension reads it (design frame D, scenario/body_spec.h; SI units): what
/// the scenario gives before any extension is applied.
struct VehicleLayout {
  double gravity = 9.81;        ///< m/s^2
  double wheelbase = 0;         ///< w, m
  double trail = 0;             ///< c, m
  double steerAxisTilt = 0;     ///< lambda, rad from vertical
  double rearWheelRadius = 0;   ///< m
  double frontWheelRadius = 0;  ///< m
  scenario::BodySpec rearFrame;   ///< rear frame with the whole rider
  scenario::BodySpec frontFrame;  ///< fork and handlebar, without the wheel
  bool hasSwingarm = false;       ///< false: the rear wheel turns on the rear frame; the values below are 0
  scenario::Vec3d swingarmPivot{0, 0, 0};  ///< pivot in D, m
  /// Moment (N m) about the pivot's lateral axis (positive lifts the hub) that the rear tyre's static
  /// load and the weights of swingarm and rear wheel exert on the swingarm at the design pose.
  double staticPivotMoment = 0;
};

/// The two frames' mass properties while the vehicle is assembled (D). An extension whose bodies
/// carry mass the scenario gives to a frame (a rider's upper body, a fork's hub carrier) takes it out.
struct FrameMasses {
  scenario::BodySpec rearFrame;
  scenario::BodySpec frontFrame;
};

/// A body an extension built with mass taken from a frame (adjustFrames): its name, its mass
/// properties in D and the frame it came from, for reports.
struct ExtensionBody {
  enum class Frame { Rear, Front };
  Frame takenFrom = Frame::Rear;
  scenario::NamedBody body;
};

/// What an extension attaches to. Body frames have their axes parallel to D at the design pose and
/// their origins at the wheel centres: the rear frame's at the rear hub p_DR, the front frame's at the
/// front hub p_DF (both in D, m). The rear frame's mobilizer is the 6-DOF Bushing (q: yaw, roll,
/// pitch, height, x, y); the front frame's the steer Pin (q: steer angle relative to the rear frame).
struct VehicleFrames {
  SimTK::MobilizedBody rearFrame, frontFrame;
  SimTK::Vec3 p_DR, p_DF;
};

/// A body an extension put in series between two parts of the vehicle (the front frame and the front
/// wheel; the rear frame and the swingarm) and its one-DOF mobilizers. Its origin is where the next
/// part attaches (the front hub; the swingarm pivot), its axes parallel to D at the design pose.
struct BodyCarrier {
  SimTK::MobilizedBody carrier;
  std::vector<NamedMobilizer> coordinates;
};

/// The common interface of model extensions: elements a scenario section adds to the vehicle (a
/// damper, a controller, a leaning rider, a compliant fork). The vehicle is assembled in stages and
/// calls each extension at every stage, in the order the extensions were registered:
///   adjustFrames -> rear frame built -> addRearBodies -> addSwingarmCarrier (with a swingarm) ->
///   swingarm -> front frame built -> addFrontHubCarrier -> wheels and contacts -> addForces ->
///   topology realized
/// Each stage's default does nothing.
class ExtensionModel {
 public:
  virtual ~ExtensionModel() = default;
  /// Takes the mass of the extension's own bodies out of the frames (or moves it between them),
  /// before the frames are built: the vehicle's totals stay as the scenario gives them.
  virtual void adjustFrames(FrameMasses& frames) const {}
  /// Adds bodies hanging from the rear frame; returns their one-DOF mobilizers with names and roles.
  /// The front frame is not built yet: frames.frontFrame is an empty handle here.
  virtual std::vector<NamedMobilizer> addRearBodies(BuildContext& context, const VehicleFrames& frames) { return {}; }
  /// Puts a carrier between the rear frame and the swingarm (its origin at the pivot p_DP, in D, m),
  /// called only when the scenario has a swingarm; an empty carrier handle: none. At most one extension
  /// of a model may give one (the vehicle checks). The front frame is not built yet.
  virtual BodyCarrier addSwingarmCarrier(BuildContext& context, const VehicleFrames& frames, const SimTK::Vec3& p_DP) {
    return {};
  }
  /// Puts a carrier between the front frame and the front wheel; an empty carrier handle: none. At
  /// most one extension of a model may give one (the vehicle checks).
  virtual BodyCarrier addFrontHubCarrier(BuildContext& context, const VehicleFrames& frames) { return {}; }
  /// Adds force elements (after the wheels and contacts). The only stage that may allocate auxiliary
  /// states (z): the vehicle names them, in order, right after it.
  virtual void addForces(BuildContext& context, const VehicleFrames& frames) {}
  /// The auxiliary states (z) its forces allocate, in allocation order, with their roles.
  virtual std::vector<AuxiliaryState> getStates() const { return {}; }
  /// The bodies it built that take mass from the frames (adjustFrames), for reports.
  virtual std::vector<ExtensionBody> getBodies() const { return {}; }
  /// Names (with units) of the quantities calcOutputs reports, e.g. an applied torque.
  virtual std::vector<std::string> getOutputNames() const { return {}; }
  /// Their values in a state realized to Velocity.
  virtual std::vector<double> calcOutputs(const SimTK::State& state) const { return {}; }
  /// Writes what it adds, with its values and units, for the model listing of `scenario check`: one
  /// or more lines, each indented by two spaces and ending in a newline (the stream's number format
  /// is the listing's).
  virtual void describe(std::ostream& out) const = 0;
};

/// Makes a model extension from its scenario section (`params`: the section's mapping) and the
/// vehicle it extends. The factory reads and checks every key (InputError at file:line:col).
using ExtensionModelFactory =
    std::function<std::unique_ptr<ExtensionModel>(io::YamlMap& params, const VehicleLayout& vehicle)>;

/// What a plugin's entry point registers into: factories by name. Names are unique across all
/// plugins (built-in and loaded); a duplicate is reported when the registration is committed.
class PluginRegistrar {
 public:
  virtual ~PluginRegistrar() = default;
  virtual void addContactModel(const std::string& name, ContactModelFactory factory) = 0;
  virtual void addSwingarmModel(const std::string& name, SwingarmModelFactory factory) = 0;
  /// Registers a model extension under the name of its scenario section (e.g. "steer_damper").
  virtual void addExtensionModel(const std::string& name, ExtensionModelFactory factory) = 0;
  /// Declares the fields of a section a plugin reads (io/field.h): its measured fields join the
  /// parameter list diagnosis varies, and `motostab fields` prints its docs table.
  virtual void addSectionFields(io::SectionFields fields) = 0;
};

}  // namespace motostab::plugins

/// Entry point a plugin library defines: MOTOSTAB_PLUGIN_ENTRY { registry.addContactModel(...); }.
/// It also exports the API version the library was built against, checked before registration.
#define MOTOSTAB_PLUGIN_ENTRY                                                          \
  extern "C" int motostab_plugin_api_version() { return MOTOSTAB_PLUGIN_API_VERSION; } \
  extern "C" void motostab_register_plugins(motostab::plugins::PluginRegistrar& registry)

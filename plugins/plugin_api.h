#pragma once
// The motostab plugin API. A plugin is a named factory with its own validated parameters.
// Built-in plugins live in tyres/ and swingarm/; third-party plugins are shared libraries that
// export MOTOSTAB_PLUGIN_ENTRY (see docs/plugins.md).
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "simbody/internal/GeneralForceSubsystem.h"
#include "simbody/internal/MobilizedBody.h"
#include "simbody/internal/MultibodySystem.h"
#include "simbody/internal/SimbodyMatterSubsystem.h"

#include "scenario/scenario.h"
#include "scenario/yaml_map.h"

namespace motostab {

/// One wheel as a contact model sees it. The wheel body's origin is the wheel centre and its
/// spin axis is the body y axis.
struct WheelSite {
  std::string name;              ///< "rear_wheel" or "front_wheel"
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
  /// Names of auxiliary states (z) this model allocates, in allocation order, per wheel.
  virtual std::vector<std::string> getStateNames(const WheelSite& wheel) const { return {}; }
};

/// Makes a contact model from its scenario parameters; must call params.finish() after reading.
using ContactModelFactory = std::function<std::unique_ptr<ContactModel>(YamlMap& params)>;

/// Plugins registered by name. Names are unique across built-in and loaded plugins.
class PluginRegistry {
 public:
  /// Registers a contact model; a duplicate name throws std::runtime_error.
  void addContactModel(const std::string& name, ContactModelFactory factory);
  /// Creates the contact model a scenario names; an unknown name is an InputError at spec.path.model.
  std::unique_ptr<ContactModel> createContactModel(const PluginSpec& spec) const;
  std::vector<std::string> getContactModelNames() const;
  /// Loads a plugin library and calls its entry point; failures are InputErrors at `where`.
  void loadLibrary(const std::string& path, const InputLocation& where);

 private:
  std::map<std::string, ContactModelFactory> contactModels_;
  std::string loadingLibrary_;  ///< set while a library registers, for messages
};

}  // namespace motostab

/// Entry point a plugin library defines: MOTOSTAB_PLUGIN_ENTRY { registry.addContactModel(...); }
#define MOTOSTAB_PLUGIN_ENTRY extern "C" void motostab_register_plugins(motostab::PluginRegistry& registry)

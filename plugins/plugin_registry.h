#pragma once
// The plugin registry: built-in and shared-library plugins by name, and the creation of the models a
// scenario selects. Libraries come from explicit paths only, are loaded once per process, must
// export the plugin API version of plugins/plugin_api.h, and register all their names or none.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "plugins/plugin_api.h"
#include "scenario/scenario.h"

namespace motostab::plugins {

/// The vehicle an extension sees (plugin_api.h VehicleLayout): the scenario's geometry, wheel radii and frames.
VehicleLayout makeVehicleLayout(const scenario::Scenario& scenario);

class PluginRegistry;

/// Every declared section: the loader's own (scenario/scenario_fields.h), then the plugins' of
/// `registry`; a plugin's fields of a loader's section (the swingarm models') join that section.
std::vector<io::SectionFields> listSectionFields(const PluginRegistry& registry);

/// Plugins registered by name. Names are unique across built-in and loaded plugins. A registry is a
/// value: copying it copies the factories (sweep workers build their models from a copy).
class PluginRegistry : public PluginRegistrar {
 public:
  /// Registers a contact model; a duplicate name throws std::runtime_error.
  void addContactModel(const std::string& name, ContactModelFactory factory) override;
  /// Creates the contact model a scenario names; an unknown name is an InputError at spec.path.model.
  /// The plugin reads the files its section names through `inputs` and records its warnings there.
  std::unique_ptr<ContactModel> createContactModel(const scenario::PluginSpec& spec,
                                                   std::shared_ptr<io::InputStore> inputs = nullptr) const;
  std::vector<std::string> getContactModelNames() const;
  /// Registers a swingarm compliance model; a duplicate name throws std::runtime_error.
  void addSwingarmModel(const std::string& name, SwingarmModelFactory factory) override;
  /// Creates the model named by `swingarm.compliance`; unknown names are InputErrors there.
  std::unique_ptr<SwingarmModel> createSwingarmModel(const scenario::SwingarmSpec& spec,
                                                     std::shared_ptr<io::InputStore> inputs = nullptr) const;
  /// Reads the plugin sections of a loaded scenario once, as building its model would: loads its
  /// plugin libraries, creates its contact, swingarm and extension models (the files they name are read into
  /// `s.inputs` and kept for every later build) and appends the warnings they found to `s.warnings`
  /// (ScenarioWarning::Check::PluginInput). Commands call it right after loading; InputError as a build.
  void readScenarioSections(scenario::Scenario& s);
  std::vector<std::string> getSwingarmModelNames() const;
  /// Registers a model extension under its section name; a duplicate name throws std::runtime_error.
  /// Extensions run their assembly stages in registration order.
  void addExtensionModel(const std::string& name, ExtensionModelFactory factory) override;
  /// The model extensions of the scenario's extension sections, in registration order (not file
  /// order: the stages and the order of forces do not depend on how a file is laid out). A section no
  /// extension is registered for is an InputError at it, naming the known ones.
  std::vector<std::unique_ptr<ExtensionModel>> createExtensionModels(const scenario::Scenario& scenario,
                                                                     std::shared_ptr<io::InputStore> inputs = nullptr) const;
  /// Names of the registered extensions, in registration order.
  std::vector<std::string> getExtensionModelNames() const;
  /// Declares a plugin section's fields; a section declared twice throws std::runtime_error.
  void addSectionFields(io::SectionFields fields) override;
  /// The plugins' declared sections, in registration order.
  const std::vector<io::SectionFields>& getSectionFields() const { return sectionFields_; }

  /// Adds the plugins of the library at `path` (absolute, or relative to the working directory;
  /// a bare file name is refused rather than searched on the system path). The library is opened
  /// and its entry point called once per process; later loads reuse what it registered. A library
  /// already added to this registry is skipped. Its API version must equal
  /// MOTOSTAB_PLUGIN_API_VERSION. Registration is all-or-nothing: on any failure (entry point
  /// throws, duplicate name) no name of the library is added. Failures are InputErrors at `where`.
  void loadLibrary(const std::string& path, const io::InputLocation& where);
  /// Adds the libraries a scenario lists under `plugins` (loadLibrary; InputError at `plugins[i]`).
  void loadScenarioLibraries(const scenario::Scenario& s);
  /// Canonical paths of the libraries added to this registry, in load order.
  const std::vector<std::string>& getLibraries() const { return libraries_; }

 private:
  void checkUnique(const std::string& name) const;
  std::map<std::string, ContactModelFactory> contactModels_;
  std::map<std::string, SwingarmModelFactory> swingarmModels_;
  std::vector<std::pair<std::string, ExtensionModelFactory>> extensionModels_;
  std::vector<io::SectionFields> sectionFields_;
  std::vector<std::string> libraries_;
};

}  // namespace motostab::plugins

#pragma once
// Model-extension sections of a scenario in tests: read one as its plugin does, or set one.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "io/yaml_map.h"
#include "scenario/scenario.h"

namespace motostab::testing {

/// The extension section `name` of `s` as its plugin reads it (a test failure when there is none:
/// then an empty mapping).
inline io::YamlMap getExtensionSection(const scenario::Scenario& s, const std::string& name) {
  const scenario::PluginSpec* e = scenario::findExtension(s, name);
  EXPECT_NE(e, nullptr) << "no section " << name;
  return e ? io::YamlMap(e->params, e->file, e->path) : io::YamlMap(YAML::Node(YAML::NodeType::Map), "", name);
}

/// The YAML value at `key` of the extension section `name` of `s` (a test failure when there is no
/// such section: then an undefined node).
inline YAML::Node getExtensionValue(const scenario::Scenario& s, const std::string& name, const std::string& key) {
  const scenario::PluginSpec* e = scenario::findExtension(s, name);
  EXPECT_NE(e, nullptr) << "no section " << name;
  return e ? YAML::Node(e->params[key]) : YAML::Node();
}

/// Sets the extension section `name` of `s` to the YAML mapping `yaml`, replacing the one there is.
inline void setExtension(scenario::Scenario& s, const std::string& name, const std::string& yaml) {
  auto& e = s.extensions;
  e.erase(std::remove_if(e.begin(), e.end(), [&](const scenario::PluginSpec& x) { return x.model == name; }), e.end());
  e.push_back({name, YAML::Load(yaml), s.sourceFile, name, {s.sourceFile, 0, 0, name}});
}

}  // namespace motostab::testing

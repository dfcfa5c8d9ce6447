#include "scenario/scenario_source.h"

#include "io/yaml_map.h"

namespace motostab::scenario {

using io::InputError;
using io::copyTree;
using io::loadYamlFile;

ScenarioSource::ScenarioSource(std::string file) : file_(std::move(file)), tree_(loadYamlFile(file_).getNode()) {}

ScenarioSource::ScenarioSource(YAML::Node tree, std::string name) : file_(std::move(name)), tree_(copyTree(tree)) {}

std::shared_ptr<const ScenarioSource> ScenarioSource::open(const std::string& file) {
  return std::make_shared<const ScenarioSource>(file);
}

YAML::Node ScenarioSource::makeTree(const ParameterOverrides& changes) const {
  YAML::Node tree = copyTree(tree_);
  changes.applyTo(tree);
  return tree;
}

Scenario ScenarioSource::load(const ParameterOverrides& changes) const {
  const std::vector<std::string> texts = changes.format();
  const YAML::Node tree = makeTree(changes);
  try {
    return readScenarioTree(tree, file_, texts, inputs_);
  } catch (const InputError& e) {
    rethrowNamingOverride(e, texts);
  }
}

}  // namespace motostab::scenario

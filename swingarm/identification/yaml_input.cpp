#include "swingarm/identification/yaml_input.h"

namespace motostab::identification {

YamlMap openTestFile(const std::filesystem::path& file, const std::string& kind) {
  YamlMap root = loadYamlFile(file.string());
  const std::string t = root.getString("test");
  if (t != kind) root.fail("test", "expected 'test: " + kind + "', found '" + t + "'");
  return root;
}

}  // namespace motostab::identification

#include "swingarm/identification/yaml_input.h"

namespace motostab::swingarm::identification {

using io::YamlMap;
using io::loadYamlFile;


YamlMap openTestFile(const std::filesystem::path& file, const std::string& kind) {
  YamlMap root = loadYamlFile(file.string());
  const std::string t = root.getString("test");
  if (t != kind) root.fail("test", "expected 'test: " + kind + "', found '" + t + "'");
  return root;
}

PlatePoint readForcePoint(YamlMap& root) {
  YamlMap fp = root.getMap("force_point");
  const PlatePoint p{fp.getDouble("x"), fp.getDouble("z")};
  fp.finish();
  return p;
}

}  // namespace motostab::swingarm::identification

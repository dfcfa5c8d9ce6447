// Fuzz target: the strict YAML layer (io/yaml_map.h) on any YAML text, anchors and aliases included:
// loading is bounded (one document, aliases expanded at most once, a node budget), and a loaded tree can
// be copied (copyTree, as every scenario variant is) and read through YamlMap.
#include "io/yaml_map.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

// Reads every key of `m` as its kind allows, recursing into maps and lists of maps.
void readAll(motostab::io::YamlMap m, int depth) {
  if (depth > 64) return;
  for (const auto& kv : m.getNode()) {
    const std::string key = kv.first.Scalar();
    const YAML::Node v = kv.second;
    if (v.IsMap()) readAll(m.getMap(key), depth + 1);
    else if (v.IsScalar()) m.getString(key);
    else if (v.IsSequence()) m.markUsed(key);
    else m.markUsed(key);
  }
  m.finish();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto dir = motostab::fuzz::resetScratchDir();
  const auto file = motostab::fuzz::writeScratchFile(dir, "input.yaml", std::string(reinterpret_cast<const char*>(data), size));
  motostab::fuzz::expectInputErrorOnly([&] {
    const motostab::io::YamlMap root = motostab::io::loadYamlFile(file.string());
    readAll(motostab::io::YamlMap(motostab::io::copyTree(root.getNode()), file.string(), ""), 0);
  });
  return 0;
}

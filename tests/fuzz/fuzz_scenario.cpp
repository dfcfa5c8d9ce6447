// Fuzz target: the scenario loader (scenario/scenario.h, loadScenario) on one YAML file, and the
// built-in plugins reading its extension sections (no plugin library is loaded).
#include "plugins/builtin.h"
#include "scenario/scenario.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto dir = motostab::fuzz::resetScratchDir();
  const auto file = motostab::fuzz::writeScratchFile(dir, "scenario.yaml", std::string(reinterpret_cast<const char*>(data), size));
  motostab::fuzz::expectInputErrorOnly([&] {
    const motostab::scenario::Scenario s = motostab::scenario::loadScenario(file.string());
    motostab::scenario::calcMassSummary(s);
    motostab::plugins::makeBuiltinRegistry().createExtensionModels(s, s.inputs);
  });
  return 0;
}

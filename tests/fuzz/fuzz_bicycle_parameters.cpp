// Fuzz target: the BicycleParameters importer (scenario/bicycle_parameters.h). A file it converts must
// give a scenario that loads, or an InputError naming the bad value.
#include "scenario/bicycle_parameters.h"
#include "scenario/scenario.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto dir = motostab::fuzz::resetScratchDir();
  const auto file = motostab::fuzz::writeScratchFile(dir, "BikeBenchmark.txt", std::string(reinterpret_cast<const char*>(data), size));
  motostab::fuzz::expectInputErrorOnly([&] {
    const std::string yaml = motostab::scenario::convertBicycleParametersToScenario(file.string(), "fuzz");
    const auto scenario = motostab::fuzz::writeScratchFile(dir, "converted.yaml", yaml);
    motostab::scenario::loadScenario(scenario.string());
  });
  return 0;
}

// Fuzz target: the BicycleParameters importer (scenario/bicycle_parameters.h) as `motostab import` runs it:
// a file it converts gives a scenario that loads (checked before it is written), or an InputError naming
// the bad value in the parameter file.
#include "scenario/bicycle_parameters.h"
#include "scenario/scenario.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto dir = motostab::fuzz::resetScratchDir();
  const auto file = motostab::fuzz::writeScratchFile(dir, "BikeBenchmark.txt", std::string(reinterpret_cast<const char*>(data), size));
  motostab::fuzz::expectInputErrorOnly([&] {
    motostab::scenario::writeBicycleParametersScenario(file.string(), "fuzz", dir / "converted.yaml");
    motostab::scenario::loadScenario((dir / "converted.yaml").string());
  });
  return 0;
}

// Fuzz target: a `steer_controller` section (and any other extension section) appended to the benchmark
// bicycle, read, built into the multibody model and trimmed and linearised at 5 m/s. Bad input is an
// InputError; a model that cannot be trimmed a ResultError (exit 3); anything else is a finding.
#include <fstream>
#include <iterator>

#include "analysis/linearize.h"
#include "analysis/trim.h"
#include "io/result_error.h"
#include "scenario/scenario.h"
#include "tests/fuzz/fuzz_support.h"
#include "vehicle/vehicle_model.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string base = [] {
    std::ifstream in(MOTOSTAB_SOURCE_DIR "/scenarios/whipple-benchmark.yaml");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }();
  const auto dir = motostab::fuzz::resetScratchDir();
  const auto file = motostab::fuzz::writeScratchFile(
      dir, "controller.yaml", base + "\n" + std::string(reinterpret_cast<const char*>(data), size));
  motostab::fuzz::expectInputErrorOnly([&] {
    try {
      const motostab::vehicle::VehicleModel model(motostab::scenario::loadScenario(file.string()));
      motostab::analysis::linearize(model, motostab::analysis::calcTrim(model, 5.0));
    } catch (const motostab::io::ResultError&) {
    }
  });
  return 0;
}

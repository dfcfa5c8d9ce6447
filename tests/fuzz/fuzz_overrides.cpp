// Fuzz target: `--set` text (io/yaml_map.h parseOverride, scenario/parameter_overrides.h) applied to the
// benchmark bicycle and read as a scenario. Each line of the input is one KEY.PATH=VALUE assignment.
#include <sstream>

#include "scenario/parameter_overrides.h"
#include "scenario/scenario.h"
#include "scenario/scenario_source.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const motostab::scenario::ScenarioSource base(MOTOSTAB_SOURCE_DIR "/scenarios/whipple-benchmark.yaml");
  std::vector<std::string> assignments;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line) && assignments.size() < 16;) assignments.push_back(line);
  motostab::fuzz::expectInputErrorOnly([&] {
    const motostab::scenario::Scenario s = base.load(motostab::scenario::ParameterOverrides(assignments));
    motostab::scenario::calcMassSummary(s);
  });
  return 0;
}

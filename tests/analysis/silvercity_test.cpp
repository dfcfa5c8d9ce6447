// Kooijman, Schwab, Meijaard (2008), "Experimental validation of a model of an uncontrolled bicycle",
// Multibody Syst Dyn 19:115-132: the Maxwell Silvercity of Table 1 has weave and capsize speeds of
// about 3.99 and 7.90 m/s in the linear Whipple model. Its parameters come from BicycleParameters
// (Moore et al. 2010), tests/data/measured-data/BicycleParameters.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/temp_dir.h"
#include "analysis/sweep.h"
#include "io/atomic_file.h"
#include "scenario/bicycle_parameters.h"

namespace motostab::analysis {

using io::writeFileAtomically;
using scenario::convertBicycleParametersToScenario;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

const std::string kScenarios = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/";
const std::string kBicycles = std::string(MOTOSTAB_TEST_DATA_DIR) + "/measured-data/BicycleParameters/data/bicycles/";

double criticalSpeed(const SweepResult& s, ModeLabel mode) {
  for (const auto& c : s.criticalSpeeds)
    if (c.mode == mode) return c.speed;
  return NAN;
}

TEST(Silvercity, WeaveAndCapsizeSpeeds) {
  const VehicleModel model(loadScenario(kScenarios + "kooijman-silvercity.yaml"));
  SweepOptions opt;
  opt.start = 2, opt.stop = 10, opt.step = 0.5;
  const SweepResult s = runSweep(model, opt);
  EXPECT_NEAR(criticalSpeed(s, ModeLabel::Weave), 3.99, 0.01);
  EXPECT_NEAR(criticalSpeed(s, ModeLabel::Capsize), 7.90, 0.01);
}

// The imported parameter files give the same eigenvalues as the hand-written scenarios.
void expectSameEigenvalues(const std::string& parameterFile, const std::string& scenarioFile) {
  const auto tmp = makeTempDir("import") / ("motostab_import_" + std::filesystem::path(scenarioFile).stem().string() + ".yaml");
  writeFileAtomically(tmp, convertBicycleParametersToScenario(parameterFile, "imported"));
  const VehicleModel imported(loadScenario(tmp.string()));
  const VehicleModel written(loadScenario(scenarioFile));
  for (double v : {0.5, 3.0, 7.0}) {
    const LinearModel a = linearize(imported, calcTrim(imported, v));
    const LinearModel b = linearize(written, calcTrim(written, v));
    ASSERT_EQ(a.eigenvalues.size(), b.eigenvalues.size());
    for (int k = 0; k < a.eigenvalues.size(); ++k) {
      double best = INFINITY;
      for (int j = 0; j < b.eigenvalues.size(); ++j) best = std::min(best, std::abs(a.eigenvalues[k] - b.eigenvalues[j]));
      EXPECT_LT(best, 1e-9) << parameterFile << " v=" << v << " lambda=" << a.eigenvalues[k];
    }
  }
}

TEST(Silvercity, ImportedBenchmarkMatchesHandWrittenScenario) {
  expectSameEigenvalues(kBicycles + "Benchmark/Parameters/BenchmarkBenchmark.txt", kScenarios + "whipple-benchmark.yaml");
}

TEST(Silvercity, ImportedSilverMatchesHandWrittenScenario) {
  expectSameEigenvalues(kBicycles + "Silver/Parameters/SilverBenchmark.txt", kScenarios + "kooijman-silvercity.yaml");
}

}  // namespace
}  // namespace motostab::analysis

// The files of an uncertainty study with few samples: charts with no finite value to show (a
// regression with fewer samples than parameters + 2 has no index) are left out instead of failing
// the whole study at the gnuplot stage; every other file and chart is still written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/portable_random.h"
#include "tests/uncertainty/test_support.h"
#include "output/uncertainty_output.h"
#include "uncertainty/uncertainty_study.h"
#include "uncertainty/uncertainty_summary.h"

namespace motostab::output {

using core::PortableRandom;
using uncertainty::TaskResult;
using uncertainty::UncertaintyOptions;
using uncertainty::UncertaintySetup;
using uncertainty::UncertaintySummary;
using uncertainty::getTaskCount;
using uncertainty::prepareUncertainty;
using uncertainty::runTasks;
using uncertainty::summarizeUncertainty;

namespace {

namespace fs = std::filesystem;

// Six Whipple parameters (Meijaard et al. 2007, Table 1) with sigmas of 0.3-1 % of their nominal values.
std::string makeSixParameterSection(PortableRandom& g) {
  const std::vector<std::pair<std::string, double>> nominal{
      {"geometry.trail_m", 0.08}, {"geometry.wheelbase_m", 1.02}, {"rear_frame.mass_kg", 85},
      {"rear_frame.com_m[2]", 0.9}, {"front_frame.com_m[0]", 0.9}, {"rear_wheel.radius_m", 0.3}};
  std::vector<std::pair<std::string, double>> section;
  for (const auto& [path, value] : nominal) section.push_back({path, value * g.drawUniform(0.003, 0.01)});
  return test::makeSection(section);
}

struct Study {
  UncertaintySetup setup;
  std::vector<TaskResult> results;
  UncertaintySummary summary;
};

Study runStudy(const std::string& file, size_t samples, uint64_t seed) {
  UncertaintyOptions o;
  o.samples = samples, o.seed = seed, o.start = 3.5, o.stop = 7.0, o.step = 0.5;  // weave 4.29, capsize 6.02 m/s
  Study s{prepareUncertainty(file, {}, o), {}, {}};
  std::vector<size_t> all(getTaskCount(s.setup));
  for (size_t t = 0; t < all.size(); ++t) all[t] = t;
  s.results = runTasks(s.setup, all, 2);
  s.summary = summarizeUncertainty(s.setup, s.results);
  return s;
}

TEST(UncertaintyOutput, FewSamplesLeaveOutTheEmptySensitivityCharts) {
  PortableRandom g(20261125);
  const std::string file = test::writeScenarioWith("whipple-benchmark.yaml", makeSixParameterSection(g), "few-samples");
  const size_t p = 6;
  // 2 to 5 samples: below the p + 2 = 8 a regression on six parameters needs.
  const size_t few = 2 + g.drawIndex(4);
  const Study s = runStudy(file, few, g.drawBits());
  const fs::path dir = makeTempDir("uq-output-few");
  ASSERT_NO_THROW(writeUncertaintyOutputs(dir, "whipple", s.setup, s.summary, s.results));
  for (const char* f : {"summary.json", "samples.csv", "mode_quantiles.csv", "sensitivity.csv", "report.md",
                        "fan_real_part.png", "fan_frequency.svg"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  for (int m = 0; m < 2; ++m) {  // weave and capsize cross in every sample
    const auto& c = s.summary.criticalSpeeds[m];
    ASSERT_EQ(c.count, few) << c.mode;
    for (double index : c.sensitivity) EXPECT_TRUE(std::isnan(index)) << c.mode;
    EXPECT_TRUE(fs::exists(dir / ("histogram_" + c.mode + ".png"))) << c.mode;
    EXPECT_FALSE(fs::exists(dir / ("sensitivity_" + c.mode + ".png"))) << c.mode;
    EXPECT_FALSE(fs::exists(dir / ("sensitivity_" + c.mode + ".gp"))) << c.mode;
  }
  EXPECT_NE(test::readText(dir / "report.md").find("needs at least 8 samples"), std::string::npos);
  // The undefined indices (and the wobble, which does not cross here) are empty cells as the JSON's
  // null, never "nan" (sensitivity.csv, samples.csv, mode_quantiles.csv carried it with exit 0).
  for (const char* f : {"samples.csv", "mode_quantiles.csv", "sensitivity.csv"}) {
    const std::string text = test::readText(dir / f);
    EXPECT_EQ(text.find("nan"), std::string::npos) << f << "\n" << text;
    EXPECT_EQ(text.find("inf"), std::string::npos) << f << "\n" << text;
  }
  EXPECT_NE(test::readText(dir / "sensitivity.csv").find(",,"), std::string::npos);  // the empty index cells

  // p + 2 to p + 4 samples: the indices exist and their charts are drawn.
  const size_t enough = p + 2 + g.drawIndex(3);
  const Study t = runStudy(file, enough, g.drawBits());
  const fs::path dir2 = makeTempDir("uq-output-enough");
  ASSERT_NO_THROW(writeUncertaintyOutputs(dir2, "whipple", t.setup, t.summary, t.results));
  for (int m = 0; m < 2; ++m) {
    const auto& c = t.summary.criticalSpeeds[m];
    EXPECT_TRUE(std::isfinite(c.sensitivity[0])) << c.mode;
    EXPECT_TRUE(fs::exists(dir2 / ("sensitivity_" + c.mode + ".png"))) << c.mode;
  }
}

}  // namespace
}  // namespace motostab::output

// The success path of `motostab diagnose` on the bundled example: Kooijman, Schwab, Meijaard (2008)
// riderless Silvercity, 26 measured weave eigenvalues with their speed ranges and run 52's lean-rate
// trace, every default candidate, the robustness reruns on. The named cause must be the tyres' crown
// radius, within 10-40 mm: the scenario's knife-edge wheels leave out the rounded crown of a real
// tyre, whose radius is of the order of half the tyre's width (25-50 mm wide bicycle tyres: 12-25 mm;
// the range allows for the fit standing in for more than the crown). The files, the report's sections and the
// robustness entries (each data source left out, speed ranges at mid speeds) are checked.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/apps/cli_support.h"

namespace {

namespace fs = std::filesystem;

TEST(DiagnoseKooijman, NamesTheTyreCrownWithItsRobustness) {
  const fs::path out = makeTempDir("diagnose_kooijman_" + std::to_string(getpid())) / "out";
  const CliRun r = runCli({"diagnose", "scenarios/kooijman-silvercity.yaml", "examples/diagnosis/kooijman2008.yaml",
                          "--threads", "2", "--out", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* f : {"diagnosis.json", "report.md", "residuals.csv", "extended.yaml", "eigen_weave.csv", "run1_lean_rate_V.csv"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_GE(checkOutputsParse(out), 4);
  const nlohmann::json j = readJson(out / "diagnosis.json");
  ASSERT_GE(j["causes"].size(), 1u);
  const std::string name = j["causes"][0]["name"];
  EXPECT_TRUE(name == "tyre_crown" || name == "parameter:front_wheel.crown_radius_m") << name;
  const auto& params = j["causes"][0]["parameters"];
  const double crown = params.contains("crown_radius_m") ? params["crown_radius_m"]["value"].get<double>()
                                                         : params["value"]["value"].get<double>();
  EXPECT_GT(crown, 0.010);
  EXPECT_LT(crown, 0.040);
  ASSERT_EQ(j["robustness"].size(), 3u);
  EXPECT_EQ(j["robustness"][0]["left_out"], "eigenvalues: kooijman2008-weave.csv");
  EXPECT_EQ(j["robustness"][1]["left_out"], "response run 1: kooijman2008_fig6_run52_lean_rate.csv");
  EXPECT_EQ(j["robustness"][2]["left_out"], "speed ranges -> mid speeds");
  EXPECT_TRUE(j.contains("fragile"));
  EXPECT_FALSE(j["noise"]["run1.lean_rate_V"]["ar"].empty()) << "the trace's residuals are autocorrelated";
  std::ifstream in(out / "report.md");
  std::stringstream report;
  report << in.rdbuf();
  for (const char* s : {"## The data", "## What the model gets wrong", "## Candidates", "## The cause", "## Robustness",
                        "## The extension", "## The gain"})
    EXPECT_NE(report.str().find(s), std::string::npos) << s;
  std::ifstream yaml(out / "extended.yaml");
  std::stringstream extended;
  extended << yaml.rdbuf();
  EXPECT_NE(extended.str().find("crown_radius_m: 0.0"), std::string::npos);
  fs::remove_all(out.parent_path());
}

}  // namespace

// Measured data with a controller in the loop (diagnosis/controller_groups.h): the setting of each
// eigenvalue file, row and response run is read strictly, each row is predicted with its own setting
// (checked against a direct linearisation of the scenario with that setting), a candidate's override
// acts on every setting, and the controller's candidates are listed.
#include "tests/support/extension_sections.h"
#include "diagnosis/controller_groups.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "analysis/linearize.h"
#include "analysis/trim.h"
#include "diagnosis/candidates.h"
#include "diagnosis/prediction.h"
#include "io/csv.h"
#include "core/portable_random.h"
#include "scenario/bicycle_parameters.h"
#include "scenario/bicycle_parameters_uncertainty.h"
#include "scenario/parameter_paths.h"
#include "vehicle/vehicle_model.h"

namespace motostab::diagnosis {

using analysis::calcTrim;
using analysis::linearize;
using core::PortableRandom;
using io::InputError;
using scenario::Scenario;
using scenario::convertBicycleParametersToScenario;
using scenario::formatBicycleParametersUncertainty;
using scenario::formatOverride;
using scenario::loadScenario;
using scenario::readBicycleParameterSigmas;
using vehicle::VehicleModel;

namespace {

namespace fs = std::filesystem;
const std::string kBenchmark = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

class ControllerDataTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("motostab-controller-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  std::string error(const std::string& yamlText) {
    try {
      loadMeasuredData(write("m.yaml", yamlText));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(ControllerDataTest, SettingPerFileAndPerRow) {
  write("a.csv", "speed_mps,mode,real,imag\n2,weave,-1,5\n3,weave,-1,6\n");
  write("b.csv", "speed_mps,mode,real,imag,steer_controller.roll_rate_Nms_per_rad\n2,weave,-1,7,-10\n3,weave,-1,8,-6\n");
  std::string run = "t,g\n";
  for (int i = 0; i < 30; ++i) run += std::to_string(0.01 * i) + "," + std::to_string(0.1 * i) + "\n";
  write("run.csv", run);
  const MeasuredData d = loadMeasuredData(write("m.yaml",
                                                "eigenvalues:\n"
                                                "  - file: a.csv\n"
                                                "    controller: {roll_rate_Nms_per_rad: -8, schedule: {below_mps: 5}}\n"
                                                "  - file: b.csv\n"
                                                "    controller: {delay_s: 0.02}\n"
                                                "responses:\n"
                                                "  - {file: run.csv, speed_mps: 3, time_column: t, signals: [{column: g, quantity: roll_rate}],\n"
                                                "     controller: {roll_rate_Nms_per_rad: -8, schedule: {below_mps: 5}}}\n"));
  ASSERT_EQ(d.eigenvalues.size(), 4u);
  EXPECT_EQ(d.eigenvalues[0].controller,
            (std::vector<std::string>{"steer_controller.roll_rate_Nms_per_rad=-8", "steer_controller.schedule={below_mps: 5}"}));
  EXPECT_EQ(d.eigenvalues[2].controller,
            (std::vector<std::string>{"steer_controller.delay_s=0.02", "steer_controller.roll_rate_Nms_per_rad=-10"}));
  EXPECT_EQ(d.eigenvalues[3].controller.back(), "steer_controller.roll_rate_Nms_per_rad=-6");
  const std::vector<ControllerGroup> g = splitByController(d);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_EQ(g[0].rows, (std::vector<size_t>{0, 1}));
  EXPECT_EQ(g[0].runs, (std::vector<size_t>{0}));  // the run has the first file's setting
  ASSERT_EQ(g[0].data.responses.size(), 1u);
  EXPECT_TRUE(g[1].runs.empty());
  EXPECT_EQ(g[1].rows, (std::vector<size_t>{2}));
  EXPECT_EQ(g[2].rows, (std::vector<size_t>{3}));
  EXPECT_TRUE(g[1].data.eigenvalues[0].controller.empty());
  EXPECT_EQ(getControllerPaths(d), (std::vector<std::string>{"steer_controller.delay_s", "steer_controller.roll_rate_Nms_per_rad",
                                                             "steer_controller.schedule"}));
}

TEST_F(ControllerDataTest, BadSettingsNameFileLineColumn) {
  write("a.csv", "speed_mps,mode,real,imag\n2,weave,-1,5\n");
  EXPECT_NE(error("eigenvalues:\n  - file: a.csv\n    controller: {roll_rate: -8}\n").find("m.yaml:3:18: eigenvalues[0].controller.roll_rate"),
            std::string::npos)
      << error("eigenvalues:\n  - file: a.csv\n    controller: {roll_rate: -8}\n");
  EXPECT_NE(error("eigenvalues:\n  - file: a.csv\n    controller: {delay_s: .nan}\n").find("m.yaml:3:18: eigenvalues[0].controller.delay_s"),
            std::string::npos);
  EXPECT_NE(error("eigenvalues:\n  - file: a.csv\n    controller: -8\n").find("m.yaml:3:5: eigenvalues[0].controller: expected a mapping"), std::string::npos);
  write("c.csv", "speed_mps,mode,real,imag,steer_controller.roll_rate\n2,weave,-1,5,1\n");
  EXPECT_NE(error("eigenvalues:\n  - file: c.csv\n").find("steer_controller.roll_rate"), std::string::npos);
  write("d.csv", "speed_mps,mode,real,imag,steer_controller.delay_s\n2,weave,-1,5,nan\n");
  EXPECT_NE(error("eigenvalues:\n  - file: d.csv\n").find("d.csv:2"), std::string::npos);
}

// The weave (the one complex pair with imag > 0 of the Whipple benchmark at 2-6 m/s, with or without
// roll-rate feedback) of the scenario with `overrides`, linearised directly.
std::complex<double> calcWeave(const std::vector<std::string>& overrides, double v) {
  const VehicleModel model(loadScenario(kBenchmark, overrides));
  const Eigen::VectorXcd e = linearize(model, calcTrim(model, v)).eigenvalues;
  for (int i = 0; i < e.size(); ++i)
    if (e[i].imag() > 1e-6) return e[i];
  return {NAN, NAN};
}

TEST(ControllerGroups, EachRowIsPredictedWithItsOwnSetting) {
  PortableRandom rng(909);
  const double gains[] = {-10, -25, 0};
  MeasuredData data;
  for (int i = 0; i < 9; ++i) {
    MeasuredEigenvalue e;
    e.speed = e.speedMin = e.speedMax = rng.drawUniform(2, 6);
    e.mode = analysis::ModeLabel::Weave;
    e.controller = {formatOverride("steer_controller.roll_rate_Nms_per_rad", gains[i % 3])};
    data.eigenvalues.push_back(e);
  }
  const Predictor p(kBenchmark, {}, data);
  const double factor = rng.drawUniform(0.4, 0.8);
  const Prediction nominal = p.predict({}, {}), scaled = p.predict({formatOverride("steer_controller.gain_factor", factor)}, {});
  for (size_t i = 0; i < data.eigenvalues.size(); ++i) {
    const double v = data.eigenvalues[i].speed, k = gains[i % 3];
    const auto ref = calcWeave({formatOverride("steer_controller.roll_rate_Nms_per_rad", k)}, v);
    const auto refScaled = calcWeave({formatOverride("steer_controller.roll_rate_Nms_per_rad", k * factor)}, v);
    EXPECT_LT(std::abs(nominal.eigenvalues[i] - ref), 1e-8) << "gain " << k << " at " << v << " m/s";
    EXPECT_LT(std::abs(scaled.eigenvalues[i] - refScaled), 1e-8) << "gain " << k << " x " << factor << " at " << v;
  }
  EXPECT_GT(std::abs(nominal.eigenvalues[0] - nominal.eigenvalues[1]), 0.1);  // the settings differ
}

TEST(ControllerGroups, ControllerCandidates) {
  YAML::Node tree = YAML::LoadFile(kBenchmark);
  std::vector<Candidate> none = listCandidates(tree, {});
  for (const auto& c : none) EXPECT_EQ(c.name.find("steer_controller"), std::string::npos) << c.name;
  tree["steer_controller"] = YAML::Load("{roll_rate_Nms_per_rad: -8, schedule: {below_mps: 5}}");
  std::vector<std::string> names;
  for (const auto& c : listCandidates(tree, {})) names.push_back(c.name);
  for (const char* n : {"steer_controller_gain", "steer_controller_delay", "parameter:steer_controller.roll_rate_Nms_per_rad",
                        "parameter:steer_controller.schedule.below_mps"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
}

// The balance-assist case: scenarios/balance-assist.yaml is the import of BicycleParameters'
// Balanceassistv1 (every imported value and uncertainty unchanged) plus its controller, and the
// example's 21 rows split into the three gains; at 5.00 m/s the schedule (5 - v) switches the
// controller off, so the three gains' 5 m/s rows are one open-loop state: predicted identically,
// measured differently (Haitjema 2023, Tables 3-5: imag 4.660, 5.325, 4.167 rad/s).
TEST(ControllerGroups, BalanceAssistExample) {
  const std::string src = MOTOSTAB_SOURCE_DIR;
  const YAML::Node bundled = YAML::LoadFile(src + "/scenarios/balance-assist.yaml");
  const std::string txt = std::string(MOTOSTAB_TEST_DATA_DIR) +
                          "/measured-data/BicycleParameters/data/bicycles/Balanceassistv1/Parameters/Balanceassistv1Benchmark.txt";
  const YAML::Node imported = YAML::Load(convertBicycleParametersToScenario(txt, "balance-assist") +
                                         formatBicycleParametersUncertainty(readBicycleParameterSigmas(txt)));
  for (const char* key : {"gravity_mps2", "geometry", "rear_frame", "front_frame", "rear_wheel", "front_wheel", "contact", "uncertainty"})
    EXPECT_EQ(YAML::Dump(bundled[key]), YAML::Dump(imported[key])) << key;
  const Scenario s = loadScenario(src + "/scenarios/balance-assist.yaml");
  EXPECT_LT(testing::getExtensionValue(s, "steer_controller", "roll_rate_Nms_per_rad").as<double>(), 0);  // into the fall
  EXPECT_EQ(VehicleModel(s).getExtensionOutputNames(), std::vector<std::string>{"steer_controller_torque"});
  const MeasuredData data = loadMeasuredData(src + "/examples/balance-assist/weave.yaml");
  ASSERT_EQ(data.eigenvalues.size(), 21u);
  const std::vector<ControllerGroup> groups = splitByController(data);
  ASSERT_EQ(groups.size(), 3u);
  std::vector<size_t> open;
  for (const auto& g : groups) {
    EXPECT_EQ(g.rows.size(), 7u);
    for (size_t r : g.rows)
      if (data.eigenvalues[r].speed == 5.0) open.push_back(r);
  }
  ASSERT_EQ(open.size(), 3u);
  MeasuredData openData;
  for (size_t r : open) openData.eigenvalues.push_back(data.eigenvalues[r]);
  const Prediction p = Predictor(src + "/scenarios/balance-assist.yaml", {}, openData).predict({}, {});
  EXPECT_LT(std::abs(p.eigenvalues[0] - p.eigenvalues[1]), 1e-12);
  EXPECT_LT(std::abs(p.eigenvalues[0] - p.eigenvalues[2]), 1e-12);
  EXPECT_GT(std::abs(openData.eigenvalues[1].imag - openData.eigenvalues[2].imag), 1.0);
}

}  // namespace
}  // namespace motostab::diagnosis

// motostab trim, and sweep/linearize with --roll-deg, run as a user would: pinned trim.json keys,
// map outputs, and the exit codes of bad turn input (2) and of a trim that fails (3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "nlohmann/json.hpp"
#include "tests/apps/cli_support.h"
#include "tests/support/temp_dir.h"

namespace motostab::cli {
namespace {

const std::string kScenarios = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/";

struct Outcome {
  int code;
  std::string output;
};

Outcome run(const std::string& test, const std::vector<std::string>& args) {
  const auto dir = makeTempDir("turn_cli_" + test);
  Outcome o;
  o.code = test::runMotostab(args, dir.string(), o.output);
  return o;
}

TEST(TurnCli, TrimWritesThePinnedKeys) {
  const auto dir = makeTempDir("turn_cli_trim");
  std::string output;
  ASSERT_EQ(test::runMotostab({"trim", kScenarios + "supersport.yaml", "--speed", "30", "--roll-deg", "-35", "--out", "t"},
                              dir.string(), output),
            0)
      << output;
  std::ifstream in(dir / "t" / "trim.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  for (const char* key : {"speed_mps", "roll_rad", "steer_rad", "pitch_rad", "steer_torque_Nm", "yaw_rate_radps",
                          "path_radius_m", "lateral_acceleration_mps2", "residual", "tyres"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_NEAR(j["speed_mps"].get<double>(), 30, 1e-9);
  EXPECT_NEAR(j["roll_rad"].get<double>(), -35 * M_PI / 180, 1e-15);
  // Leaning left turns left; speed = path radius x yaw rate; lateral acceleration = speed x yaw rate.
  const double r = j["yaw_rate_radps"], radius = j["path_radius_m"];
  EXPECT_GT(r, 0);
  EXPECT_NEAR(radius * r, 30, 1e-9);
  EXPECT_NEAR(j["lateral_acceleration_mps2"].get<double>(), 30 * r, 1e-9);
  EXPECT_LT(j["residual"].get<double>(), 1e-10);
  for (const char* key : {"front_tyre_Fy_N", "rear_tyre_Fy_N", "rear_tyre_slip_angle_rad", "rear_tyre_camber_rad"})
    EXPECT_TRUE(j["tyres"].contains(key)) << key;
  EXPECT_NE(output.find("steer torque"), std::string::npos) << output;
}

// trim.json of `trim --hands-free` on the Whipple bicycle at `rollDeg` over `speeds`, run in a new
// folder; `output`: what it printed.
nlohmann::json runHandsFreeWhipple(const std::string& test, const std::string& rollDeg, const std::string& speeds,
                                   std::string& output) {
  const auto dir = makeTempDir("turn_cli_" + test);
  EXPECT_EQ(test::runMotostab({"trim", kScenarios + "whipple-benchmark.yaml", "--roll-deg", rollDeg, "--hands-free",
                               "--speeds", speeds, "--out", "h"},
                              dir.string(), output),
            0)
      << output;
  std::ifstream in(dir / "h" / "trim.json");
  return nlohmann::json::parse(in);
}

TEST(TurnCli, HandsFreeTrimHasZeroSteerTorque) {
  std::string output;
  const nlohmann::json j = runHandsFreeWhipple("hands_free", "3", "4:8:0.5", output);
  EXPECT_EQ(j["steer_torque_Nm"].get<double>(), 0.0);
  EXPECT_NEAR(j["speed_mps"].get<double>(), 6.0, 0.1);  // near the capsize speed, 6.024 m/s
  EXPECT_TRUE(j["tyres"].empty());                        // rolling constraints report no tyre outputs
}

// trim.json of --hands-free lists every turn on the grid, sorted by speed, the one continuing from
// straight running marked and the default (the Whipple bicycle at 20 deg: 3.14 and 5.53 m/s, the latter
// reached from the capsize speed).
TEST(TurnCli, HandsFreeTrimListsEveryTurn) {
  std::string output;
  const nlohmann::json j = runHandsFreeWhipple("hands_free_list", "20", "0.5:8:0.25", output);
  const nlohmann::json& turns = j.at("hands_free_turns");
  ASSERT_GE(turns.size(), 2u);
  int marked = 0, defaults = 0;
  bool slow = false;
  for (size_t i = 0; i < turns.size(); ++i) {
    const nlohmann::json& t = turns[i];
    EXPECT_EQ(t.at("steer_torque_Nm").get<double>(), 0.0);
    EXPECT_GT(t.at("path_radius_m").get<double>(), 0.0);
    if (i > 0) EXPECT_LT(turns[i - 1].at("speed_mps").get<double>(), t.at("speed_mps").get<double>());
    slow = slow || std::abs(t.at("speed_mps").get<double>() - 3.14) < 0.01;
    if (t.at("continues_from_straight_running").get<bool>()) {
      ++marked;
      EXPECT_NEAR(t.at("speed_mps").get<double>(), 5.53, 0.01);
      EXPECT_TRUE(t.at("default").get<bool>());
    }
    defaults += t.at("default").get<bool>();
  }
  EXPECT_TRUE(slow) << "the 3.14 m/s turn is missing";
  EXPECT_EQ(marked, 1);
  EXPECT_EQ(defaults, 1);
  EXPECT_TRUE(j.at("continues_from_straight_running").get<bool>());  // the top level is the default turn
  EXPECT_NEAR(j.at("speed_mps").get<double>(), 5.53, 0.01);
  EXPECT_NE(output.find("from straight running"), std::string::npos) << output;
}

// A speed x roll map keeps the points that trim: the enduro's turn at 1 m/s and 5 deg does not (the
// roll continuation stalls), the other points are written, the failed one is listed with its residual,
// and the exit code is 3 (docs/commands.md, exit codes).
TEST(TurnCli, PartialMapKeepsThePointsThatTrimAndExits3) {
  const auto dir = makeTempDir("turn_cli_partial_map");
  std::string output;
  EXPECT_EQ(test::runMotostab({"sweep", kScenarios + "enduro.yaml", "--roll-deg", "0:5:5", "--speeds", "1:3:1", "--out", "m"},
                              dir.string(), output),
            3)
      << output;
  EXPECT_NE(output.find("1 of 6 points of the map did not trim"), std::string::npos) << output;
  std::ifstream in(dir / "m" / "map_summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("failed_points").get<int>(), 1);
  std::ifstream rollIn(dir / "m" / "roll_+005.0deg" / "summary.json");
  const nlohmann::json roll = nlohmann::json::parse(rollIn);
  ASSERT_EQ(roll.at("failed_speeds").size(), 1u);
  EXPECT_EQ(roll["failed_speeds"][0].at("speed_mps").get<double>(), 1.0);
  EXPECT_GT(roll["failed_speeds"][0].at("residual").get<double>(), 1e-6);
  std::ifstream csv(dir / "m" / "map.csv");
  std::string line;
  std::set<std::string> points;  // roll and speed of every row
  std::getline(csv, line);
  while (std::getline(csv, line)) points.insert(line.substr(0, line.find(',', line.find(',') + 1)));
  EXPECT_EQ(points.size(), 5u) << "the five points that trim";
}

TEST(TurnCli, BadTurnInputExits2AndSaysWhatToChange) {
  const std::string w = kScenarios + "whipple-benchmark.yaml";
  struct Case {
    std::vector<std::string> args;
    std::string needle;
  };
  const std::vector<Case> cases{
      {{"trim", w, "--speed", "5", "--roll-deg", "89"}, "strictly between -89 and 89"},
      {{"trim", w, "--speed", "5", "--roll-deg", "-120"}, "strictly between -89 and 89"},
      {{"trim", w, "--speed", "5", "--roll-deg", "nan"}, "roll angle"},
      {{"trim", w, "--roll-deg", "5"}, "--speed"},
      {{"sweep", w, "--speeds", "0:5:1", "--roll-deg", "10"}, "start the speed grid above 0"},
      {{"sweep", w, "--speeds", "1:5:1", "--roll-deg", "0:95:5"}, "strictly between -89 and 89"},
      {{"linearize", w, "--speed", "0", "--roll-deg", "10", "--out", "x"}, "above 0"},
  };
  const std::string dir = makeTempDir("turn_cli_bad_input").string();
  for (const Case& c : cases) expectInputError(c.args, c.needle, dir);
}

// Valid input without a result: exit 3 (docs/commands.md, exit codes), saying what was tried.
TEST(TurnCli, FailedTrimExits3NamingSpeedRollAndResidual) {
  const Outcome o = run("failed", {"trim", kScenarios + "whipple-benchmark.yaml", "--speed", "0.5", "--roll-deg", "80", "--out", "f"});
  EXPECT_EQ(o.code, 3) << o.output;
  for (const char* needle : {"0.5 m/s", "roll 80 deg", "residual"}) EXPECT_NE(o.output.find(needle), std::string::npos) << o.output;
}

// No hands-free turn bracketed on a valid grid: exit 3 with what to change.
TEST(TurnCli, NoHandsFreeTurnExits3AndSaysWhatToChange) {
  const Outcome o = run("noturn", {"trim", kScenarios + "whipple-benchmark.yaml", "--roll-deg", "5", "--hands-free", "--speeds",
                                   "1:3:0.5", "--out", "n"});
  EXPECT_EQ(o.code, 3) << o.output;
  EXPECT_NE(o.output.find("widen --speeds or change --roll-deg"), std::string::npos) << o.output;
}

TEST(TurnCli, MapWritesEveryRollAndThePlots) {
  const auto dir = makeTempDir("turn_cli_map");
  std::string output;
  ASSERT_EQ(test::runMotostab({"sweep", kScenarios + "whipple-benchmark.yaml", "--speeds", "3:7:0.5", "--roll-deg", "0:20:10",
                               "--out", "m"},
                              dir.string(), output),
            0)
      << output;
  for (const char* f : {"map.csv", "map_summary.json", "damping_map.png", "root_loci.png", "real_part_vs_speed.png",
                        "roll_+000.0deg/eigenvalues.csv", "roll_+020.0deg/summary.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / "m" / f)) << f;
  std::ifstream in(dir / "m" / "map.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "roll_deg,speed_mps,mode,real,imag,frequency_hz,damping_ratio");
  std::set<std::string> weaveRolls;
  while (std::getline(in, line))
    if (line.find(",weave,") != std::string::npos) weaveRolls.insert(line.substr(0, line.find(',')));
  EXPECT_EQ(weaveRolls.size(), 3u) << "weave tracked at every roll";
}

// Values of one column of a CSV file (header row first), by name.
std::vector<double> readColumn(const std::filesystem::path& file, const std::string& name) {
  std::ifstream in(file);
  std::string line, cell;
  std::getline(in, line);
  int index = -1, k = 0;
  for (std::stringstream header(line); std::getline(header, cell, ','); ++k)
    if (cell == name) index = k;
  std::vector<double> out;
  while (index >= 0 && std::getline(in, line)) {
    std::stringstream row(line);
    for (int j = 0; j <= index; ++j) std::getline(row, cell, ',');
    out.push_back(std::stod(cell));
  }
  return out;
}

// Without a perturbation a simulation from a steady turn stays in it: the nonlinear model, integrated in
// ground coordinates with the PI speed control holding the trim's speed, keeps roll, steer and yaw rate.
TEST(TurnCli, SimulationFromASteadyTurnStaysInIt) {
  const auto dir = makeTempDir("turn_cli_simulate");
  std::string output;
  ASSERT_EQ(test::runMotostab({"simulate", kScenarios + "enduro.yaml", "--speed", "25", "--roll-deg", "30", "--duration", "2",
                               "--out", "s"},
                              dir.string(), output),
            0)
      << output;
  const auto roll = readColumn(dir / "s" / "timeseries.csv", "roll");
  const auto yawRate = readColumn(dir / "s" / "timeseries.csv", "yaw_rate");
  ASSERT_GT(roll.size(), 100u);
  EXPECT_NEAR(roll.front(), 30 * M_PI / 180, 1e-12);
  EXPECT_LT(yawRate.front(), 0);
  for (size_t k = 0; k < roll.size(); ++k) {
    EXPECT_NEAR(roll[k], roll.front(), 1e-5) << "sample " << k;
    EXPECT_NEAR(yawRate[k], yawRate.front(), 1e-5) << "sample " << k;
  }
}

TEST(TurnCli, StudyComparesSwingarmsAtARollAngle) {
  const auto dir = makeTempDir("turn_cli_study");
  std::string output;
  ASSERT_EQ(test::runMotostab({"study", kScenarios + "supersport.yaml", "--roll-deg", "20", "--speeds", "5:40:1", "--out", "st"},
                              dir.string(), output),
            0)
      << output;
  std::ifstream in(dir / "st" / "report.md");
  std::stringstream report;
  report << in.rdbuf();
  EXPECT_NE(report.str().find("steady turns at roll 20.0 deg"), std::string::npos) << report.str().substr(0, 600);
  const Outcome zero = run("study_zero", {"study", kScenarios + "supersport.yaml", "--roll-deg", "20", "--speeds", "0:40:1"});
  EXPECT_EQ(zero.code, 2) << zero.output;
}

TEST(TurnCli, LinearizeAboutATurnWritesTheHeadingFrameModel) {
  const auto dir = makeTempDir("turn_cli_linearize");
  std::string output;
  ASSERT_EQ(test::runMotostab({"linearize", kScenarios + "enduro.yaml", "--speed", "30", "--roll-deg", "20", "--out", "l"},
                              dir.string(), output),
            0)
      << output;
  std::ifstream in(dir / "l" / "linear_model.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_TRUE(j["heading_frame"].get<bool>());
  EXPECT_NEAR(j["roll_rad"].get<double>(), 20 * M_PI / 180, 1e-15);
  const auto states = j["states"].get<std::vector<std::string>>();
  EXPECT_EQ(std::count(states.begin(), states.end(), "yaw"), 0) << "yaw is cyclic in the heading frame";
  EXPECT_EQ(std::count(states.begin(), states.end(), "roll"), 1);
}

}  // namespace
}  // namespace motostab::cli

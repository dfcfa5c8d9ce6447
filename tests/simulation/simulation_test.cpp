// Nonlinear simulation of the Whipple benchmark bicycle: energy conservation, settling to the trim at a
// self-stable speed, falls, pulse inputs, initial-rate projection, integrators and outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <iostream>

#include "tests/support/temp_dir.h"
#include "analysis/state_function.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "simulation/simulation.h"
#include "apps/simulate_identify.h"
#include "output/simulation_output.h"

namespace motostab::simulation {

using analysis::StateFunction;
using analysis::TrimResult;
using analysis::calcTrim;
using io::CsvTable;
using io::InputError;
using io::readCsv;
using output::writeResponsePlot;
using output::writeTimeseries;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

const Scenario& getWhipple() {
  static const Scenario s = loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml");
  return s;
}

double getLast(const SimulationResult& r, const std::string& name) { return r.rows.back()[r.getColumnIndex(name)]; }
double getTrim(const SimulationResult& r, const std::string& name) { return r.trimRow[r.getColumnIndex(name)]; }

// (c) Whipple with rolling_no_slip has no damping, slip or drag: kinetic plus gravitational energy is
// conserved while coasting, through a large lean-and-steer oscillation.
TEST(SimulationConservation, EnergyIsConservedWhileCoasting) {
  SimulationOptions o;
  o.speed = 5;
  o.duration = 10;
  o.speedControl = SpeedControl::None;
  o.accuracy = 1e-8;
  o.perturbations = {parsePerturbation("roll-rate:0.5")};
  const SimulationResult r = runSimulation(getWhipple(), o);
  ASSERT_EQ(r.status, SimulationStatus::Completed) << r.message;
  const auto energy = r.getColumn("energy");
  const auto rollRate = r.getColumn("roll_rate");
  double drift = 0, maxRollRate = 0;
  for (size_t k = 0; k < energy.size(); ++k) {
    drift = std::max(drift, std::abs(energy[k] - energy[0]));
    maxRollRate = std::max(maxRollRate, std::abs(rollRate[k]));
  }
  const double relative = drift / std::abs(energy[0]);
  std::cout << "energy " << energy[0] << " J, max relative drift over 10 s " << relative << " (accuracy 1e-8), "
            << r.steps << " steps\n";
  EXPECT_GE(maxRollRate, 0.5 - 1e-12);  // the motion is not trivial
  EXPECT_LT(relative, 1e-6);
}

// Speed control: with the PI controller the forward speed returns to the target after a perturbation;
// coasting it does not need to. Also checks that energy is not conserved when the controller works.
TEST(SimulationRobustness, SelfStableRunSettlesToTrim) {
  SimulationOptions o;
  o.speed = 5;  // inside the benchmark's self-stable range 4.29..6.02 m/s (Meijaard et al. 2007)
  o.duration = 60;
  o.outputStep = 0.02;
  o.perturbations = {parsePerturbation("steer-torque:5:0.1:0.2:halfsine"),
                     parsePerturbation("lateral-force:rear_frame:200:0.5:0.1")};
  const SimulationResult r = runSimulation(getWhipple(), o);
  ASSERT_EQ(r.status, SimulationStatus::Completed) << r.message;
  EXPECT_NEAR(r.endTime, 60, 1e-9);
  const auto roll = r.getColumn("roll");
  double maxRoll = 0;
  for (double x : roll) maxRoll = std::max(maxRoll, std::abs(x));
  std::cout << "v = 5 m/s, 60 s: max |roll| " << maxRoll << " rad; final roll " << getLast(r, "roll") << ", steer "
            << getLast(r, "steer") << ", yaw rate " << getLast(r, "yaw_rate") << ", speed " << getLast(r, "forward_speed")
            << "\n";
  EXPECT_GT(maxRoll, 0.01);  // the pulses did disturb it
  // Within the noise floor of the default accuracy and constraint tolerance 1e-6 (states wander by a few
  // 1e-6), four orders of magnitude below the disturbance.
  for (const char* name : {"roll", "steer", "pitch", "height", "roll_rate", "steer_rate", "yaw_rate"})
    EXPECT_NEAR(getLast(r, name), getTrim(r, name), 2e-5) << name;
  EXPECT_NEAR(getLast(r, "forward_speed"), 5, 1e-5);
  EXPECT_NEAR(getLast(r, "steer_torque"), getTrim(r, "steer_torque"), 1e-9);

  // Coasting, the same pulses leave the forward speed changed (no drag, energy conserved apart from the
  // pulses' work): the controller above did restore it.
  o.speedControl = SpeedControl::None;
  o.duration = 20;
  const SimulationResult coast = runSimulation(getWhipple(), o);
  ASSERT_EQ(coast.status, SimulationStatus::Completed) << coast.message;
  std::cout << "coasting: final speed " << getLast(coast, "forward_speed") << " m/s\n";
  EXPECT_GT(std::abs(getLast(coast, "forward_speed") - 5), 1e-3);
}

// At 2 m/s the benchmark's weave is unstable (Meijaard et al. 2007, Fig. 3): a lean kick grows until the
// bicycle falls; the run ends at the fall limit and keeps every sample up to it.
TEST(SimulationRobustness, UnstableRunFallsAndKeepsData) {
  SimulationOptions o;
  o.speed = 2;
  o.duration = 30;
  o.fallRollLimit = 45 * M_PI / 180;
  o.perturbations = {parsePerturbation("roll-rate:0.05")};
  const SimulationResult r = runSimulation(getWhipple(), o);
  ASSERT_EQ(r.status, SimulationStatus::Fell) << r.message;
  EXPECT_NE(r.message.find("fell"), std::string::npos);
  EXPECT_LT(r.endTime, 30);
  EXPECT_GT(std::abs(getLast(r, "roll")), 45 * M_PI / 180);
  EXPECT_NEAR(r.rows.size(), std::round(r.endTime / o.outputStep) + 1, 0.5);
  std::cout << r.message << "\n";

  const auto dir = makeTempDir("sim_fall_test");
  std::filesystem::remove_all(dir);
  writeTimeseries(dir, r);
  const CsvTable t = readCsv(dir / "timeseries.csv");
  EXPECT_EQ(t.header, r.columns);
  ASSERT_EQ(t.rows.size(), r.rows.size());
  EXPECT_EQ(t.rows.back(), r.rows.back());  // 17 digits round-trip exactly
  std::filesystem::remove_all(dir);
}

// Pulses switch exactly at their edges: the steer torque column holds the trim torque plus the pulse.
TEST(SimulationInputs, PulsesFollowTheirShape) {
  SimulationOptions o;
  o.speed = 5;
  o.duration = 1;
  o.outputStep = 0.01;
  o.speedControl = SpeedControl::None;
  o.perturbations = {parsePerturbation("steer-torque:2:0.2:0.3:halfsine"),
                     parsePerturbation("steer-torque:-1:0.6:0.1"),
                     parsePerturbation("lateral-force:front_wheel:50:0.25:0.05")};
  const SimulationResult r = runSimulation(getWhipple(), o);
  ASSERT_EQ(r.status, SimulationStatus::Completed) << r.message;
  const double trim = getTrim(r, "steer_torque");
  for (const auto& row : r.rows) {
    const double t = row[0];
    double expected = trim;
    // Pulses act on [start, start + duration).
    if (t > 0.2 - 1e-9 && t < 0.5 - 1e-9) expected += 2 * std::sin(M_PI * (t - 0.2) / 0.3);
    if (t > 0.6 - 1e-9 && t < 0.7 - 1e-9) expected -= 1;
    EXPECT_NEAR(row[r.getColumnIndex("steer_torque")], expected, 1e-12) << "t = " << t;
    const bool force = t > 0.25 - 1e-9 && t < 0.3 - 1e-9;
    EXPECT_EQ(row[r.getColumnIndex("lateral_force")], force ? 50.0 : 0.0) << "t = " << t;
  }
  EXPECT_GT(std::abs(getLast(r, "steer") - trim), 1e-4);
}

// Initial rate offsets: the named rates are set exactly, the forward speed is kept, and the dependent rates
// satisfy the rolling constraints.
TEST(SimulationInputs, InitialRatesAreProjectedOntoConstraints) {
  const VehicleModel model(getWhipple());
  const TrimResult trim = calcTrim(model, 4);
  SimTK::State s = trim.state;
  applyInitialRates(model, s, {parsePerturbation("roll-rate:0.2"), parsePerturbation("steer-rate:-0.3")});
  const auto& ix = model.getIndices();
  EXPECT_DOUBLE_EQ(s.getU()[ix.roll], trim.state.getU()[ix.roll] + 0.2);
  EXPECT_DOUBLE_EQ(s.getU()[ix.steer], trim.state.getU()[ix.steer] - 0.3);
  EXPECT_DOUBLE_EQ(s.getU()[ix.x], 4);
  Eigen::VectorXd err;
  StateFunction(model).calcConstraintErrors(s, err);
  EXPECT_LT(err.lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_GT(std::abs(s.getU()[ix.yaw] - trim.state.getU()[ix.yaw]), 1e-3);  // steering rate turns the heading
}

// Every integrator gives the same 2 s response to within its accuracy.
TEST(SimulationInputs, IntegratorsAgree) {
  SimulationOptions o;
  o.speed = 5;
  o.duration = 2;
  o.outputStep = 0.1;
  o.accuracy = 1e-8;
  o.perturbations = {parsePerturbation("roll-rate:0.1")};
  o.integrator = IntegratorKind::RungeKuttaMerson;
  const SimulationResult ref = runSimulation(getWhipple(), o);
  ASSERT_EQ(ref.status, SimulationStatus::Completed) << ref.message;
  for (IntegratorKind k : {IntegratorKind::RungeKutta3, IntegratorKind::CPodes, IntegratorKind::Verlet}) {
    o.integrator = k;
    const SimulationResult r = runSimulation(getWhipple(), o);
    ASSERT_EQ(r.status, SimulationStatus::Completed) << getIntegratorName(k) << ": " << r.message;
    for (const char* name : {"roll", "steer"})
      EXPECT_NEAR(getLast(r, name), getLast(ref, name), 1e-5) << getIntegratorName(k) << " " << name;
  }
}

TEST(SimulationInputs, RoadStepNeedsForceBasedTyres) {
  SimulationOptions o;
  o.perturbations = {parsePerturbation("road-step:front_wheel:0.02:1")};
  try {
    runSimulation(getWhipple(), o);
    ADD_FAILURE() << "road-step accepted on rolling_no_slip";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs a force-based tyre model"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("road-step:front_wheel:0.02:1"), std::string::npos) << e.what();
  }
}

TEST(SimulationInputs, BadOptionsAreInputErrors) {
  SimulationOptions o;
  o.duration = -1;
  EXPECT_THROW(runSimulation(getWhipple(), o), InputError);
  o.duration = 1;
  o.accuracy = 0;
  EXPECT_THROW(runSimulation(getWhipple(), o), InputError);
  // More than 1e5 output samples (duration / output step; drawn, seeded): 300000 s at 1e-4 s overflowed
  // the sample count (exit 0, an empty run), 1 s at 1e-6 s took 3 GB. Refused at --output-step.
  o.accuracy = 1e-6;
  std::mt19937 rng(93);
  for (int i = 0; i < 5; ++i) {
    o.duration = std::pow(10.0, std::uniform_real_distribution<double>(-1, 6)(rng));
    o.outputStep = o.duration / std::pow(10.0, std::uniform_real_distribution<double>(5.01, 12)(rng));
    try {
      runSimulation(getWhipple(), o);
      ADD_FAILURE() << o.duration << " / " << o.outputStep;
    } catch (const InputError& e) {
      EXPECT_EQ(e.getLocation().key, "--output-step") << e.what();
      EXPECT_NE(e.getReason().find("at most 1e5"), std::string::npos) << e.what();
    }
  }
}

// Outputs: timeseries columns by model name, the plot, and modes.json.
TEST(SimulationOutput, WritesTimeseriesPlotAndModes) {
  SimulationOptions o;
  o.speed = 5;
  o.duration = 3;
  o.perturbations = {parsePerturbation("steer-torque:1:0:0.1")};
  const SimulationResult r = runSimulation(getWhipple(), o);
  ASSERT_EQ(r.status, SimulationStatus::Completed);
  const VehicleModel model(getWhipple());
  for (const auto& n : model.getQNames()) EXPECT_NO_THROW(r.getColumnIndex(n)) << n;
  for (const auto& n : model.getUNames()) EXPECT_NO_THROW(r.getColumnIndex(n)) << n;
  EXPECT_NO_THROW(r.getColumnIndex("speed_control_integral"));
  for (const char* n : {"time", "steer_torque", "drive_torque", "forward_speed", "energy"})
    EXPECT_NO_THROW(r.getColumnIndex(n)) << n;

  // Extra output channels are evaluated on the sampled state.
  o.extraOutputs = {{"front_wheel_centre_z", [](const VehicleModel& m, const SimTK::State& st) {
                       return m.getFrontWheel().getBodyOriginLocation(st)[2];
                     }}};
  const SimulationResult withExtra = runSimulation(getWhipple(), o);
  ASSERT_EQ(withExtra.status, SimulationStatus::Completed);
  EXPECT_EQ(withExtra.columns.back(), "front_wheel_centre_z");
  for (const auto& row : withExtra.rows)  // knife-edge front wheel centre height: r cos(lean of the wheel plane)
    EXPECT_LE(row.back(), 0.35 + 1e-9);
  EXPECT_NEAR(withExtra.rows.front().back(), 0.35, 1e-9);  // upright at the trim

  const auto dir = makeTempDir("sim_output_test");
  std::filesystem::remove_all(dir);
  writeTimeseries(dir, r);
  writeResponsePlot(dir, r, "test");
  cli::writeSimulatedModes(dir, r, getFreeResponseStart(o.perturbations), {{"speed_mps", 5}});
  for (const char* f : {"timeseries.csv", "response.png", "response.svg", "response.gp", "modes.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace motostab::simulation

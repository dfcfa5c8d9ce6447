#include <gtest/gtest.h>

#include <algorithm>

#include "analysis/sweep.h"
#include "scenario/scenario.h"
#include "plugins/contact_geometry.h"

namespace motostab::analysis {

using scenario::loadScenario;
using plugins::calcTorusContact;
using vehicle::CoordinateIndices;
using vehicle::Input;
using vehicle::VehicleModel;
using vehicle::kNumInputs;

namespace {

const std::string kScenario = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

TEST(Trim, SymmetricBicycleRunsUpright) {
  const VehicleModel model(loadScenario(kScenario));
  const TrimResult t = calcTrim(model, 4.0);
  const CoordinateIndices& ix = model.getIndices();
  EXPECT_LT(t.residualNorm, 1e-10);
  EXPECT_NEAR(t.state.getQ()[ix.roll], 0, 1e-12);
  EXPECT_NEAR(t.state.getQ()[ix.steer], 0, 1e-12);
  EXPECT_NEAR(t.state.getQ()[ix.height], 0.3, 1e-12);               // rear wheel radius
  EXPECT_NEAR(t.state.getU()[ix.rearSpin], 4.0 / 0.3, 1e-10);       // v / r_R
  EXPECT_NEAR(t.state.getU()[ix.frontSpin], 4.0 / 0.35, 1e-10);     // v / r_F
}

// Without lateral symmetry the trim must lean the bicycle until the whole centre of mass lies
// above the line of the contact points (knife-edge wheels, steady straight running).
TEST(Trim, LaterallyOffsetRiderLeansUntilCentreOfMassIsOverTheContactLine) {
  const VehicleModel model(loadScenario(kScenario, {"rear_frame.com_m=[0.3, 0.05, 0.9]"}));
  const TrimResult t = calcTrim(model, 5.0);
  EXPECT_LT(t.residualNorm, 1e-10);
  const double roll = t.state.getQ()[model.getIndices().roll];
  EXPECT_GT(std::abs(roll), 1e-3);
  model.getSystem().realize(t.state, SimTK::Stage::Position);
  const SimTK::Vec3 com = model.getMatter().calcSystemMassCenterLocationInGround(t.state);
  auto contactPoint = [&](const SimTK::MobilizedBody& wheel, double radius) {
    const SimTK::Transform& X_GW = wheel.getBodyTransform(t.state);
    return X_GW.p() + calcTorusContact(X_GW.R(), SimTK::Vec3(0), radius, 0).r_CP_G;
  };
  const SimTK::Vec3 rear = contactPoint(model.getRearWheel(), 0.3), front = contactPoint(model.getFrontWheel(), 0.35);
  EXPECT_NEAR(rear[2], 0, 1e-12);
  EXPECT_NEAR(front[2], 0, 1e-12);
  // Horizontal cross product of (front - rear) and (com - rear): zero when the CoM is over the line.
  const double cross = (front[0] - rear[0]) * (com[1] - rear[1]) - (front[1] - rear[1]) * (com[0] - rear[0]);
  EXPECT_NEAR(cross, 0, 1e-9);
}

TEST(Trim, FailureNamesSpeedAndResidual) {
  const VehicleModel model(loadScenario(kScenario));
  TrimOptions opt;
  opt.tolerance = -1;  // unreachable
  opt.maxIterations = 2;
  try {
    calcTrim(model, 3.5, opt);
    FAIL() << "trim cannot succeed";
  } catch (const TrimError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("3.5 m/s"), std::string::npos) << m;
    EXPECT_NE(m.find("residual norm"), std::string::npos) << m;
    EXPECT_DOUBLE_EQ(e.speed, 3.5);
  }
}

// The in-place trim does the copying trim's arithmetic on the same values: equal to the last bit.
TEST(Trim, InPlaceTrimEqualsCopyingTrim) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml", {"swingarm.compliance=twist"}));
  const TrimResult a0 = calcTrim(model, 10.0);
  const TrimResult a1 = calcTrim(model, 10.5, {}, &a0);
  const TrimResult a2 = calcTrim(model, 11.0, {}, &a1);
  TrimResult b = calcTrim(model, 10.0);
  updTrim(model, 10.5, {}, b);
  updTrim(model, 11.0, {}, b);
  ASSERT_EQ(a2.state.getNY(), b.state.getNY());
  for (int i = 0; i < b.state.getNY(); ++i) EXPECT_EQ(a2.state.getY()[i], b.state.getY()[i]) << i;
  EXPECT_EQ(a2.iterations, b.iterations);
  EXPECT_EQ(a2.unknownsCurvature.size(), b.unknownsCurvature.size());
  EXPECT_GT(b.unknownsCurvature.size(), 0);  // three speeds: the predictor is quadratic
  EXPECT_EQ(b.speed, 11.0);
}

// A trim kept without its State comes back with the same values, and is still a trim: the residual
// evaluated afresh on the restored State stays within the tolerance.
TEST(Trim, TrimPointRestoresTheTrimmedState) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml", {"swingarm.compliance=torsion"}));
  TrimResult t = calcTrim(model, 15.0);
  const TrimPoint p = makeTrimPoint(model, t);
  const TrimResult r = restoreTrim(model, p);
  for (int i = 0; i < t.state.getNY(); ++i) EXPECT_EQ(r.state.getY()[i], t.state.getY()[i]) << i;
  EXPECT_NE(p.inputs[static_cast<int>(Input::DriveTorque)], 0.0);  // rolling resistance and drag need drive
  for (int k = 0; k < kNumInputs; ++k)
    EXPECT_EQ(model.getInput(r.state, static_cast<Input>(k)), model.getInput(t.state, static_cast<Input>(k)));
  Eigen::VectorXd res;
  StateFunction(model).calcTrimResidual(r.state, res);
  EXPECT_LE(res.lpNorm<Eigen::Infinity>(), TrimOptions().tolerance);
  EXPECT_EQ(r.speed, 15.0);
  const VehicleModel other(loadScenario(kScenario));
  EXPECT_THROW(restoreTrim(other, p), std::logic_error);
}

}  // namespace
}  // namespace motostab::analysis

namespace motostab::analysis {
namespace {

// Splitting the speeds between workers changes only the trims' warm starts.
// Each speed of a sweep is the trim and linearisation of that speed, whatever the chain that
// reached it: the serial sweep from standstill starts at 1 m/s (the reference), goes down to 0 and
// turns; every speed, either side of the turn, matches a cold trim and linearisation there.
TEST(Sweep, EverySpeedMatchesItsOwnColdLinearisation) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml", {"swingarm.compliance=torsion"}));
  SweepOptions opt;
  opt.start = 0, opt.stop = 2.5, opt.step = 0.5;
  const SweepResult r = runSweep(model, opt);
  LinearizeOptions lo = opt.linearize;
  lo.removeYaw = r.models[0].findState("yaw") < 0 ? 1 : 0;
  auto sorted = [](Eigen::VectorXcd v) {
    std::sort(v.data(), v.data() + v.size(), [](auto a, auto b) { return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag(); });
    return v;
  };
  for (size_t k = 0; k < r.speeds.size(); ++k) {
    const Eigen::VectorXcd cold = sorted(linearize(model, calcTrim(model, r.speeds[k]), lo).eigenvalues);
    const Eigen::VectorXcd swept = sorted(r.models[k].eigenvalues);
    ASSERT_EQ(cold.size(), swept.size());
    for (int j = 0; j < cold.size(); ++j) EXPECT_LT(std::abs(cold[j] - swept[j]), 1e-6 * (1 + std::abs(cold[j]))) << r.speeds[k];
  }
}

TEST(Sweep, ParallelSweepMatchesSerial) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml", {"swingarm.compliance=torsion"}));
  for (double start : {5.0, 0.0}) {  // from 0 m/s the lead chain turns at 1 m/s
  SweepOptions serial;
  serial.start = start, serial.stop = 30, serial.step = 1;
  const SweepResult a = runSweep(model, serial);
  for (int threads : {2, 3, 4}) {  // two workers per span of speeds; an odd one alone
    SweepOptions parallel = serial;
    parallel.threads = threads;
    const SweepResult b = runSweep(model, parallel);
    ASSERT_EQ(a.branches.size(), b.branches.size()) << threads;
    for (size_t i = 0; i < a.branches.size(); ++i) {
      EXPECT_EQ(a.branches[i].label, b.branches[i].label);
      for (size_t k = 0; k < a.speeds.size(); ++k)
        EXPECT_LT(std::abs(a.branches[i].eigenvalue[k] - b.branches[i].eigenvalue[k]), 1e-7 * (1 + std::abs(a.branches[i].eigenvalue[k])));
    }
    for (size_t k = 0; k < a.speeds.size(); ++k) EXPECT_EQ(b.trims[k].speed, a.speeds[k]) << threads;
    ASSERT_EQ(a.criticalSpeeds.size(), b.criticalSpeeds.size());
    for (size_t i = 0; i < a.criticalSpeeds.size(); ++i) EXPECT_NEAR(a.criticalSpeeds[i].speed, b.criticalSpeeds[i].speed, 1e-8);
  }
  }
}

// A trim failure in one worker reaches the caller as a TrimError (no worker left waiting): the
// tilted-axis enduro has no upright equilibrium at standstill, the first worker's first speed.
TEST(Sweep, ParallelSweepReportsATrimFailure) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml",
                                        {"swingarm.compliance=torsion",
                                         "swingarm.torsion={point_m: [0.56, 0, 0.014], direction: [1, 0.2, 0], "
                                         "stiffness_Nm_per_rad: 55200, damping_Nms_per_rad: 0.49}"}));
  SweepOptions opt;
  opt.start = 0, opt.stop = 10, opt.step = 1;
  for (int threads : {2, 3, 4}) {
    opt.threads = threads;
    EXPECT_THROW(runSweep(model, opt), TrimError) << threads;
  }
}

}  // namespace
}  // namespace motostab::analysis

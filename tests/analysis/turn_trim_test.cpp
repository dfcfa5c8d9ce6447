// Steady-turn trim (analysis/trim.h): the published Whipple steady turn (Peterson 2011), the force
// and moment balance of a turn, and the zero-roll turn against straight running.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <algorithm>
#include <map>
#include <sstream>

#include "analysis/linearize.h"
#include "analysis/sweep.h"
#include "analysis/trim.h"
#include "core/portable_random.h"
#include "scenario/scenario.h"
#include "plugins/builtin.h"
#include "plugins/contact_geometry.h"

namespace motostab::analysis {

using core::PortableRandom;
using scenario::WheelSpec;
using scenario::loadScenario;
using plugins::calcTorusContact;
using vehicle::CoordinateIndices;
using vehicle::Input;
using vehicle::VehicleModel;

namespace {

const std::string kWhipple = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

// quantity -> value of tests/data/reference-data/WhippleSteadyTurn/peterson2011_steady_turn.csv.
std::map<std::string, double> readPeterson() {
  std::ifstream in(std::string(MOTOSTAB_TEST_DATA_DIR) + "/reference-data/WhippleSteadyTurn/peterson2011_steady_turn.csv");
  std::map<std::string, double> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("quantity", 0) == 0) continue;
    const size_t comma = line.find(',');
    const std::string value = line.substr(comma + 1);
    if (value.find('j') == std::string::npos) out[line.substr(0, comma)] = std::stod(value);
  }
  return out;
}

// Peterson (2011), "Precise steady turning conditions" (UC Davis Sports Biomechanics Lab): the
// benchmark bicycle (Meijaard et al. 2007) at lean 5 deg and steer 0.02499 rad, both to the right.
// Conventions there: lean and steer positive right, steer torque positive right, pitch about the
// rear frame's right-pointing axis (nose up) plus lambda = pi/10, speed = -front wheel rate x r_F.
// Here: roll > 0 right, steer and steer torque > 0 left, pitch > 0 nose down.
TEST(TurnTrim, ReproducesPetersonsWhippleSteadyTurn) {
  const auto ref = readPeterson();
  ASSERT_EQ(ref.size(), 6u);
  const VehicleModel model(loadScenario(kWhipple));
  TrimOptions opt;
  opt.roll = ref.at("lean");
  opt.condition = TurnCondition::Steer;
  opt.steer = -ref.at("steer");
  const TrimResult t = calcTrim(model, 5.0, opt);  // 5 m/s: the starting guess only
  const CoordinateIndices& ix = model.getIndices();
  const double pitch = -(ref.at("pitch_reported") - M_PI / 10);
  const double frontSpeed = std::abs(t.state.getU()[ix.frontSpin]) * 0.35;
  EXPECT_NEAR(t.state.getQ()[ix.pitch], pitch, 1e-9);
  EXPECT_NEAR(model.getInput(t.state, Input::SteerTorque), -ref.at("steer_torque_Nm"), 1e-9);
  EXPECT_NEAR(frontSpeed, ref.at("velocity_m_s"), 1e-9);
  // motostab's wheel spin axis points left: forward rolling is a positive rate.
  EXPECT_NEAR(t.state.getU()[ix.frontSpin], -ref.at("front_wheel_rate_rad_s"), 1e-9);
  std::printf("Peterson 2011: pitch error %.3g rad, steer torque error %.3g N m, speed error %.3g m/s\n",
              t.state.getQ()[ix.pitch] - pitch, model.getInput(t.state, Input::SteerTorque) + ref.at("steer_torque_Nm"),
              frontSpeed - ref.at("velocity_m_s"));
  // A right turn: negative yaw rate, the rear contact's speed = path radius x yaw rate.
  const TurnFigures f = calcTurnFigures(model, t.state);
  EXPECT_LT(f.yawRate, 0);
  EXPECT_NEAR(f.speed, f.pathRadius * std::abs(f.yawRate), 1e-12);
  EXPECT_DOUBLE_EQ(t.speed, f.speed);
}


// d'Alembert balance of a steady turn computed here from the trimmed pose alone: every body's centre
// of mass on its circle about the turn centre c (a_i = -r^2 (p_i - c) horizontally), every angular
// momentum turning with the heading (dH_i/dt = r z x H_i; the wheels are axisymmetric).
struct TurnBalance {
  SimTK::Vec3 inertialForce{0};  ///< sum m_i a_i, N: what the ground must supply horizontally
  double momentAboutContactLine = 0;  ///< of gravity and the inertial forces and moments, N m
  double scale = 0;           ///< sum |m_i g| |p_i - P_rear|, N m: the size of the terms
};

SimTK::Vec3 findContactPoint(const VehicleModel& model, const SimTK::State& s, const SimTK::MobilizedBody& wheel,
                             const WheelSpec& spec) {
  const SimTK::Transform& X_GW = wheel.getBodyTransform(s);
  return X_GW.p() + calcTorusContact(X_GW.R(), SimTK::Vec3(0), spec.radius, spec.crownRadius).r_CP_G;
}

TurnBalance calcTurnBalance(const VehicleModel& model, const SimTK::State& s) {
  model.getSystem().realize(s, SimTK::Stage::Velocity);
  const CoordinateIndices& ix = model.getIndices();
  const double r = s.getU()[ix.yaw], g = model.getScenario().gravity;
  const SimTK::Vec3 z(0, 0, 1);
  const SimTK::MobilizedBody& frame = model.getRearFrame();
  const SimTK::Vec3 vO = frame.getBodyOriginVelocity(s), pO = frame.getBodyOriginLocation(s);
  const SimTK::Vec3 centre = pO + (z % vO) / r;  // v_O = r z x (p_O - c)
  const SimTK::Vec3 pR = findContactPoint(model, s, model.getRearWheel(), model.getScenario().rearWheel);
  const SimTK::Vec3 pF = findContactPoint(model, s, model.getFrontWheel(), model.getScenario().frontWheel);
  const SimTK::Vec3 line = (pF - pR) / (pF - pR).norm();
  TurnBalance b;
  const SimTK::SimbodyMatterSubsystem& matter = model.getMatter();
  for (SimTK::MobilizedBodyIndex i(1); i < matter.getNumBodies(); ++i) {
    const SimTK::MobilizedBody& body = matter.getMobilizedBody(i);
    const SimTK::MassProperties& mp = body.getBodyMassProperties(s);
    const double m = mp.getMass();
    if (m == 0) continue;  // massless links (rear suspension) carry no load
    const SimTK::Vec3 p = body.findStationLocationInGround(s, mp.getMassCenter());
    SimTK::Vec3 rel = p - centre;
    rel[2] = 0;
    const SimTK::Vec3 a = -r * r * rel;
    const SimTK::Rotation& R_GB = body.getBodyRotation(s);
    const SimTK::Vec3 w = body.getBodyAngularVelocity(s);
    const SimTK::Vec3 H = R_GB * (mp.calcCentralInertia() * (~R_GB * w));
    const SimTK::Vec3 gravity(0, 0, -m * g);
    b.inertialForce += m * a;
    b.momentAboutContactLine += ~((p - pR) % (gravity - m * a) - r * (z % H)) * line;
    b.scale += m * g * (p - pR).norm();
  }
  return b;
}

// The Whipple bicycle in random turns: the moment about the contact line of gravity and the inertial
// loads vanishes (contact forces act on the line; steer and drive torques are internal), and with
// rolling without slip nothing dissipates, so the drive torque is zero (energy balance).
TEST(TurnTrim, WhippleTurnBalancesMomentsAboutTheContactLine) {
  const VehicleModel model(loadScenario(kWhipple));
  PortableRandom rng(20110428);
  for (int k = 0; k < 4; ++k) {
    TrimOptions opt;
    opt.roll = rng.drawUniform(-0.7, 0.7);
    const double v = rng.drawUniform(2.0, 9.0);
    const TrimResult t = calcTrim(model, v, opt);
    EXPECT_NEAR(calcTurnFigures(model, t.state).speed, v, 1e-10);
    const TurnBalance b = calcTurnBalance(model, t.state);
    EXPECT_LT(std::abs(b.momentAboutContactLine), 1e-9 * b.scale) << "roll " << opt.roll << ", v " << v;
    EXPECT_NEAR(model.getInput(t.state, Input::DriveTorque), 0, 1e-9);
    // Roll right turns right: negative yaw rate and lateral acceleration.
    EXPECT_LT(calcTurnFigures(model, t.state).yawRate * opt.roll, 0);
  }
}

// The enduro on relaxation tyres: the tyres' horizontal forces (their Fx, Fy along the wheel's
// heading and the ground's lateral direction) equal the inertial force sum m_i a_i, i.e. m V^2 / R
// body by body.
TEST(TurnTrim, EnduroTyreForcesBalanceTheCentripetalForce) {
  // Without aerodynamic drag, the only other horizontal force.
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml",
                                        {"aerodynamics.drag_area_m2=0"}));
  PortableRandom rng(2001);
  for (int k = 0; k < 2; ++k) {
    TrimOptions opt;
    opt.roll = rng.drawUniform(0.1, 0.7);
    const double v = rng.drawUniform(10.0, 40.0);
    const TrimResult t = calcTrim(model, v, opt);
    const TurnBalance b = calcTurnBalance(model, t.state);
    const auto names = model.getContactOutputNames();
    const auto values = model.calcContactOutputs(t.state);
    auto output = [&](const std::string& name) {
      const auto it = std::find(names.begin(), names.end(), name);
      EXPECT_NE(it, names.end()) << name;
      return values[it - names.begin()];
    };
    SimTK::Vec3 tyres(0);
    for (const auto& [wheel, prefix] : {std::pair{&model.getRearWheel(), "rear_tyre_"}, {&model.getFrontWheel(), "front_tyre_"}}) {
      const SimTK::Vec3 n(0, 0, 1), a = wheel->getBodyRotation(t.state).y().asVec3();
      SimTK::Vec3 eL = a % n;
      eL /= eL.norm();
      tyres += output(std::string(prefix) + "Fx_N") * eL + output(std::string(prefix) + "Fy_N") * (n % eL);
    }
    const double total = b.inertialForce.norm();
    EXPECT_GT(total, 100.0);
    EXPECT_LT((tyres - b.inertialForce).norm(), 1e-8 * total) << "roll " << opt.roll << ", v " << v;
  }
}

// Hands-free turns of the Whipple bicycle tend, as the roll goes to zero, to straight running at the
// capsize speed (Meijaard et al. 2007, Table 2: 6.02426201538837 m/s), where the upright linear model
// has a zero eigenvalue; their steer/roll ratio tends to that of its null vector (lean and steer only,
// rates zero). Both limits are approached as roll^2 (the turn is even in roll).
TEST(TurnTrim, HandsFreeTurnsTendToTheCapsizeSpeed) {
  const VehicleModel model(loadScenario(kWhipple));
  const double capsizeSpeed = 6.02426201538837;
  const LinearModel upright = linearize(model, calcTrim(model, capsizeSpeed));
  // With the rates zero, A x = 0 reduces to the roll and steer accelerations' dependence on roll and
  // steer: its 2 x 2 block is singular at the capsize speed (forward speed is a separate neutral state).
  const int roll = upright.findState("roll"), steer = upright.findState("steer");
  const int rollRate = upright.findState("roll_rate"), steerRate = upright.findState("steer_rate");
  Eigen::Matrix2d K;
  K << upright.A(rollRate, roll), upright.A(rollRate, steer), upright.A(steerRate, roll), upright.A(steerRate, steer);
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(K, Eigen::ComputeFullV);
  EXPECT_LT(svd.singularValues()[1], 1e-6 * svd.singularValues()[0]);
  const double nullRatio = svd.matrixV()(1, 1) / svd.matrixV()(0, 1);
  std::vector<double> speeds;
  for (double v = 4; v <= 8.0001; v += 0.5) speeds.push_back(v);
  double lastSpeedError = NAN, lastRatioError = NAN;
  for (double phi : {0.04, 0.02, 0.01}) {
    TrimOptions opt;
    opt.roll = phi;
    const TrimResult t = calcHandsFreeTrim(model, speeds, opt, 6.0);
    EXPECT_EQ(model.getInput(t.state, Input::SteerTorque), 0.0);
    const double ratio = t.state.getQ()[model.getIndices().steer] / phi;
    const double speedError = t.speed - capsizeSpeed, ratioError = ratio - nullRatio;
    std::printf("hands-free at roll %.3f rad: speed %.9f m/s (capsize %.9f), steer/roll %.9f (null vector %.9f)\n",
                phi, t.speed, capsizeSpeed, ratio, nullRatio);
    if (!std::isnan(lastSpeedError)) {  // halving the roll quarters the errors
      EXPECT_NEAR(speedError / lastSpeedError, 0.25, 0.02);
      EXPECT_NEAR(ratioError / lastRatioError, 0.25, 0.02);
    }
    lastSpeedError = speedError, lastRatioError = ratioError;
  }
  EXPECT_LT(std::abs(lastSpeedError), 1e-3);
  EXPECT_LT(std::abs(lastRatioError), 1e-3 * std::abs(nullRatio));
}

// Every hands-free turn of the Whipple bicycle on a wide speed grid is listed, sorted by speed, each with
// zero steer torque; at 20 deg there are turns at 3.14 m/s (23 deg of steer) and 5.53 m/s (7 deg), and
// the one marked as continuing from straight running is the default. The check of the marking, apart
// from how it is found: from 2 deg (where it lies within 0.05 m/s of the capsize speed of Meijaard et
// al. 2007, Table 2) up to 20 deg, the marked turn at each roll is the listed turn nearest the marked one
// of the roll before (the branch is continuous in roll), and its speed falls as the roll grows.
TEST(TurnTrim, EveryHandsFreeTurnListedAndTheOneFromStraightRunningMarked) {
  const VehicleModel model(loadScenario(kWhipple));
  std::vector<double> speeds;
  for (int i = 1; i <= 40; ++i) speeds.push_back(0.25 * i);
  double previous = 6.02426201538837;  // the capsize speed
  for (double deg : {2.0, 5.0, 10.0, 20.0}) {
    TrimOptions opt;
    opt.roll = deg * M_PI / 180;
    const std::vector<HandsFreeTurn> turns = calcHandsFreeTurns(model, speeds, opt);
    ASSERT_FALSE(turns.empty());
    int marked = -1;
    size_t nearest = 0;
    for (size_t i = 0; i < turns.size(); ++i) {
      const TrimResult t = restoreTrim(model, turns[i].trim);
      EXPECT_NEAR(model.getInput(t.state, Input::SteerTorque), 0.0, 1e-9) << deg << " deg, turn " << i;
      if (i > 0) {
        EXPECT_LT(turns[i - 1].trim.speed, turns[i].trim.speed);
      }
      if (turns[i].continuesFromStraight) {
        EXPECT_EQ(marked, -1) << "two turns marked at " << deg << " deg";
        marked = static_cast<int>(i);
      }
      if (std::abs(turns[i].trim.speed - previous) < std::abs(turns[nearest].trim.speed - previous)) nearest = i;
    }
    ASSERT_GE(marked, 0) << "no turn marked at " << deg << " deg";
    EXPECT_EQ(static_cast<size_t>(marked), nearest) << deg << " deg";
    EXPECT_EQ(chooseHandsFreeTurn(turns), static_cast<size_t>(marked));
    EXPECT_LT(turns[marked].trim.speed, previous);
    if (deg == 2.0) {
      EXPECT_NEAR(turns[marked].trim.speed, previous, 0.05);
    }
    previous = turns[marked].trim.speed;
    if (deg != 20.0) continue;
    auto findTurn = [&](double v) {
      for (const HandsFreeTurn& t : turns)
        if (std::abs(t.trim.speed - v) < 0.01) return restoreTrim(model, t.trim);
      ADD_FAILURE() << "no hands-free turn near " << v << " m/s at 20 deg";
      return restoreTrim(model, turns[marked].trim);
    };
    const int steer = model.getIndices().steer;
    EXPECT_NEAR(std::abs(findTurn(3.14).state.getQ()[steer]) * 180 / M_PI, 23.0, 0.5);
    EXPECT_NEAR(std::abs(findTurn(5.53).state.getQ()[steer]) * 180 / M_PI, 7.0, 0.5);
    EXPECT_NEAR(turns[marked].trim.speed, 5.53, 0.01);
  }
}

// A failed turn names the speed and the requested roll.
TEST(TurnTrim, FailureNamesSpeedAndRoll) {
  const VehicleModel model(loadScenario(kWhipple));
  TrimOptions opt;
  opt.roll = 80 * M_PI / 180;
  try {
    calcTrim(model, 0.5, opt);
    FAIL() << "a 0.5 m/s turn at 80 deg has no trim";
  } catch (const TrimError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("0.5 m/s"), std::string::npos) << m;
    EXPECT_NE(m.find("roll 80 deg"), std::string::npos) << m;
    EXPECT_NE(m.find("residual norm"), std::string::npos) << m;
    EXPECT_DOUBLE_EQ(e.roll, opt.roll);
  }
}


// A contact plugin with its own geometry: the rolling constraint of a wheel with a wide crown (rho, m)
// whatever crown the scenario's wheel has. Its contact point is not the scenario wheel's torus.
class WideCrownContact : public plugins::ContactModel {
 public:
  WideCrownContact(std::unique_ptr<plugins::ContactModel> rolling, double crown) : rolling_(std::move(rolling)), crown_(crown) {}
  void addWheel(plugins::BuildContext& context, const plugins::WheelSite& wheel) override {
    rolling_->addWheel(context, widen(wheel));
  }
  plugins::ContactPoint calcContactPoint(const plugins::WheelSite& wheel, const SimTK::Rotation& R_GW,
                                         const SimTK::Vec3& w_GW_G) const override {
    return rolling_->calcContactPoint(widen(wheel), R_GW, w_GW_G);
  }

 private:
  plugins::WheelSite widen(plugins::WheelSite wheel) const {
    wheel.crownRadius = crown_;
    return wheel;
  }
  std::unique_ptr<plugins::ContactModel> rolling_;
  double crown_;
};

// The lowest point of a torus (centre C, spin axis a, radii R and rho) on the ground z = 0, written out
// here: from C down the wheel plane by R - rho, then down by rho.
SimTK::Vec3 findTorusBottom(const SimTK::Transform& X_GW, double R, double rho) {
  const SimTK::Vec3 a = X_GW.R().y().asVec3(), n(0, 0, 1);
  SimTK::Vec3 down = -(n - (~n * a) * a);
  down /= down.norm();
  return X_GW.p() + (R - rho) * down - rho * n;
}

// The horizontal speed of the rear-frame point at p (m/s), state realized to Velocity.
double calcRearFramePointSpeed(const VehicleModel& model, const SimTK::State& s, const SimTK::Vec3& p) {
  const SimTK::MobilizedBody& frame = model.getRearFrame();
  const SimTK::Vec3 v = frame.getBodyOriginVelocity(s) + frame.getBodyAngularVelocity(s) % (p - frame.getBodyOriginLocation(s));
  return std::hypot(v[0], v[1]);
}

// The turn trim takes the contact point from the contact plugin: with a wide-crowned wheel the rear
// contact point moves across the tread with roll, and the trimmed speed is that point's (computed here
// from the trimmed pose), not the speed of the scenario's knife-edge contact. Roll, speed and crown
// drawn at random (seeded).
TEST(TurnTrim, TakesTheContactPointFromTheContactPlugin) {
  PortableRandom g(3303);
  const double crown = g.drawUniform(0.05, 0.1), roll = g.drawUniform(0.2, 0.4), speed = g.drawUniform(4.5, 6);
  plugins::PluginRegistry registry = plugins::makeBuiltinRegistry();
  const plugins::PluginRegistry builtin = registry;
  registry.addContactModel("wide_crown", [&builtin, crown](io::YamlMap&) -> std::unique_ptr<plugins::ContactModel> {
    scenario::PluginSpec rolling;
    rolling.model = "rolling_no_slip";
    rolling.params = YAML::Load("{model: rolling_no_slip}");
    rolling.path = "contact";
    return std::make_unique<WideCrownContact>(builtin.createContactModel(rolling), crown);
  });
  const VehicleModel model(loadScenario(kWhipple, {"contact.model=wide_crown"}), registry);
  TrimOptions opt;
  opt.roll = roll;
  const TrimResult t = calcTrim(model, speed, opt);
  const TurnFigures f = calcTurnFigures(model, t.state);  // realizes to Velocity
  const auto& sc = model.getScenario();
  ASSERT_EQ(sc.rearWheel.crownRadius, 0);
  const SimTK::Transform& X_GR = model.getRearWheel().getBodyTransform(t.state);
  const SimTK::Transform& X_GF = model.getFrontWheel().getBodyTransform(t.state);
  const SimTK::Vec3 wideRear = findTorusBottom(X_GR, sc.rearWheel.radius, crown);
  EXPECT_NEAR(wideRear[2], 0, 1e-9);  // the wide crown rolls on the ground
  EXPECT_NEAR(findTorusBottom(X_GF, sc.frontWheel.radius, crown)[2], 0, 1e-9);
  EXPECT_NEAR(f.speed, calcRearFramePointSpeed(model, t.state, wideRear), 1e-12);
  EXPECT_NEAR(f.speed, speed, 1e-8);
  // The scenario's knife edge is elsewhere (rho sin(roll) across) and moves at another speed.
  const double knifeSpeed = calcRearFramePointSpeed(model, t.state, findTorusBottom(X_GR, sc.rearWheel.radius, 0));
  EXPECT_GT(std::abs(knifeSpeed - speed), 1e-4) << knifeSpeed;
}

}  // namespace
// A sweep of turns that starts in a tight turn (radius 2-3 m: 26 deg of steer at 4 m/s and 35 deg) stays
// on the branch of turns a cold trim finds (roll stepped up from straight running at each speed): its next
// speed's steer and pitch are the cold trim's. Roll and first speed drawn at random (seeded).
TEST(TurnTrim, SweepFromATightTurnStaysOnTheColdTrimsBranch) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/supersport-mf.yaml"));
  const CoordinateIndices& ix = model.getIndices();
  PortableRandom g(2811);
  for (int draw = 0; draw < 3; ++draw) {
    const double roll = g.drawUniform(30, 38) * M_PI / 180, v0 = g.drawUniform(3.5, 4.5);
    SweepOptions opt;
    opt.trim.roll = roll;
    opt.findCriticalSpeeds = false;
    const SweepResult s = runSweep(model, std::vector<double>{v0, v0 + 2}, opt);
    TrimOptions cold;
    cold.roll = roll;
    const TrimResult t = calcTrim(model, v0 + 2, cold);
    ASSERT_EQ(s.trims.size(), 2u);
    EXPECT_NEAR(s.trims[1].y[ix.steer], t.state.getQ()[ix.steer], 1e-6) << "draw " << draw << ": roll " << roll << " rad, " << v0 + 2 << " m/s";
    EXPECT_NEAR(s.trims[1].y[ix.pitch], t.state.getQ()[ix.pitch], 1e-6) << "draw " << draw;
  }
}

}  // namespace motostab::analysis

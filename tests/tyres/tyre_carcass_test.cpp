// relaxation_linear tyres whose relaxation length comes from the carcass: sigma = Fz k_alpha / k_y(V),
// 1/k_y(V) = (1 + b1 V + b2 V^2)/k_y0 (tyres/relaxation_linear.h). References are written out here:
// the lag rate of the stretched-string relaxation, -V/sigma (Pacejka 2012 sec. 7.2), the constant-length
// model at the same sigma, and the published law sigma = K_ya (C1 + C2 V + C3 V^2) of Sharp, Evangelou &
// Limebeer (2004) sec. 4 with Evangelou's (2004) Table 9.5 coefficients.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../support/catch_input_error.h"
#include "../support/temp_dir.h"
#include "analysis/linearize.h"
#include "core/portable_random.h"
#include "io/csv.h"
#include "tyres/relaxation_linear.h"
#include "tests/support/contact_outputs.h"

namespace motostab::tyres {

using analysis::LinearModel;
using analysis::TrimOptions;
using analysis::TrimResult;
using analysis::calcTrim;
using analysis::linearize;
using io::InputError;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

const std::string kDir = MOTOSTAB_SOURCE_DIR;

struct Carcass {
  double stiffness = 0, b1 = 0, b2 = 0;  // N/m, s/m, s^2/m^2
};

// The scenario's tyre map without its relaxation_length_m, open for more keys: "{k: v, ..., ".
std::string openTyre(const YAML::Node& tyre) {
  std::string t = "{";
  for (const auto& kv : tyre)
    if (kv.first.Scalar() != "relaxation_length_m") t += kv.first.Scalar() + ": " + kv.second.Scalar() + ", ";
  return t;
}

// The scenario's tyre map with its relaxation_length_m replaced by a carcass (or by a constant length
// when `carcass` is null).
std::string makeTyre(const YAML::Node& tyre, const Carcass* carcass, double length = 0) {
  std::ostringstream t;
  t.precision(17);
  t << openTyre(tyre);
  if (carcass)
    t << "lateral_carcass_stiffness_N_per_m: " << carcass->stiffness << ", carcass_compliance_speed_coefficient_s_per_m: "
      << carcass->b1 << ", carcass_compliance_speed_coefficient_s2_per_m2: " << carcass->b2 << "}";
  else
    t << "relaxation_length_m: " << length << "}";
  return t.str();
}

// The forward speed of a wheel centre along the wheel's heading in the ground plane, v_C . (a x z), a
// the spin axis (tyres/tyre_contact.h): in a turn each wheel's differs from the trim speed.
double calcWheelSpeed(const VehicleModel& m, const SimTK::State& s, const std::string& tyre) {
  m.getSystem().realize(s, SimTK::Stage::Velocity);
  const SimTK::MobilizedBody& wheel = tyre == "front" ? m.getFrontWheel() : m.getRearWheel();
  SimTK::Vec3 e = wheel.getBodyTransform(s).R().y().asVec3() % SimTK::Vec3(0, 0, 1);
  return ~wheel.getBodyOriginVelocity(s) * (e / e.norm());
}

Carcass drawCarcass(core::PortableRandom& rng) {
  // Around Sharp et al.'s (2004) 1/C1 = 103-116 kN/m and b1 = C2/C1, b2 = C3/C1 (-1.4e-3..4.3e-3 s/m,
  // 9.7e-5..2.0e-4 s^2/m^2), widened.
  return {rng.drawUniform(6e4, 2e5), rng.drawUniform(-2e-3, 6e-3), rng.drawUniform(0, 3e-4)};
}

// sigma = Fz k_alpha (1 + b1 V + b2 V^2)/k_y0, written out.
double calcSigma(double Fz, double kAlpha, const Carcass& c, double V) {
  return Fz * kAlpha * (1 + c.b1 * V + c.b2 * V * V) / c.stiffness;
}

// At a drawn speed and carcass, the linearised lag row of each tyre's lagged slip is zdot = ... - (V/sigma) z
// with sigma at the trim's load (the tyre's reported Fz) and speed, V the contact's regularised speed
// sqrt(V^2 + 0.1^2) (tyres/tyre_contact.h).
TEST(TyreCarcass, LagRateIsSpeedOverTheCarcassRelaxationLength) {
  core::PortableRandom rng(3030);
  for (const char* name : {"supersport", "enduro"}) {
    const std::string file = kDir + "/scenarios/" + name + ".yaml";
    const YAML::Node contact = YAML::LoadFile(file)["contact"];
    const Carcass front = drawCarcass(rng), rear = drawCarcass(rng);
    const double V = rng.drawUniform(5, 45);
    const VehicleModel m(loadScenario(file, {"contact.front=" + makeTyre(contact["front"], &front),
                                             "contact.rear=" + makeTyre(contact["rear"], &rear)}));
    const TrimResult trim = calcTrim(m, V);
    const LinearModel lin = linearize(m, trim);
    const double Veps = std::sqrt(V * V + 0.01);
    for (const auto& [tyre, c] : {std::pair<std::string, Carcass>{"front", front}, {"rear", rear}}) {
      const double Fz = test::findContactOutput(m, trim.state, tyre + "_tyre_Fz_N");
      const double sigma = calcSigma(Fz, contact[tyre]["cornering_stiffness_per_rad"].as<double>(), c, V);
      const int z = lin.findState(tyre + "_tyre_lagged_slip");
      ASSERT_GE(z, 0);
      EXPECT_NEAR(lin.A(z, z), -Veps / sigma, 1e-7 * Veps / sigma) << name << " " << tyre << " at " << V << " m/s";
    }
  }
}

// Every largest distance from an eigenvalue of `a` to the nearest of `b`, relative to |lambda| + 1.
double compareEigenvalues(const LinearModel& a, const LinearModel& b) {
  double worst = 0;
  for (int i = 0; i < a.eigenvalues.size(); ++i) {
    double best = INFINITY;
    for (int k = 0; k < b.eigenvalues.size(); ++k) best = std::min(best, std::abs(a.eigenvalues[i] - b.eigenvalues[k]));
    worst = std::max(worst, best / (std::abs(a.eigenvalues[i]) + 1));
  }
  return worst;
}

// The load and speed dependence of sigma enter the linearisation only through sigma's value at the trim:
// its derivatives multiply s_ss - s, zero in every steady state. So at a drawn speed, straight or in a
// steady turn at a drawn roll, the carcass tyres' eigenvalues equal those of constant lengths set to
// sigma at each tyre's trim load and its wheel centre's speed, and the trims are the same.
TEST(TyreCarcass, EigenvaluesAreTheConstantLengthModelsAtTheTrimLoadAndSpeed) {
  core::PortableRandom rng(3031);
  for (const char* name : {"supersport", "enduro"}) {
    const std::string file = kDir + "/scenarios/" + name + ".yaml";
    const YAML::Node contact = YAML::LoadFile(file)["contact"];
    const Carcass front = drawCarcass(rng), rear = drawCarcass(rng);
    const double V = rng.drawUniform(8, 40);
    TrimOptions opt;
    opt.roll = std::string(name) == "supersport" ? rng.drawUniform(0.1, 0.4) : 0.0;
    const VehicleModel carcass(loadScenario(file, {"contact.front=" + makeTyre(contact["front"], &front),
                                                   "contact.rear=" + makeTyre(contact["rear"], &rear)}));
    const TrimResult trimC = calcTrim(carcass, V, opt);
    auto sigma = [&](const char* tyre, const Carcass& c) {
      const double speed = calcWheelSpeed(carcass, trimC.state, tyre);
      if (opt.roll == 0) {
        EXPECT_NEAR(speed, V, 1e-9 * V);
      }
      return calcSigma(test::findContactOutput(carcass, trimC.state, std::string(tyre) + "_tyre_Fz_N"),
                       contact[tyre]["cornering_stiffness_per_rad"].as<double>(), c, speed);
    };
    const VehicleModel constant(loadScenario(file, {"contact.front=" + makeTyre(contact["front"], nullptr, sigma("front", front)),
                                                    "contact.rear=" + makeTyre(contact["rear"], nullptr, sigma("rear", rear))}));
    const TrimResult trimK = calcTrim(constant, V, opt);
    const double dq = (trimC.state.getQ() - trimK.state.getQ()).normInf(), dz = (trimC.state.getZ() - trimK.state.getZ()).normInf();
    EXPECT_LT(dq, 1e-9) << name;
    EXPECT_LT(dz, 1e-9) << name;
    // In a turn the differences also see the curvature of the load dependence (sigma changes by some
    // 10 % per mm of tyre deflection): at a step of 1e-3 the eigenvalues differ by 1e-6
    // (relative), at a quarter of it by 4e-9, the fourth-order differences' truncation.
    analysis::LinearizeOptions lo;
    lo.step = 2.5e-4;
    const LinearModel a = linearize(carcass, trimC, lo), b = linearize(constant, trimK, lo);
    ASSERT_EQ(a.eigenvalues.size(), b.eigenvalues.size());
    EXPECT_LT(compareEigenvalues(a, b), 1e-7) << name << " at " << V << " m/s, roll " << opt.roll;
    EXPECT_LT(compareEigenvalues(b, a), 1e-7) << name;
  }
}

// Sharp, Evangelou & Limebeer (2004): sigma = K_ya (C1 + C2 V + C3 V^2), Table 9.5's front and rear
// coefficients; as a carcass, k_y0 = 1/C1, b1 = C2/C1, b2 = C3/C1, with K_ya = Fz k_alpha.
TEST(TyreCarcass, PublishedSpeedLawAsACarcass) {
  core::PortableRandom rng(3032);
  const double C[2][3] = {{8.633e-6, 3.725e-8, 8.389e-10}, {9.694e-6, -1.333e-8, 1.898e-9}};
  for (const auto& c : C) {
    LinearTyreParameters p;
    p.corneringStiffness = rng.drawUniform(8, 20);
    p.lateralCarcassStiffness = 1 / c[0];
    p.carcassSpeedCoefficient = c[1] / c[0];
    p.carcassSpeedCoefficient2 = c[2] / c[0];
    const auto law = makeLinearTyreForceLaw(p);
    for (int i = 0; i < 10; ++i) {
      const double Fz = rng.drawUniform(300, 3000), V = rng.drawUniform(0, 150);
      const double expected = Fz * p.corneringStiffness * (c[0] + c[1] * V + c[2] * V * V);
      EXPECT_NEAR(law->calcRelaxationLength(Fz, 0, V), expected, 1e-12 * expected);
      EXPECT_NEAR(law->calcRelaxationLength(Fz, 0, -V), expected, 1e-12 * expected);  // even in V
    }
  }
}

// Bad carcass input is an InputError at its key with line and column: both a length and a stiffness,
// a speed coefficient without a stiffness, coefficients that make the stiffness non-positive at a drawn
// speed up to 150 m/s, a stiffness that is not positive, and one so stiff that sigma at the static load
// falls below 1e-4 m. A compliance positive up to 150 m/s but not beyond is accepted.
TEST(TyreCarcass, BadCarcassInputIsRefusedAtItsKey) {
  const std::string file = kDir + "/scenarios/supersport.yaml";
  const std::filesystem::path dir = makeTempDir("tyre_carcass");
  const std::string both = (dir / "both.yaml").string();
  {
    std::ifstream in(file);
    std::ofstream out(both);
    std::string line;
    while (std::getline(in, line)) {
      const auto at = line.find("relaxation_length_m: 0.129");
      if (at != std::string::npos) line.insert(at, "lateral_carcass_stiffness_N_per_m: 1.1e5, ");
      out << line << "\n";
    }
  }
  const InputError e = test::catchInputError([&] { VehicleModel(loadScenario(both)); });
  EXPECT_EQ(e.getLocation().key, "contact.front.lateral_carcass_stiffness_N_per_m") << e.what();
  EXPECT_EQ(e.getLocation().line, 51) << e.what();
  EXPECT_GT(e.getLocation().column, 1) << e.what();
  EXPECT_NE(e.getReason().find("not both"), std::string::npos) << e.what();

  const std::string carcass = "lateral_carcass_stiffness_N_per_m: 1.1e5";
  const YAML::Node rear = YAML::LoadFile(file)["contact"]["rear"];
  core::PortableRandom rng(3033);
  const double V0 = rng.drawUniform(1, 149);
  struct Case {
    std::string set, key, reason;
  };
  for (const Case& c : std::vector<Case>{
           {"contact.front.carcass_compliance_speed_coefficient_s_per_m=1e-3", "contact.front.carcass_compliance_speed_coefficient_s_per_m",
            "needs lateral_carcass_stiffness_N_per_m"},
           {"contact.rear=" + openTyre(rear) + carcass +
                ", carcass_compliance_speed_coefficient_s_per_m: " + io::formatNumber(-1.001 / V0) + "}",
            "contact.rear.carcass_compliance_speed_coefficient_s_per_m", "must stay positive"},
           {"contact.rear=" + openTyre(rear) + carcass +
                ", carcass_compliance_speed_coefficient_s2_per_m2: " + io::formatNumber(-1.001 / (V0 * V0)) + "}",
            "contact.rear.carcass_compliance_speed_coefficient_s2_per_m2", "must stay positive"},
           {"contact.rear=" + openTyre(rear) +
                "lateral_carcass_stiffness_N_per_m: -1e5}",
            "contact.rear.lateral_carcass_stiffness_N_per_m", "positive"},
           {"contact.rear=" + openTyre(rear) +
                "lateral_carcass_stiffness_N_per_m: 1e12}",
            "contact.rear.lateral_carcass_stiffness_N_per_m", "at least 0.0001 m"}}) {
    const InputError err = test::catchInputError([&] { VehicleModel(loadScenario(file, {c.set})); });
    EXPECT_EQ(err.getLocation().key, c.key) << c.set << ": " << err.what();
    EXPECT_NE(err.getReason().find(c.reason), std::string::npos) << err.what();
  }
  const Carcass limit{1.1e5, -1 / 151.0, 0};  // positive up to 150 m/s
  EXPECT_NO_THROW(VehicleModel(loadScenario(file, {"contact.rear=" + makeTyre(rear, &limit)})));
}

}  // namespace
}  // namespace motostab::tyres

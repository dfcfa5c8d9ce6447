// Diagnosis tests that hide an effect: "measured" data come from the extended model
// (hidden_effect.h) with values and noise drawn here; diagnose must name the effect (or list it as
// indistinguishable from the named one), estimate its parameter within 2 standard errors and 15 %,
// and improve the cross-validated RMS by a factor of at least 2. Candidate lists are trimmed to the
// true effect and its look-alikes to keep each test within seconds.
#include <gtest/gtest.h>

#include <filesystem>

#include "diagnosis/diagnosis.h"
#include "output/diagnosis_output.h"
#include "run_hidden.h"

namespace motostab::diagnosis {

using io::formatNumber;

namespace {

namespace fs = std::filesystem;
const std::string kDir = MOTOSTAB_SOURCE_DIR;
const std::string kBenchmark = kDir + "/scenarios/whipple-benchmark.yaml";
const std::string kEnduro = kDir + "/scenarios/enduro.yaml";

using testing::runHidden;

testing::HiddenEffect makeEffect(const std::string& scenario, uint64_t seed, std::vector<std::string> overrides,
                                 std::vector<std::string> modes) {
  testing::HiddenEffect h;
  h.scenario = scenario;
  h.seed = seed;
  h.overrides = std::move(overrides);
  h.modes = std::move(modes);
  return h;
}

// The cause `name` (named, or indistinguishable from a named one) with parameter `key` near `truth`.
void expectFound(const DiagnosisResult& r, const std::string& name, const std::string& key, double truth) {
  const FitSummary* hit = nullptr;
  for (const auto& c : r.causes) {
    if (c.fit.name == name) hit = &c.fit;
    for (const auto& i : c.indistinguishable)
      if (i.name == name && !hit) hit = &i;
  }
  ASSERT_NE(hit, nullptr) << name << " not found; first candidate " << (r.candidates.empty() ? "" : r.candidates[0].name);
  const ParameterEstimate* p = nullptr;
  for (const auto& e : hit->parameters)
    if (e.name == key) p = &e;
  ASSERT_NE(p, nullptr);
  EXPECT_NEAR(p->value, truth, 2 * p->stderr_) << name;
  EXPECT_NEAR(p->value, truth, 0.15 * std::abs(truth)) << name;
  EXPECT_GE(r.baseline.cvRms / r.extended.cvRms, 2.0);
}

std::string damper(double c) { return "steer_damper={damping_Nms_per_rad: " + formatNumber(c) + "}"; }

TEST(HiddenEffect, SteerDamperFromEigenvalues) {
  // Rows of every mode the sweep labels between 3 and 8 m/s (weave, capsize, castor). Bicycle-sized
  // dampers; seed 101 draws noise about 1.3 times its nominal level on the weave rows, the case where
  // a noise estimate fitted to the richer model's residuals named a spurious second cause (wheelbase)
  // and pulled the damping 20-28 % low.
  testing::Draw draw(707);
  const double c = draw.uniform(0.15, 0.45);
  auto h = makeEffect(kBenchmark, 101, {damper(c)}, {"weave", "capsize", "castor"});
  h.start = 3;  // where the damped weave is still oscillatory
  const DiagnosisResult r = runHidden(h, "damper", true, {}, "steer_damper,tyre_slip,parameter:geometry.*,parameter:front_frame.inertia_kgm2.zz", 3);
  expectFound(r, "steer_damper", "damping_Nms_per_rad", c);
  EXPECT_EQ(r.causes.size(), 1u) << "second cause: " << (r.causes.size() > 1 ? r.causes[1].fit.name : "");
}

TEST(HiddenEffect, SteerDamperFromResponsesOnly) {
  const double c = testing::Draw(1414).uniform(0.3, 0.8);
  const auto h = makeEffect(kBenchmark, 202, {damper(c)}, {});
  const DiagnosisResult r = runHidden(h, "damper-runs", false, {3.5, 4.5, 5.5, 6.5},
                                      "steer_damper,parameter:geometry.trail_m,parameter:front_frame.inertia_kgm2.zz", 3);
  expectFound(r, "steer_damper", "damping_Nms_per_rad", c);
}

TEST(HiddenEffect, WrongTrail) {
  testing::Draw draw(2121);
  const double trail = 0.08 + draw.uniform(0.02, 0.035) * (draw.uniform() < 0.5 ? -1 : 1);
  auto h = makeEffect(kBenchmark, 303, {"geometry.trail_m=" + formatNumber(trail)}, {"weave", "capsize"});
  h.step = 0.25, h.relativeNoise = 0.002, h.absoluteNoise = 0.002;
  const DiagnosisResult r = runHidden(h, "trail", true, {}, "steer_damper,parameter:geometry.*,parameter:front_frame.com_m[0]", 1);
  expectFound(r, "parameter:geometry.trail_m", "value", trail);
}

TEST(HiddenEffect, TwoEffectsAtOnce) {
  testing::Draw draw(2828);
  const double c = draw.uniform(0.3, 0.8), trail = 0.08 + draw.uniform(0.025, 0.035);
  auto h = makeEffect(kBenchmark, 404, {damper(c), "geometry.trail_m=" + formatNumber(trail)}, {"weave", "capsize"});
  h.step = 0.25, h.relativeNoise = 0.002, h.absoluteNoise = 0.002;
  const DiagnosisResult r = runHidden(h, "two", true, {}, "steer_damper,parameter:geometry.trail_m,parameter:geometry.wheelbase_m", 3);
  expectFound(r, "steer_damper", "damping_Nms_per_rad", c);
  expectFound(r, "parameter:geometry.trail_m", "value", trail);
}

TEST(HiddenEffect, SwingarmTorsionOnTheEnduro) {
  const double scale = testing::Draw(3535).uniform(0.25, 0.6);  // an unseen stiffness: not the seed's 1 or 0.5
  auto h = makeEffect(kEnduro, 505, {"swingarm.compliance=torsion", "swingarm.stiffness_scale=" + formatNumber(scale)},
                      {"weave", "wobble"});
  h.start = 10, h.stop = 40, h.step = 3;
  const DiagnosisResult r = runHidden(h, "torsion", true, {}, "swingarm_*,steer_damper,fork_compliance", 1);
  expectFound(r, "swingarm_torsion", "stiffness_scale", scale);
}

TEST(HiddenEffect, ForkComplianceOnTheEnduro) {
  testing::Draw draw(4242);
  const double k = std::exp(draw.uniform(std::log(2e4), std::log(6e4)));
  auto h = makeEffect(kEnduro, 606, {"fork_compliance={stiffness_Nm_per_rad: " + formatNumber(k) + ", damping_Nms_per_rad: 0}"},
                      {"weave", "wobble"});
  h.start = 10, h.stop = 40, h.step = 3;
  const DiagnosisResult r = runHidden(h, "fork", true, {}, "fork_compliance,steer_damper,swingarm_twist", 1);
  expectFound(r, "fork_compliance", "stiffness_Nm_per_rad", k);
}

// A leaning rider on the benchmark bicycle (its 85 kg rear frame includes the rider): the upper body
// built here as docs/diagnosis.md states the candidate's (a 75 kg rider's head-arms-trunk, 0.678 of
// it (Winter 2009), a proportional slice of the rear frame hinged 0.25 m below its CoM, damping 0.3
// of critical at 4 m g d), with a lean stiffness drawn between 2 and 6 m g d.
TEST(HiddenEffect, RiderLeanOnTheBenchmark) {
  const YAML::Node rf = makeScenarioTree(kBenchmark, {})["rear_frame"];
  const double mB = rf["mass_kg"].as<double>(), mU = 0.678 * 75, share = mU / mB, d = 0.25;
  const double zU = rf["com_m"][2].as<double>(), gravity = mU * 9.81 * d;
  std::string body = "rider_lean={hinge_height_m: " + formatNumber(zU - d) + ", mass_kg: " + formatNumber(mU) +
                     ", com_m: [" + formatNumber(rf["com_m"][0].as<double>()) + ", 0, " + formatNumber(zU) + "], inertia_kgm2: {";
  for (const char* k : {"xx", "yy", "zz", "xy", "xz", "yz"})
    body += std::string(k) + ": " + formatNumber(share * rf["inertia_kgm2"][k].as<double>(0.0)) + (k[1] == 'z' && k[0] == 'y' ? "}" : ", ");
  const double damping = 0.6 * std::sqrt(4 * gravity * (share * rf["inertia_kgm2"]["xx"].as<double>() + mU * d * d));
  const double k = testing::Draw(5151).uniform(2, 6) * gravity;
  auto h = makeEffect(kBenchmark, 707, {body + ", stiffness_Nm_per_rad: " + formatNumber(k) + ", damping_Nms_per_rad: " +
                                            formatNumber(damping) + "}"}, {"weave", "capsize"});
  h.start = 3;
  const DiagnosisResult r = runHidden(h, "rider", true, {}, "rider_lean,steer_damper,parameter:geometry.trail_m", 1);
  expectFound(r, "rider_lean", "stiffness_Nm_per_rad", k);
}

// A parameter whose profile-likelihood interval runs into vehicles that cannot exist: the benchmark
// front frame's I_xz (0.00756 kg m^2 in the scenario's z-up axes) drawn near the end of its valid range
// (the triangle inequality of the principal moments, computed here from Meijaard et al. 2007 Table 1:
// I_xx 0.05892, I_yy 0.06, I_zz 0.00708 kg m^2, |I_xz| <= sqrt((I_yy / 2)^2 - ((I_xx - I_zz) / 2)^2)). The interval must stop at that edge (a
// refit there throws: before, the whole diagnosis stopped with the scenario's input error).
TEST(HiddenEffect, ProfileStopsAtTheEdgeOfValidVehicles) {
  const double edge = std::sqrt(0.03 * 0.03 - std::pow((0.05892 - 0.00708) / 2, 2));
  const double xz = edge * testing::Draw(6363).uniform(0.97, 0.99);
  auto h = makeEffect(kBenchmark, 808, {"front_frame.inertia_kgm2.xz=" + formatNumber(xz)}, {"weave", "capsize", "castor"});
  h.start = 3, h.step = 0.25, h.relativeNoise = 0.002, h.absoluteNoise = 0.002;
  const DiagnosisResult r = runHidden(h, "edge", true, {}, "parameter:front_frame.inertia_kgm2.xz", 1);
  ASSERT_EQ(r.causes.size(), 1u);
  const ParameterEstimate& e = r.causes[0].fit.parameters.at(0);
  ASSERT_TRUE(e.hasProfile);
  EXPECT_NEAR(e.value, xz, 3 * e.stderr_);
  EXPECT_LE(e.profileHigh, edge + 1e-6) << "the interval reaches past the valid range";
  EXPECT_GT(e.profileHigh, edge - 0.5 * (edge - e.value)) << "the interval stops short of the edge";
}

// Noise only: no cause in any of 20 seeds.
TEST(HiddenEffect, NullDataNamesNothing) {
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const auto h = makeEffect(kBenchmark, 1000 + seed, {}, {"weave", "capsize"});
    const DiagnosisResult r = runHidden(h, "null-" + std::to_string(seed), true, {},
                                        "steer_damper,tyre_slip,parameter:geometry.trail_m,parameter:front_frame.mass_kg", 1);
    EXPECT_TRUE(r.causes.empty()) << "seed " << seed << ": " << (r.causes.empty() ? "" : r.causes[0].fit.name);
  }
}

}  // namespace
}  // namespace motostab::diagnosis

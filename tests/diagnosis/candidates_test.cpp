// Default candidates: rider_lean is offered where the rear frame holds a rider
// (the benchmark bicycle's 85 kg rear frame includes its rider, Meijaard et al. 2007) and loads as a
// valid scenario; on the riderless Kooijman (2008) Silvercity (12.06 kg rear frame) it is listed as
// unavailable with the reason. The upper body's mass is Winter's (2009, Table 4.1) head-arms-trunk
// share 0.678 of the assumed rider mass; its stiffness start is 4 m g d with d = 0.25 m.
#include <gtest/gtest.h>

#include "diagnosis/candidates.h"
#include "diagnosis/diagnosis.h"
#include "scenario/scenario.h"

namespace motostab::diagnosis {

using scenario::Scenario;
using scenario::loadScenario;

namespace {

const std::string kDir = MOTOSTAB_SOURCE_DIR;

const Candidate* find(const std::vector<Candidate>& all, const std::string& name) {
  for (const auto& c : all)
    if (c.name == name) return &c;
  return nullptr;
}

TEST(Candidates, RiderLeanWhereTheRearFrameHoldsARider) {
  const std::string file = kDir + "/scenarios/whipple-benchmark.yaml";
  std::vector<std::string> unavailable;
  const auto all = listCandidates(makeScenarioTree(file, {}), {}, &unavailable);
  const Candidate* c = find(all, "rider_lean");
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(c->parameters.size(), 1u);
  const double mU = 0.678 * kRiderMass_kg, gravity = mU * 9.81 * 0.25;
  EXPECT_NEAR(c->parameters[0].start, 4 * gravity, 1e-9 * gravity);
  EXPECT_NEAR(c->parameters[0].lower, 1.1 * gravity, 1e-9 * gravity);
  EXPECT_TRUE(c->parameters[0].offAtInfinity);
  std::vector<std::string> ov = c->fixedOverrides;
  ov.push_back("rider_lean.stiffness_Nm_per_rad=1234");
  const Scenario s = loadScenario(file, ov);
  ASSERT_TRUE(s.hasRiderLean);
  EXPECT_NEAR(s.riderLean.body.mass, mU, 1e-9);
  EXPECT_NEAR(s.riderLean.stiffness, 1234, 1e-9);
  EXPECT_NEAR(s.riderLean.body.com[2] - s.riderLean.hingeHeight, 0.25, 1e-9);
  EXPECT_TRUE(unavailable.empty());
}

TEST(Candidates, NoRiderLeanOnARiderlessBicycle) {
  std::vector<std::string> unavailable;
  const auto all = listCandidates(makeScenarioTree(kDir + "/scenarios/kooijman-silvercity.yaml", {}), {}, &unavailable);
  EXPECT_EQ(find(all, "rider_lean"), nullptr);
  ASSERT_EQ(unavailable.size(), 1u);
  EXPECT_NE(unavailable[0].find("riderless"), std::string::npos) << unavailable[0];
  EXPECT_NE(find(all, "steer_damper"), nullptr);
}

// A scenario with a leaning rider (Browser with Jason, BicycleParameters) offers no second one; its lean
// stiffness and damping are wrong-parameter candidates instead, centred on the scenario's values.
TEST(Candidates, AnExistingRiderLeanHasItsStiffnessAndDampingAsParameters) {
  const std::string file = kDir + "/scenarios/browser-jason-rider.yaml";
  const YAML::Node tree = makeScenarioTree(file, {});
  std::vector<std::string> unavailable;
  const auto all = listCandidates(tree, {}, &unavailable);
  EXPECT_EQ(find(all, "rider_lean"), nullptr);
  ASSERT_EQ(unavailable.size(), 1u);
  EXPECT_NE(unavailable[0].find("rider_lean"), std::string::npos) << unavailable[0];
  for (const char* key : {"stiffness_Nm_per_rad", "damping_Nms_per_rad"}) {
    const Candidate* c = find(all, std::string("parameter:rider_lean.") + key);
    ASSERT_NE(c, nullptr) << key;
    ASSERT_EQ(c->parameters.size(), 1u);
    EXPECT_DOUBLE_EQ(c->parameters[0].start, tree["rider_lean"][key].as<double>());
    EXPECT_LT(c->parameters[0].lower, c->parameters[0].start);
    EXPECT_GT(c->parameters[0].upper, c->parameters[0].start);
  }
}

}  // namespace
}  // namespace motostab::diagnosis

// Default candidates: rider_lean is offered where the rear frame holds a rider
// (the benchmark bicycle's 85 kg rear frame includes its rider, Meijaard et al. 2007) and loads as a
// valid scenario; on the riderless Kooijman (2008) Silvercity (12.06 kg rear frame) it is listed as
// unavailable with the reason. The upper body's mass is Winter's (2009, Table 4.1) head-arms-trunk
// share 0.678 of the assumed rider mass; its stiffness start is 4 m g d with d = 0.25 m.
#include <gtest/gtest.h>

#include "tests/support/extension_sections.h"
#include "vehicle/vehicle_model.h"
#include "diagnosis/candidates.h"
#include "plugins/builtin.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/linearize.h"
#include "analysis/trim.h"
#include "core/portable_random.h"
#include "diagnosis/fit_problem.h"
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
  std::vector<std::string> ov = c->fixedOverrides.format();
  ov.push_back("rider_lean.stiffness_Nm_per_rad=1234");
  const Scenario s = loadScenario(file, ov);
  auto lean = [&](const std::string& key) { return testing::getExtensionValue(s, "rider_lean", key); };
  EXPECT_NEAR(lean("mass_kg").as<double>(), mU, 1e-9);
  EXPECT_NEAR(lean("stiffness_Nm_per_rad").as<double>(), 1234, 1e-9);
  EXPECT_NEAR(lean("com_m")[2].as<double>() - lean("hinge_height_m").as<double>(), 0.25, 1e-9);
  EXPECT_NO_THROW(vehicle::VehicleModel{s});  // the section is a valid rider_lean
  EXPECT_TRUE(unavailable.empty());
}

TEST(Candidates, NoRiderLeanOnARiderlessBicycle) {
  std::vector<std::string> unavailable;
  const auto all = listCandidates(makeScenarioTree(kDir + "/scenarios/kooijman-silvercity.yaml", {}), {}, &unavailable);
  EXPECT_EQ(find(all, "rider_lean"), nullptr);
  EXPECT_EQ(find(all, "rider_arms"), nullptr);
  ASSERT_EQ(unavailable.size(), 2u);
  EXPECT_NE(unavailable[0].find("riderless"), std::string::npos) << unavailable[0];
  EXPECT_EQ(unavailable[1].rfind("rider_arms:", 0), 0u) << unavailable[1];
  EXPECT_NE(find(all, "steer_damper"), nullptr);
}

// tyre_relaxation on relaxation_linear tyres: one factor scales both tyres' relaxation lengths (the
// supersport's 0.129 and 0.122 m); the switched-on scenario loads with the scaled lengths.
TEST(Candidates, TyreRelaxationScalesBothTyres) {
  const std::string file = kDir + "/scenarios/supersport.yaml";
  const std::vector<Candidate> all = listCandidates(makeScenarioTree(file, {}), {});
  const Candidate* c = find(all, "tyre_relaxation");
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(c->parameters.size(), 1u);
  const double f = core::PortableRandom(77).drawUniform(0.3, 3);
  ModelSpec m;
  m.parts = {c};
  Eigen::VectorXd x(1);
  x << std::log(f);
  const std::vector<std::string> ov = m.makeOverrides(x).format();
  EXPECT_NO_THROW(loadScenario(file, ov));
  std::map<std::string, double> set;
  for (const auto& o : ov) set[o.substr(0, o.find('='))] = std::stod(o.substr(o.find('=') + 1));
  EXPECT_NEAR(set["contact.front.relaxation_length_m"], 0.129 * f, 1e-12);
  EXPECT_NEAR(set["contact.rear.relaxation_length_m"], 0.122 * f, 1e-12);
  EXPECT_EQ(find(listCandidates(makeScenarioTree(kDir + "/scenarios/whipple-benchmark.yaml", {}), {}), "tyre_relaxation"), nullptr);
}

// tyre_carcass on relaxation_linear tyres: each tyre's relaxation length becomes the carcass's,
// sigma = sigma0 (Fz/Fz0)(1 + lambda (b1 V + b2 V^2)), with the supersport's sigma0 (0.129, 0.122 m) at the
// static loads Fz0 and Sharp, Evangelou & Limebeer's (2004) speed coefficients b1 = C2/C1, b2 = C3/C1
// (Evangelou 2004 Table 9.5) times the free factor lambda. At a drawn lambda and speed the built model's
// lag rate of each tyre, read off the linearisation, is -V/sigma with that sigma at the trim's load.
TEST(Candidates, TyreCarcassGivesThePublishedSpeedDependenceTimesItsFactor) {
  const std::string file = kDir + "/scenarios/supersport.yaml";
  const std::vector<Candidate> all = listCandidates(makeScenarioTree(file, {}), {});
  const Candidate* c = find(all, "tyre_carcass");
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(c->parameters.size(), 1u);
  EXPECT_DOUBLE_EQ(c->parameters[0].priorMean, 1);
  EXPECT_TRUE(c->parameters[0].offAtBound);
  EXPECT_EQ(c->parameters[0].off, 0);
  core::PortableRandom rng(78);
  const double lambda = rng.drawUniform(0.2, 2.5), V = rng.drawUniform(10, 45);
  ModelSpec m;
  m.parts = {c};
  Eigen::VectorXd x(1);
  x << lambda;
  const std::vector<std::string> ov = m.makeOverrides(x).format();
  const vehicle::VehicleModel model(loadScenario(file, ov));
  const auto trim = analysis::calcTrim(model, V);
  const auto lin = analysis::linearize(model, trim);
  const auto static0 = scenario::calcStaticWheelLoads(loadScenario(file));  // rear, front
  const auto names = model.getContactOutputNames();
  const auto values = model.calcContactOutputs(trim.state);
  auto output = [&](const std::string& n) { return values[std::find(names.begin(), names.end(), n) - names.begin()]; };
  struct Tyre {
    std::string name;
    double sigma0, Fz0, C1, C2, C3;
  };
  for (const Tyre& t : {Tyre{"front", 0.129, static0[1], 8.633e-6, 3.725e-8, 8.389e-10},
                        Tyre{"rear", 0.122, static0[0], 9.694e-6, -1.333e-8, 1.898e-9}}) {
    const double sigma = t.sigma0 * output(t.name + "_tyre_Fz_N") / t.Fz0 * (1 + lambda * (t.C2 / t.C1 * V + t.C3 / t.C1 * V * V));
    const int z = lin.findState(t.name + "_tyre_lagged_slip");
    ASSERT_GE(z, 0);
    const double Veps = std::sqrt(V * V + 0.01);
    EXPECT_NEAR(lin.A(z, z), -Veps / sigma, 1e-7 * Veps / sigma) << t.name << ", lambda " << lambda << ", " << V << " m/s";
  }
  // Not offered without relaxation_linear tyres, nor twice.
  EXPECT_EQ(find(listCandidates(makeScenarioTree(kDir + "/scenarios/whipple-benchmark.yaml", {}), {}), "tyre_carcass"), nullptr);
  std::vector<std::string> unavailable;
  EXPECT_EQ(find(listCandidates(makeScenarioTree(file, ov), {}, &unavailable), "tyre_carcass"), nullptr);
  EXPECT_TRUE(std::any_of(unavailable.begin(), unavailable.end(), [](const std::string& u) { return u.find("tyre_carcass") == 0; }));
}

// rider_arms where the rear frame holds a rider: Sharp's (1994) hands-on steer inertia 0.20 kg m^2
// (0.71 -> 0.91), stiffness and damping free with priors centred on his 50 N m/rad and 5 N m s/rad; the
// switched-on scenario loads with those values.
TEST(Candidates, RiderArmsOnTheSupersport) {
  const std::string file = kDir + "/scenarios/supersport.yaml";
  const auto all = listCandidates(makeScenarioTree(file, {}), {});
  const Candidate* c = find(all, "rider_arms");
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(c->parameters.size(), 2u);
  EXPECT_EQ(c->parameters[0].path, "rider_arms.stiffness_Nm_per_rad");
  EXPECT_DOUBLE_EQ(c->parameters[0].priorMean, 50);
  EXPECT_EQ(c->parameters[1].path, "rider_arms.damping_Nms_per_rad");
  EXPECT_DOUBLE_EQ(c->parameters[1].priorMean, 5);
  std::vector<std::string> ov = c->fixedOverrides.format();
  ov.push_back("rider_arms.damping_Nms_per_rad=7");
  const Scenario s = loadScenario(file, ov);
  auto arms = [&](const std::string& key) { return testing::getExtensionValue(s, "rider_arms", key).as<double>(); };
  EXPECT_NEAR(arms("inertia_kgm2"), 0.20, 1e-12);
  EXPECT_NEAR(arms("stiffness_Nm_per_rad"), 50, 1e-12);
  EXPECT_NEAR(arms("damping_Nms_per_rad"), 7, 1e-12);
  EXPECT_NO_THROW(vehicle::VehicleModel{s});
  EXPECT_EQ(find(listCandidates(makeScenarioTree(file, ov), {}), "rider_arms"), nullptr);  // it has them
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

namespace motostab::diagnosis {
namespace {

// Where `path` (a --set key path) lies in the declared sections: the failure message if it names a
// key no declared section of its path declares (a section may be declared once per selector, e.g. the
// contact models' `contact.front`), "" if one declares it or it lies in a plugin's undeclared mapping.
std::string checkDeclared(const std::vector<io::SectionFields>& sections, const std::string& path) {
  size_t longest = 0;
  for (const io::SectionFields& s : sections)
    if (!s.path.empty() && path.rfind(s.path + ".", 0) == 0) longest = std::max(longest, s.path.size());
  if (longest == 0) return "";
  const std::string section = path.substr(0, longest), rest = path.substr(longest + 1);
  const size_t end = rest.find_first_of(".[");
  const std::string key = rest.substr(0, end);
  for (const io::SectionFields& s : sections)
    if (s.path == section)
      for (const io::Field& f : s.fields)
        if (f.key == key) return "";
  return end == std::string::npos ? path + ": section " + section + " declares no key " + key : "";
}

// Every key a candidate writes (its parameters' paths and the sections its fixed changes switch on) is
// one its section declares, so the extended scenarios diagnosis writes read back with the declared
// meaning, on motorcycles, bicycles and a controlled bicycle.
TEST(Candidates, WrittenKeysAreDeclaredFields) {
  const std::vector<io::SectionFields> sections = plugins::listSectionFields(plugins::makeBuiltinRegistry());
  int checked = 0;
  for (const char* name : {"enduro", "supersport", "whipple-benchmark", "balance-assist", "kooijman-silvercity"}) {
    const std::string file = kDir + "/scenarios/" + name + ".yaml";
    for (const Candidate& c : listCandidates(makeScenarioTree(file, {}), {})) {
      for (const CandidateParameter& p : c.parameters) {
        EXPECT_EQ(checkDeclared(sections, p.path), "") << name << " " << c.name;
        for (const std::string& also : p.alsoPaths) EXPECT_EQ(checkDeclared(sections, also), "") << name << " " << c.name;
        ++checked;
      }
      for (const scenario::ParameterOverride& o : c.fixedOverrides.getItems()) {
        EXPECT_EQ(checkDeclared(sections, o.path), "") << name << " " << c.name;
        if (const YAML::Node* node = std::get_if<YAML::Node>(&o.value); node && node->IsMap())
          for (const auto& kv : *node) {
            EXPECT_EQ(checkDeclared(sections, o.path + "." + kv.first.as<std::string>()), "") << name << " " << c.name;
            ++checked;
          }
      }
    }
  }
  EXPECT_GT(checked, 100);
  // The check itself: an undeclared key of a declared section is named.
  EXPECT_NE(checkDeclared(sections, "steer_damper.damping_Ns_per_rad"), "");
  EXPECT_EQ(checkDeclared(sections, "rider_lean.inertia_kgm2.xz"), "");
}

}  // namespace
}  // namespace motostab::diagnosis

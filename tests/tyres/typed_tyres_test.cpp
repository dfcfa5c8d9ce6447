// The typed tyre constructors (C++ values, no YAML text): a `relaxation_linear` and a `magic_formula`
// contact model built by makeRelaxationLinear and makeMagicFormulaContact from the values a scenario
// gives give the same vehicle as the scenario reader builds from that scenario: the same linearised
// state matrix, bit for bit, at a speed drawn at random.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <map>
#include <string>

#include "analysis/linearize.h"
#include "core/portable_random.h"
#include "plugins/builtin.h"
#include "tyres/coefficient_source.h"
#include "tyres/magic_formula_contact.h"
#include "tyres/relaxation_linear.h"

namespace motostab::tyres {

using analysis::LinearModel;
using analysis::calcTrim;
using analysis::linearize;
using core::PortableRandom;
using plugins::PluginRegistry;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

const std::string kScenarios = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/";

// The linearised model of `scenario` with its contact replaced by the model `make` returns.
LinearModel linearizeWithContact(Scenario scenario, const std::function<std::unique_ptr<plugins::ContactModel>()>& make,
                                 double speed) {
  PluginRegistry registry = plugins::makeBuiltinRegistry();
  registry.addContactModel("typed", [&](io::YamlMap&) { return make(); });
  scenario.contact.model = "typed";
  YAML::Node params(YAML::NodeType::Map);
  params["model"] = "typed";
  scenario.contact.params.reset(params);  // rebinds: assignment would write into the node `scenario` shares
  const VehicleModel model(scenario, registry);
  return linearize(model, calcTrim(model, speed));
}

LinearModel linearizeAsRead(const Scenario& scenario, double speed) {
  const VehicleModel model(scenario);
  return linearize(model, calcTrim(model, speed));
}

TEST(TypedTyres, RelaxationLinearIsTheReadersModel) {
  PortableRandom rng(2033);
  const double speed = rng.drawUniform(3, 8);
  const Scenario read = loadScenario(kScenarios + "whipple-benchmark-tyres.yaml");
  ASSERT_EQ(read.contact.model, "relaxation_linear");
  ASSERT_EQ(read.contact.params["preset"].as<std::string>(), "bicycle");
  const LinearTyreParameters p = getRelaxationLinearPreset("bicycle");
  const LinearModel typed = linearizeWithContact(read, [&] { return makeRelaxationLinear(p, p); }, speed);
  const LinearModel reference = linearizeAsRead(read, speed);
  ASSERT_EQ(typed.A.rows(), reference.A.rows());
  EXPECT_EQ((typed.A - reference.A).lpNorm<Eigen::Infinity>(), 0) << "speed " << speed;
  EXPECT_GT(typed.A.rows(), 8) << "the relaxation states are there";
}

// The supersport's motorcycle Magic Formula tyres: the coefficients as numbers in code (read here from
// the scenario file into a map), the law built by makeTyreForceLaw from makeMapSource.
MagicFormulaTyre makeTyre(const YAML::Node& side) {
  std::map<std::string, double> coefficients;
  for (const auto& kv : side["coefficients"]) coefficients[kv.first.as<std::string>()] = kv.second.as<double>();
  MagicFormulaTyre t;
  t.variant = MagicFormulaVariant::Motorcycle;
  t.law = makeTyreForceLaw(t.variant, *makeMapSource(coefficients, nullptr));
  t.radial = {side["radial_stiffness_N_per_m"].as<double>(), side["radial_damping_Ns_per_m"].as<double>()};
  return t;
}

TEST(TypedTyres, MagicFormulaIsTheReadersModel) {
  PortableRandom rng(3320);
  const double speed = rng.drawUniform(10, 40);
  const std::string file = kScenarios + "supersport-mf.yaml";
  const YAML::Node contact = YAML::LoadFile(file)["contact"];
  ASSERT_EQ(contact["model"].as<std::string>(), "magic_formula");
  const MagicFormulaTyre front = makeTyre(contact["front"]), rear = makeTyre(contact["rear"]);
  const Scenario read = loadScenario(file);
  const LinearModel typed = linearizeWithContact(read, [&] { return makeMagicFormulaContact(front, rear); }, speed);
  const LinearModel reference = linearizeAsRead(read, speed);
  ASSERT_EQ(typed.A.rows(), reference.A.rows());
  EXPECT_EQ((typed.A - reference.A).lpNorm<Eigen::Infinity>(), 0) << "speed " << speed;
  // A missing coefficient of the typed source is an input error naming it.
  std::map<std::string, double> none{{"FNOMIN", 1100}};
  try {
    makeTyreForceLaw(MagicFormulaVariant::Motorcycle, *makeMapSource(none, nullptr, "front tyre"));
    ADD_FAILURE() << "no error for a law without coefficients";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.getLocation().file, "front tyre");
    EXPECT_FALSE(e.getLocation().key.empty());
  }
}

}  // namespace
}  // namespace motostab::tyres

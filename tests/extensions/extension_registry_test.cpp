// Model extensions as plugins (plugins/plugin_api.h ExtensionModel): an extension written in this test
// and registered by one line is built into the vehicle (checked against Meijaard et al. 2007 with its
// stiffness added to the steer entry of K, tests/support); the stages run in registration order
// whatever the file's order; unknown sections and duplicate names are errors.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <ostream>

#include "analysis/linearize.h"
#include "core/portable_random.h"
#include "extension_test_util.h"
#include "extensions/steer_torque.h"
#include "plugins/builtin.h"
#include "tests/support/benchmark_equations.h"
#include "tests/support/catch_input_error.h"

namespace motostab::extensions {

using core::PortableRandom;
using io::formatNumber;
using plugins::PluginRegistry;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

using namespace motostab::testing;

// A steer spring T = -k delta between the frames: the smallest extension, as a user would write one.
class SteerSpring : public plugins::ExtensionModel {
 public:
  explicit SteerSpring(double k) : k_(k) {}
  void addForces(plugins::BuildContext& ctx, const plugins::VehicleFrames& frames) override {
    const double k = k_;
    addSteerTorque(ctx, frames.frontFrame, [k](double steer, double) { return -k * steer; },
                   [k](double steer) { return 0.5 * k * steer * steer; });
    front_ = frames.frontFrame;
  }
  std::vector<std::string> getOutputNames() const override { return {"steer_spring_torque"}; }
  std::vector<double> calcOutputs(const SimTK::State& s) const override {
    return {-k_ * front_.getOneQ(s, SimTK::MobilizerQIndex(0))};
  }
  void describe(std::ostream& out) const override { out << "  steer spring          " << k_ << " N m/rad\n"; }

 private:
  double k_;
  SimTK::MobilizedBody front_;
};

PluginRegistry makeRegistryWithSteerSpring() {
  PluginRegistry registry = plugins::makeBuiltinRegistry();
  registry.addExtensionModel("steer_spring", [](io::YamlMap& m, const plugins::VehicleLayout&) {
    return std::make_unique<SteerSpring>(m.getNonNegative("stiffness_Nm_per_rad"));
  });
  return registry;
}

TEST(ExtensionRegistry, AnExtensionRegisteredByOneLineIsBuiltIntoTheVehicle) {
  PortableRandom rng(4096);
  const double k = rng.drawUniform(2, 40), v = rng.drawUniform(2, 8);
  const Scenario s = loadScenario(kWhipple, {"steer_spring={stiffness_Nm_per_rad: " + formatNumber(k) + "}"});
  PluginRegistry registry = makeRegistryWithSteerSpring();
  const VehicleModel model(s, registry);
  const Eigen::VectorXcd ref = Eigen::EigenSolver<Eigen::Matrix4d>(calcBenchmarkStateMatrix(calcMeijaardMatrices(s), s.gravity, v, k)).eigenvalues();
  const Eigen::VectorXcd got = analysis::linearize(model, analysis::calcTrim(model, v)).eigenvalues;
  EXPECT_LT(calcSpectrumDistance(ref, got), 1e-8) << "\nref " << ref.transpose() << "\ngot " << got.transpose();
  // Its output, and a replica (worker threads) builds it again.
  ASSERT_EQ(model.getExtensionOutputNames(), std::vector<std::string>{"steer_spring_torque"});
  SimTK::State st = model.getDefaultState();
  st.updQ()[model.getIndices().steer] = 0.1;
  model.getSystem().realize(st, SimTK::Stage::Velocity);
  EXPECT_NEAR(model.calcExtensionOutputs(st).at(0), -0.1 * k, 1e-12);
  EXPECT_EQ(model.makeReplica()->getExtensionOutputNames(), model.getExtensionOutputNames());
  // The built-in registry does not know it: an InputError at the section, naming the known ones.
  const io::InputError e = test::catchInputError([&] { const VehicleModel plain(s); });
  EXPECT_EQ(e.getLocation().key, "steer_spring");
  EXPECT_NE(std::string(e.what()).find("steer_damper"), std::string::npos) << e.what();
}

TEST(ExtensionRegistry, UnknownSectionNamesFileLineAndColumn) {
  int line = 0;
  const std::string file = writeScenarioWith(kWhipple, "steer_dampr:\n  damping_Nms_per_rad: 1\n", "misspelt", line);
  EXPECT_NO_THROW(loadScenario(file));  // a mapping: an extension section until the plugins are asked
  const std::string what = expectInputError(file, line, 1, "steer_dampr");
  EXPECT_NE(what.find("unknown section 'steer_dampr'"), std::string::npos) << what;
  // Not a mapping: no section of any kind, refused at load.
  const std::string scalar = writeScenarioWith(kWhipple, "steer_dampr: 1\n", "misspelt_scalar", line);
  const io::InputError e = test::catchInputError([&] { loadScenario(scalar); });
  EXPECT_EQ(e.getLocation().line, line);
  EXPECT_EQ(e.getLocation().key, "steer_dampr");
}

// The stages and forces run in registration order: the file's order of the sections changes nothing,
// to the last bit.
TEST(ExtensionRegistry, FileOrderOfSectionsChangesNothing) {
  const std::string damper = "steer_damper: {damping_Nms_per_rad: 0.7, coulomb_Nm: 0.2}\n";
  const std::string arms = "rider_arms: {inertia_kgm2: 0.15, stiffness_Nm_per_rad: 30, damping_Nms_per_rad: 3}\n";
  const std::string lean = "rider_lean: {hinge_height_m: 0.75, mass_kg: 40, com_m: [0.45, 0, 1.05], "
                           "inertia_kgm2: {xx: 2, yy: 2.1, zz: 0.7, xy: 0, xz: 0, yz: 0}, "
                           "stiffness_Nm_per_rad: 2000, damping_Nms_per_rad: 60}\n";
  int line = 0;
  const Scenario a = loadScenario(writeScenarioWith(kEnduro, damper + arms + lean, "order_a", line));
  const Scenario b = loadScenario(writeScenarioWith(kEnduro, lean + arms + damper, "order_b", line));
  const VehicleModel ma(a), mb(b);
  EXPECT_EQ(ma.getQNames(), mb.getQNames());
  const Eigen::MatrixXd A = analysis::linearize(ma, analysis::calcTrim(ma, 12.0)).A;
  const Eigen::MatrixXd B = analysis::linearize(mb, analysis::calcTrim(mb, 12.0)).A;
  EXPECT_EQ((A - B).cwiseAbs().maxCoeff(), 0.0);
}

// Each extension checks its own share of a frame; together they may take too much: an input error
// naming the frame, not a Simbody failure (the Whipple rear frame, 85 kg and I_xx 9.2 kg m^2, gives a
// 25 kg upper body and the grips, but what remains breaks the triangle inequality).
TEST(ExtensionRegistry, ExtensionsTakingTooMuchOfAFrameAreAnInputError) {
  const Scenario s = loadScenario(kWhipple, {"rider_arms={inertia_kgm2: 0.15, stiffness_Nm_per_rad: 30, damping_Nms_per_rad: 3}",
                                             "rider_lean={hinge_height_m: 0.9, mass_kg: 25, com_m: [0.3, 0, 1.2], inertia_kgm2: "
                                             "{xx: 1.2, yy: 1.3, zz: 0.4, xy: 0, xz: 0, yz: 0}, stiffness_Nm_per_rad: 1200, "
                                             "damping_Nms_per_rad: 40}"});
  const io::InputError e = test::catchInputError([&] { const VehicleModel model(s); });
  EXPECT_EQ(e.getLocation().key, "rear_frame") << e.what();
  EXPECT_NE(std::string(e.what()).find("together take more"), std::string::npos) << e.what();
  EXPECT_NO_THROW(VehicleModel(loadScenario(kWhipple, {"rider_arms={inertia_kgm2: 0.15, stiffness_Nm_per_rad: 30, damping_Nms_per_rad: 3}"})));
}

TEST(ExtensionRegistry, NamesAreUniqueAcrossKinds) {
  PluginRegistry registry = plugins::makeBuiltinRegistry();
  auto make = [](io::YamlMap&, const plugins::VehicleLayout&) { return std::unique_ptr<plugins::ExtensionModel>(); };
  EXPECT_THROW(registry.addExtensionModel("steer_damper", make), std::runtime_error);
  EXPECT_THROW(registry.addExtensionModel("rolling_no_slip", make), std::runtime_error);
  const std::vector<std::string> names = registry.getExtensionModelNames();
  EXPECT_EQ(names.front(), "swingarm.suspension");  // registration order, the order of the stages
  EXPECT_EQ(names[1], "aerodynamics");
  // A section's fields are declared once.
  EXPECT_THROW(registry.addSectionFields({"steer_damper", {}}), std::runtime_error);
  EXPECT_EQ(names.back(), "steer_head_friction");
}

}  // namespace
}  // namespace motostab::extensions

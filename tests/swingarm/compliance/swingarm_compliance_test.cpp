// Swingarm compliance plugins on the enduro motorcycle (seed sec. 4).
#include <gtest/gtest.h>

#include <complex>

#include "tests/support/temp_dir.h"
#include "analysis/sweep.h"
#include "swingarm/compliance/swingarm_compliance.h"
#include "tests/support/analysis_chain.h"

namespace motostab::swingarm {

using namespace motostab::testing;
using io::YamlMap;
using io::loadYamlFile;
using scenario::InertiaSpec;
using scenario::SwingarmFrame;
using scenario::WheelSpec;
using scenario::calcSwingarmFrame;
using vehicle::CoordinateIndices;

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

// The weave eigenvalue (upper half plane) at v, found by tracking from a nearby labelled sweep.
std::complex<double> weaveAt(const std::vector<std::string>& overrides, double v) {
  const VehicleModel model(loadScenario(kEnduro, overrides));
  SweepOptions opt;
  opt.start = v - 2, opt.stop = v, opt.step = 1;
  const SweepResult s = runSweep(model, opt);
  for (const auto& b : s.branches)
    if (b.label == analysis::ModeLabel::Weave && b.eigenvalue.back().imag() > 0) return b.eigenvalue.back();
  ADD_FAILURE() << "no weave found";
  return 0;
}

TEST(SwingarmCompliance, InfiniteStiffnessConvergesToRigid) {
  const std::complex<double> rigid = weaveAt({"swingarm.compliance=rigid"}, 20.0);
  for (const char* model : {"torsion", "bending", "twist"}) {
    double previous = INFINITY;
    for (double scale : {1.0, 100.0, 10000.0}) {
      const auto w = weaveAt({std::string("swingarm.compliance=") + model,
                              "swingarm.stiffness_scale=" + std::to_string(scale)}, 20.0);
      const double err = std::abs(w - rigid);
      EXPECT_LT(err, previous) << model << " scale " << scale;
      previous = err;
    }
    EXPECT_LT(previous, 1e-4 * std::abs(rigid)) << model;
  }
}

// J about the compliance axis, from the scenario's mass properties alone: the swingarm and the
// rear wheel turn about the axis together (spin locked).
double calcInertiaAboutAxis(const Scenario& s, const ComplianceAxis& axis) {
  const SwingarmFrame f = calcSwingarmFrame(s);
  const SimTK::Mat33 R_DS(f.x[0], f.y[0], f.z[0], f.x[1], f.y[1], f.z[1], f.x[2], f.y[2], f.z[2]);
  const SimTK::Vec3 d = R_DS * axis.direction_S;
  const SimTK::Vec3 p = SimTK::Vec3(f.origin[0], f.origin[1], f.origin[2]) + R_DS * axis.point_S;
  auto about = [&](double m, const SimTK::Vec3& c, const SimTK::Mat33& I) {
    const SimTK::Vec3 r = c - p, rPerp = r - (~r * d) * d;
    return ~d * (I * d) + m * rPerp.normSqr();
  };
  const InertiaSpec& a = s.swingarm.body.inertia;
  const SimTK::Mat33 I_S(a.xx, a.xy, a.xz, a.xy, a.yy, a.yz, a.xz, a.yz, a.zz);
  const auto& com = s.swingarm.body.com;
  const SimTK::Vec3 origin(f.origin[0], f.origin[1], f.origin[2]);
  const double Jarm = about(s.swingarm.body.mass, origin + R_DS * SimTK::Vec3(com[0], com[1], com[2]), R_DS * I_S * ~R_DS);
  const WheelSpec& w = s.rearWheel;
  const SimTK::Mat33 Iw(w.diametralInertia, 0, 0, 0, w.axialInertia, 0, 0, 0, w.diametralInertia);
  return Jarm + about(w.mass, SimTK::Vec3(0, 0, w.radius), Iw);
}

TEST(SwingarmCompliance, LockedVehicleOscillatesAtSqrtKOverJ) {
  for (const char* model : {"bending", "torsion", "twist"}) {
    const Scenario s = loadScenario(kEnduro, {std::string("swingarm.compliance=") + model, "gravity_mps2=0"});
    const VehicleModel vm(s);
    ASSERT_EQ(vm.getIndices().compliance.size(), 1u);
    const int qc = vm.getIndices().compliance[0];
    // Lift the vehicle off the ground and lock every other mobilizer.
    SimTK::State st = vm.getDefaultState();
    st.updQ()[vm.getIndices().height] += 1.0;
    const SimTK::SimbodyMatterSubsystem& matter = vm.getMatter();
    for (SimTK::MobilizedBodyIndex b(1); b < matter.getNumBodies(); ++b) {
      const SimTK::MobilizedBody& mb = matter.getMobilizedBody(b);
      if (mb.getNumU(st) > 0 && mb.getFirstQIndex(st) != qc) mb.lock(st, SimTK::Motion::Position);
    }
    const double q0 = 1e-4;
    st.updQ()[qc] = q0;
    vm.getSystem().realize(st, SimTK::Stage::Acceleration);
    // J q'' = -k q with no damping force at rest.
    YamlMap axisMap = loadYamlFile(kEnduro).getMap("swingarm").getMap(model);
    const double k = axisMap.getDouble("stiffness_Nm_per_rad");
    const SwingarmFrame f = calcSwingarmFrame(s);
    const ComplianceAxis axis = makeAxisFromArm(SimTK::Vec3(f.length, 0, 0), axisMap.getDouble("arm_m"),
                                                axisMap.getDouble("beta_deg") * M_PI / 180, k, 0);
    const double J = calcInertiaAboutAxis(s, axis);
    const double omegaModel = std::sqrt(-st.getUDot()[qc] / q0);
    EXPECT_NEAR(omegaModel, std::sqrt(k / J), 1e-6 * std::sqrt(k / J)) << model;
    std::cout << model << ": J = " << J << " kg m^2, sqrt(k/J)/2pi = " << std::sqrt(k / J) / (2 * M_PI) << " Hz\n";
  }
}

TEST(SwingarmCompliance, CyclicColumnsAreZeroAndSymmetricTrimIsUpright) {
  const VehicleModel model(loadScenario(kEnduro, {"swingarm.compliance=bending+torsion"}));
  const TrimResult trim = calcTrim(model, 25.0);
  EXPECT_LT(trim.residualNorm, 1e-10);
  for (int q : model.getIndices().compliance) EXPECT_NEAR(trim.state.getQ()[q], 0, 1e-12);
  EXPECT_NEAR(trim.state.getQ()[model.getIndices().roll], 0, 1e-12);
  const LinearModel lin = linearize(model, trim);
  ASSERT_GE(lin.removedColumns.size(), 4u);
  for (const auto& [name, col] : lin.removedColumns) EXPECT_LT(col.lpNorm<Eigen::Infinity>(), 1e-8) << name;
}

// A compliance axis with a lateral tilt breaks the lateral symmetry: the trim needs small roll,
// steer and compliance deflections and a steer torque, and must still converge.
TEST(SwingarmCompliance, TiltedAxisTrimsWithSmallLateralStates) {
  const VehicleModel model(loadScenario(kEnduro, {"swingarm.compliance=torsion",
                                                  "swingarm.torsion={point_m: [0.56, 0, 0.014], direction: [1, 0.2, 0], "
                                                  "stiffness_Nm_per_rad: 55200, damping_Nms_per_rad: 0.49}"}));
  const TrimResult trim = calcTrim(model, 25.0);
  EXPECT_LT(trim.residualNorm, 1e-10);
  const CoordinateIndices& ix = model.getIndices();
  const double roll = trim.state.getQ()[ix.roll], twist = trim.state.getQ()[ix.compliance[0]];
  EXPECT_GT(std::abs(roll) + std::abs(twist), 1e-9);
  EXPECT_LT(std::abs(roll), 0.05);
  EXPECT_LT(std::abs(twist), 0.01);
}

}  // namespace
}  // namespace motostab::swingarm

#include <fstream>

#include "core/portable_random.h"
#include "io/number.h"
#include "plugins/builtin.h"
#include "swingarm/identification/decomposition.h"
#include "swingarm/identification/swingarm_uncertainty.h"

namespace motostab::swingarm {
namespace {

// The fragment `motostab identify swingarm` writes is accepted unchanged (axes_from) and builds the
// same model as the same values typed inline (seed Table 3 and 5, swingarm 2, with the enduro
// scenario's beta).
TEST(SwingarmCompliance, IdentificationFragmentIsUsedUnchanged) {
  swingarm::identification::SwingarmIdentification id;
  auto fill = [](swingarm::identification::LumpedModel& m, double arm, double betaDeg, double k, double c) {
    m.arm.value = arm, m.betaDeg.value = betaDeg, m.stiffness.value = k, m.damping.value = c;
    const double b = betaDeg * M_PI / 180;
    m.direction = Eigen::Vector2d(std::cos(b), std::sin(b));
    m.point = Eigen::Vector2d(0.5625 - arm * std::sin(b), arm * std::cos(b));
  };
  fill(id.bending, 0.388, 90.0, 94200, 2.25);
  fill(id.torsion, 0.014, 0.0, 55200, 0.49);
  fill(id.twist, 0.375, 86.48, 87600, 2.09);
  const auto file = makeTempDir("identified_swingarm") / "identified_swingarm.yaml";
  std::ofstream(file) << swingarm::identification::formatSwingarmYaml(id, "static.yaml", "frf.yaml", {0.5625, 0});
  for (const char* model : {"bending", "torsion", "twist"}) {
    const std::string sel = std::string("swingarm.compliance=") + model;
    const std::string axis = std::string("swingarm.") + model;
    const std::string values = model == std::string("bending") ? "{arm_m: 0.388, beta_deg: 90.0, stiffness_Nm_per_rad: 94200, damping_Nms_per_rad: 2.25}"
                               : model == std::string("torsion") ? "{arm_m: 0.014, beta_deg: 0.0, stiffness_Nm_per_rad: 55200, damping_Nms_per_rad: 0.49}"
                                                                 : "{arm_m: 0.375, beta_deg: 86.48, stiffness_Nm_per_rad: 87600, damping_Nms_per_rad: 2.09}";
    const VehicleModel inlineModel(loadScenario(kEnduro, {sel, axis + "=" + values}));
    // Remove the inline axes so that the fragment supplies them.
    YAML::Node tree = YAML::LoadFile(kEnduro);
    for (const char* k : {"bending", "torsion", "twist"}) tree["swingarm"].remove(k);
    tree["swingarm"]["axes_from"] = file.string();
    tree["swingarm"]["compliance"] = model;
    const auto scenarioFile = makeTempDir("enduro_from_fragment") / "enduro_from_fragment.yaml";
    std::ofstream(scenarioFile) << tree;
    const VehicleModel fromFragment(loadScenario(scenarioFile.string()));
    const LinearModel a = linearize(inlineModel, calcTrim(inlineModel, 20.0));
    const LinearModel b = linearize(fromFragment, calcTrim(fromFragment, 20.0));
    ASSERT_EQ(a.eigenvalues.size(), b.eigenvalues.size());
    for (int k = 0; k < a.eigenvalues.size(); ++k) {
      double best = INFINITY;
      for (int j = 0; j < b.eigenvalues.size(); ++j) best = std::min(best, std::abs(a.eigenvalues[k] - b.eigenvalues[j]));
      EXPECT_LT(best, 1e-6 * (1 + std::abs(a.eigenvalues[k]))) << model;
    }
  }
}


// The `axes_from` file is read once, when the scenario's sections are read at load: it may be deleted
// after that, and building the model (again, and on four sweep workers) still works and uses its axes.
// Without that read at load, the same scenario loaded after the deletion cannot be built.
TEST(SwingarmCompliance, AxesFileIsReadOnceAtLoad) {
  const auto dir = makeTempDir("axes_once");
  const auto axes = dir / "axes.yaml";
  std::ofstream(axes) << "bending: {arm_m: 0.388, beta_deg: 90.0, stiffness_Nm_per_rad: 94200, damping_Nms_per_rad: 2.25}\n";
  YAML::Node tree = YAML::LoadFile(kEnduro);
  for (const char* k : {"bending", "torsion", "twist"}) tree["swingarm"].remove(k);
  tree["swingarm"]["axes_from"] = "axes.yaml";  // relative to the scenario file
  tree["swingarm"]["compliance"] = "bending";
  const auto scenarioFile = dir / "enduro_axes.yaml";
  std::ofstream(scenarioFile) << tree;
  scenario::Scenario s = loadScenario(scenarioFile.string());
  plugins::makeBuiltinRegistry().readScenarioSections(s);
  EXPECT_EQ(s.inputs->getReadCount(axes.string()), 1);
  std::filesystem::remove(axes);
  const VehicleModel model(s);
  const auto& names = model.getQNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "swingarm_bending"), names.end());
  SweepOptions opt;
  opt.start = 10, opt.stop = 13, opt.step = 1, opt.threads = 4;
  const SweepResult sweep = runSweep(model, opt);
  EXPECT_EQ(sweep.speeds.size(), 4u);
  EXPECT_EQ(s.inputs->getReadCount(axes.string()), 1);
  const scenario::Scenario late = loadScenario(scenarioFile.string());
  EXPECT_THROW(VehicleModel{late}, io::InputError);
}

// The standard errors `motostab identify swingarm` writes as an `uncertainty:` section (drawn here) are
// keyed by declared number fields of the axis sections, and load beside the enduro's inline axes: each
// path names a number of the scenario.
TEST(SwingarmCompliance, IdentifiedUncertaintiesAreDeclaredAxisFields) {
  core::PortableRandom rng(20261129);
  swingarm::identification::SwingarmIdentification id;
  for (auto* m : {&id.bending, &id.torsion, &id.twist})
    for (auto* e : {&m->arm, &m->betaDeg, &m->stiffness, &m->damping}) e->stderr_ = rng.drawUniform(1e-3, 10);
  const YAML::Node written = YAML::Load(swingarm::identification::formatSwingarmUncertainty(id))["uncertainty"];
  ASSERT_TRUE(written.IsMap());
  EXPECT_EQ(written.size(), 12u);
  YAML::Node tree = YAML::LoadFile(kEnduro);
  tree["uncertainty"] = written;
  for (const auto& kv : written) {
    const std::string path = kv.first.as<std::string>();
    const size_t dot = path.rfind('.');
    const std::string section = path.substr(0, dot), key = path.substr(dot + 1);
    ASSERT_EQ(section.rfind("swingarm.", 0), 0u) << path;
    const io::Field& f = getSwingarmAxisFields(section.substr(9)).get(key);
    EXPECT_EQ(f.shape, io::Shape::Number) << path;
  }
  const scenario::Scenario s = scenario::readScenarioTree(tree, kEnduro, {});
  EXPECT_EQ(s.uncertainty.size(), 12u);
}

// A value the identification writes beside an axis is checked where it stands (at the top of the axis
// or nested under `axis`): a negative one, drawn, is an input error at its key path.
TEST(SwingarmCompliance, IdentificationValuesAreChecked) {
  core::PortableRandom rng(7);
  const std::string bad = io::formatShortest(-rng.drawUniform(0.01, 5));
  const std::string base = "arm_m: 0.388, beta_deg: 90, stiffness_Nm_per_rad: 94200, damping_Nms_per_rad: 2.25";
  const std::pair<std::string, std::string> cases[] = {
      {"{" + base + ", frequency_hz: " + bad + "}", "swingarm.bending.frequency_hz"},
      {"{stiffness_Nm_per_rad: 94200, damping_Nms_per_rad: 2.25, axis: {arm_m: 0.388, beta_deg: 90, arm_m_stderr: " + bad + "}}",
       "swingarm.bending.axis.arm_m_stderr"}};
  for (const auto& [value, key] : cases) {
    try {
      const VehicleModel model(loadScenario(kEnduro, {"swingarm.compliance=bending", "swingarm.bending=" + value}));
      ADD_FAILURE() << key << " accepted";
    } catch (const io::InputError& e) {
      EXPECT_EQ(e.getLocation().key, key) << e.what();
    }
  }
  // The axis nested and beside it at once is refused (the geometry is given once).
  try {
    const VehicleModel model(loadScenario(kEnduro, {"swingarm.compliance=bending", "swingarm.bending={" + base + ", axis: {arm_m: 0.3, beta_deg: 90}}"}));
    ADD_FAILURE() << "the axis given twice was accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.getLocation().key, "swingarm.bending.arm_m") << e.what();
    EXPECT_NE(e.getReason().find("unknown key"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace motostab::swingarm

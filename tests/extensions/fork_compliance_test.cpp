// Lateral fork compliance (extensions/fork_compliance.h, scenario `fork_compliance`): mass split keeps the
// totals, locked-vehicle frequencies sqrt(k/J) against hand calculations, the stiff limit, labels,
// --set and malformed input.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

#include "core/portable_random.h"
#include "extension_test_util.h"
#include "extensions/fork_compliance.h"
#include "plugins/plugin_registry.h"

namespace motostab::extensions {

using analysis::SweepResult;
using core::PortableRandom;
using scenario::InertiaSpec;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::VehicleModel;


namespace {

using namespace motostab::testing;

struct Fork {
  double k = 0, c = 0, distance = 0, fraction = 0, kt = 0, ct = 0;
  bool torsion = false;
};

// Stiffnesses around a motorcycle fork's (Sharp & Alstead 1980; Cossalter 2006 sec. 8.6: tens of
// kN m/rad in bending), drawn at random (seeded) with the axis point and the moving fraction.
Fork drawFork(PortableRandom& rng, bool torsion) {
  Fork f;
  f.k = rng.drawUniform(2e4, 6e4);
  f.c = rng.drawUniform(5, 30);
  f.distance = rng.drawUniform(0.6, 0.9);
  f.fraction = rng.drawUniform(0.2, 0.45);
  f.torsion = torsion;
  f.kt = rng.drawUniform(2e4, 6e4);
  f.ct = rng.drawUniform(5, 30);
  return f;
}

std::string toYaml(const Fork& f, double stiffnessScale = 1, double dampingScale = 1) {
  std::ostringstream o;
  o.precision(17);
  o << "fork_compliance={stiffness_Nm_per_rad: " << f.k * stiffnessScale << ", damping_Nms_per_rad: " << f.c * dampingScale
    << ", axis_distance_along_steer_m: " << f.distance << ", carrier_mass_fraction: " << f.fraction;
  if (f.torsion)
    o << ", torsion: {stiffness_Nm_per_rad: " << f.kt * stiffnessScale << ", damping_Nms_per_rad: " << f.ct * dampingScale << "}";
  o << "}";
  return o.str();
}

// Hand calculation from the scenario's numbers: hinge point P and axis n in the design frame.
struct Axis {
  Eigen::Vector3d p, n;
};
Axis calcBendingAxis(const Scenario& s, double distance) {
  const double l = s.geometry.steerAxisTilt;
  return {Eigen::Vector3d(s.geometry.wheelbase + s.geometry.trail - distance * std::sin(l), 0, distance * std::cos(l)),
          Eigen::Vector3d(std::cos(l), 0, std::sin(l))};
}

// Inertia about the axis of a body at `com` with central inertia `I` (tensor, design frame).
double calcAxisInertia(const Axis& a, double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& I) {
  const double d = (com - a.p).cross(a.n).norm();
  return a.n.dot(I * a.n) + mass * d * d;
}

Eigen::Matrix3d toMatrix(const InertiaSpec& I) {
  return (Eigen::Matrix3d() << I.xx, I.xy, I.xz, I.xy, I.yy, I.yz, I.xz, I.yz, I.zz).finished();
}

TEST(ForkCompliance, MassSplitKeepsTheTotals) {
  PortableRandom rng(11);
  for (const std::string& file : {kWhipple, kEnduro}) {
    const Scenario base = loadScenario(file);
    const Scenario fork = loadScenario(file, {toYaml(drawFork(rng, true))});
    ASSERT_NE(scenario::findExtension(fork, "fork_compliance"), nullptr);
    EXPECT_LT(calcTotalsDifference(calcVehicleTotals(base), calcVehicleTotals(fork), base.geometry.wheelbase), 1e-13) << file;
  }
}

// Everything else locked, no gravity: the carrier (by default the front frame scaled by the
// fraction) and the wheel swing about the bending axis,
// omega^2 = k / J; the torsion link (massless) turns the wheel alone about the steer-axis direction.
TEST(ForkCompliance, LockedVehicleFrequenciesAreSqrtKOverJ) {
  PortableRandom rng(22);
  for (int trial = 0; trial < 3; ++trial) {
    const Fork f = drawFork(rng, true);
    const Scenario s = loadScenario(kEnduro, {toYaml(f), "gravity_mps2=0"});
    const Axis bend = calcBendingAxis(s, f.distance);
    const Eigen::Vector3d hub(s.geometry.wheelbase, 0, s.frontWheel.radius);
    const double D = s.frontWheel.diametralInertia, A = s.frontWheel.axialInertia, mw = s.frontWheel.mass;
    const Eigen::Matrix3d Iw = Eigen::Vector3d(D, A, D).asDiagonal();
    const double Jb = calcAxisInertia(bend, mw, hub, Iw) +
                      calcAxisInertia(bend, f.fraction * s.frontFrame.mass, Eigen::Vector3d(s.frontFrame.com.data()),
                                      f.fraction * toMatrix(s.frontFrame.inertia));
    EXPECT_NEAR(std::sqrt(calcLockedOmegaSquared(s, "fork_bending")) / std::sqrt(f.k / Jb), 1.0, 1e-6);
    const Axis twist{bend.p, Eigen::Vector3d(-std::sin(s.geometry.steerAxisTilt), 0, std::cos(s.geometry.steerAxisTilt))};
    const double Jt = calcAxisInertia(twist, mw, hub, Iw);
    EXPECT_NEAR(std::sqrt(calcLockedOmegaSquared(s, "fork_torsion")) / std::sqrt(f.kt / Jt), 1.0, 1e-6);
  }
}

TEST(ForkCompliance, StiffForkReproducesTheRigidFork) {
  PortableRandom rng(33);
  expectWhippleSpectrumKept(loadScenario(kWhipple, {toYaml(drawFork(rng, true), 1e4, 1e2)}));

  expectEnduroWeaveAndWobbleKept({toYaml(drawFork(rng, true), 1e4, 1e2)});
}

// With a realistic fork the sweep still finds weave and wobble, and names the fork's own mode.
TEST(ForkCompliance, LabelsNameTheForkModeAndKeepWeaveAndWobble) {
  PortableRandom rng(44);
  const SweepResult r = runScenarioSweep(loadScenario(kEnduro, {toYaml(drawFork(rng, false))}), 5, 35, 1);
  std::set<std::string> labels;
  for (const auto& b : r.branches) labels.insert(analysis::toString(b.label));
  EXPECT_TRUE(labels.count("weave"));
  EXPECT_TRUE(labels.count("wobble"));
  EXPECT_TRUE(labels.count("fork_bending"));
}

TEST(ForkCompliance, DefaultsAndSet) {
  const Scenario s = loadScenario(kEnduro, {"fork_compliance={stiffness_Nm_per_rad: 40000, damping_Nms_per_rad: 10}",
                                            "fork_compliance.torsion={stiffness_Nm_per_rad: 50000, damping_Nms_per_rad: 5}"});
  io::YamlMap section = getExtensionSection(s, "fork_compliance");
  const ForkComplianceParams f = readForkCompliance(section, plugins::makeVehicleLayout(s));
  ASSERT_TRUE(f.hasTorsion);
  EXPECT_DOUBLE_EQ(f.torsion.stiffness, 50000);
  // Default axis point: the steer-axis point at the height of the tyre's top, 2 r_F.
  EXPECT_NEAR(f.axisDistance * std::cos(s.geometry.steerAxisTilt), 2 * s.frontWheel.radius, 1e-12);
  EXPECT_NEAR(f.carrier.mass, 0.3 * s.frontFrame.mass, 1e-12);
  EXPECT_NEAR(getModelBody(s, "fork_carrier").mass, 0.3 * s.frontFrame.mass, 1e-12);
  EXPECT_NEAR(getModelBody(s, "front_frame").mass, 0.7 * s.frontFrame.mass, 1e-12);
  const VehicleModel model(s);
  EXPECT_GE(findCoordinate(model, "fork_bending"), 0);
  EXPECT_GE(findCoordinate(model, "fork_torsion"), 0);
}

TEST(ForkCompliance, MalformedInputNamesFileLineColumnAndKey) {
  const std::string head = "fork_compliance:\n  stiffness_Nm_per_rad: 40000\n";
  expectBadInputs(kEnduro, "fork_bad",
                  {
                      {"fork_compliance:\n  damping_Nms_per_rad: 1\n  stiffness_Nm_per_rad: -4\n", 3,
                       "fork_compliance.stiffness_Nm_per_rad"},
                      {head + "  damping_Nms_per_rad: .nan\n", 3, "fork_compliance.damping_Nms_per_rad"},
                      {head + "  damping_Nms_per_rad: 1\n  axis_distance_along_steer_m: [0.7]\n", 3,
                       "fork_compliance.axis_distance_along_steer_m"},
                      {head + "  damping_Nms_per_rad: 1\n  carrier_mass_fraction: 1.5\n", 3, "fork_compliance.carrier_mass_fraction"},
                      {head + "  damping_Nms_per_rad: 1\n  carrier_mass_fraction: -0.2\n", 3, "fork_compliance.carrier_mass_fraction"},
                      {head + "  damping_Nms_per_rad: 1\n  carrier:\n    mass_kg: 5\n    com_m: [1.5, 0, 0.32]\n"
                              "    inertia_kgm2: {xx: 0.1, yy: 0.1, zz: 0.05, xy: 0, xz: 0, yz: 0}\n    colour: red\n",
                       5, "fork_compliance.carrier.colour"},
                      {head + "  damping_Nms_per_rad: 1\n  carrier: {mass_kg: 50, com_m: [1.5, 0, 0.32], "
                              "inertia_kgm2: {xx: 0.1, yy: 0.1, zz: 0.05, xy: 0, xz: 0, yz: 0}}\n",
                       3, "fork_compliance.carrier"},  // heavier than the 16 kg front frame
                      {head + "  damping_Nms_per_rad: 1\n  torsion:\n    damping_Nms_per_rad: 1\n    stiffness_Nm_per_rad: -1\n", 5,
                       "fork_compliance.torsion.stiffness_Nm_per_rad"},
                      {head + "  damping_Nms_per_rad: 1\n  torsion:\n    stiffness_Nm_per_rad: 1\n    damping_Nms_per_rad: 1\n    axis: y\n", 5,
                       "fork_compliance.torsion.axis"},
                      {head + "  damping_Nms_per_rad: 1\n  bending_axis: x\n", 3, "fork_compliance.bending_axis"},
                      {head + "  damping_Nms_per_rad: 1\n  carrier: {mass_kg: 1}\n  carrier_mass_fraction: 0.2\n", 3,
                       "fork_compliance.carrier_mass_fraction"},
                  });
}

}  // namespace
}  // namespace motostab::extensions

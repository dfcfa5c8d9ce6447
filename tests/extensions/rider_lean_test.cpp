// Passive rider lean (extensions/rider_lean.h, scenario `rider_lean`): totals kept, the locked-vehicle
// frequency sqrt(k/J) against a hand calculation, the stiff limit, --set and malformed input.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/portable_random.h"
#include "extension_test_util.h"
#include "extensions/rider_lean.h"
#include "plugins/plugin_registry.h"

namespace motostab::extensions {

using core::PortableRandom;
using scenario::BodySpec;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::VehicleModel;


namespace {

using namespace motostab::testing;

// A rider upper body drawn at random (seeded): 20-30 kg with its CoM 0.15-0.25 m above the rear
// frame's and 0.2-0.3 m above the hinge, inertia of a trunk-sized body (Winter 2009, Table 4.1:
// head-arms-trunk radius of gyration about 0.5 of its 0.5 m length). Small enough that the rest of the
// Meijaard (2007) rear frame (85 kg, I_xx 9.2 kg m^2) stays a valid body.
RiderLeanParams drawRider(PortableRandom& rng, const BodySpec& rearFrame) {
  RiderLeanParams r;
  r.body.mass = rng.drawUniform(20, 30);
  r.body.com = {rearFrame.com[0] + rng.drawUniform(-0.05, 0.05), 0, rearFrame.com[2] + rng.drawUniform(0.15, 0.25)};
  r.hingeHeight = r.body.com[2] - rng.drawUniform(0.2, 0.3);
  const double xx = rng.drawUniform(1.0, 1.5);
  r.body.inertia = {xx, xx * rng.drawUniform(1.0, 1.1), rng.drawUniform(0.3, 0.5), 0, rng.drawUniform(-0.1, 0.1), 0};
  r.stiffness = rng.drawUniform(800, 2000);
  r.damping = rng.drawUniform(20, 80);
  return r;
}

std::string toYaml(const RiderLeanParams& r, double stiffnessScale = 1, double dampingScale = 1) {
  std::ostringstream o;
  o.precision(17);
  const auto& I = r.body.inertia;
  o << "rider_lean={hinge_height_m: " << r.hingeHeight << ", mass_kg: " << r.body.mass << ", com_m: [" << r.body.com[0]
    << ", " << r.body.com[1] << ", " << r.body.com[2] << "], inertia_kgm2: {xx: " << I.xx << ", yy: " << I.yy
    << ", zz: " << I.zz << ", xy: " << I.xy << ", xz: " << I.xz << ", yz: " << I.yz
    << "}, stiffness_Nm_per_rad: " << r.stiffness * stiffnessScale
    << ", damping_Nms_per_rad: " << r.damping * dampingScale << "}";
  return o.str();
}

TEST(RiderLean, WholeVehicleTotalsAreKept) {
  PortableRandom rng(1010);
  for (const std::string& file : {kWhipple, kEnduro}) {
    const Scenario base = loadScenario(file);
    const RiderLeanParams r = drawRider(rng, base.rearFrame);
    const Scenario lean = loadScenario(file, {toYaml(r)});
    ASSERT_NE(scenario::findExtension(lean, "rider_lean"), nullptr);
    EXPECT_LT(calcTotalsDifference(calcVehicleTotals(base), calcVehicleTotals(lean), base.geometry.wheelbase), 1e-13) << file;
  }
}

// With everything else locked and no gravity the upper body swings about the hinge axis (design x
// through (0, 0, h)): omega^2 = k / J, J = I_xx + m ((z_G - h)^2 + y_G^2) (parallel axes).
TEST(RiderLean, LockedVehicleFrequencyIsSqrtKOverJ) {
  PortableRandom rng(2020);
  for (int trial = 0; trial < 3; ++trial) {
    const RiderLeanParams r = drawRider(rng, loadScenario(kEnduro).rearFrame);
    const Scenario s = loadScenario(kEnduro, {toYaml(r), "gravity_mps2=0"});
    const double dz = r.body.com[2] - r.hingeHeight;
    const double J = r.body.inertia.xx + r.body.mass * dz * dz;
    const double omega = std::sqrt(calcLockedOmegaSquared(s, "rider_lean"));
    EXPECT_NEAR(omega / std::sqrt(r.stiffness / J), 1.0, 1e-6);
  }
}

TEST(RiderLean, StiffRiderReproducesTheRigidRider) {
  PortableRandom rng(3030);
  expectWhippleSpectrumKept(loadScenario(kWhipple, {toYaml(drawRider(rng, loadScenario(kWhipple).rearFrame), 1e4, 1e2)}));

  expectEnduroWeaveAndWobbleKept({toYaml(drawRider(rng, loadScenario(kEnduro).rearFrame), 1e4, 1e2)});
}

TEST(RiderLean, SetCreatesTheSectionAndEditsIt) {
  PortableRandom rng(4040);
  const RiderLeanParams r = drawRider(rng, loadScenario(kWhipple).rearFrame);
  const Scenario s = loadScenario(kWhipple, {toYaml(r), "rider_lean.stiffness_Nm_per_rad=1234"});
  io::YamlMap section = getExtensionSection(s, "rider_lean");
  const RiderLeanParams read = readRiderLean(section, plugins::makeVehicleLayout(s));
  EXPECT_DOUBLE_EQ(read.stiffness, 1234);
  EXPECT_DOUBLE_EQ(read.body.mass, r.body.mass);
  const VehicleModel model(s);
  EXPECT_GE(findCoordinate(model, "rider_lean"), 0);
  EXPECT_EQ(model.getIndices().extension.size(), 1u);
}

TEST(RiderLean, MalformedInputNamesFileLineColumnAndKey) {
  const std::string ok = "  hinge_height_m: 0.85\n  mass_kg: 25\n  com_m: [0.3, 0, 1.1]\n"
                         "  inertia_kgm2: {xx: 1.2, yy: 1.3, zz: 0.4, xy: 0, xz: 0, yz: 0}\n"
                         "  stiffness_Nm_per_rad: 1000\n";
  const std::string head = "rider_lean:\n";
  expectBadInputs(kWhipple, "rider_lean_bad",
                  {
                      {head + ok + "  damping_Nms_per_rad: -1\n", 3, "rider_lean.damping_Nms_per_rad"},
                      {head + ok + "  damping_Nms_per_rad: .nan\n", 3, "rider_lean.damping_Nms_per_rad"},
                      {head + ok + "  damping_Nms_per_rad: 1\n  lean_axis: x\n", 3, "rider_lean.lean_axis"},
                      {head + "  damping_Nms_per_rad: 1\n" + ok + "  stiffness: 5\n", 3, "rider_lean.stiffness"},
                      {"rider_lean:\n  damping_Nms_per_rad: 1\n  mass_kg: 25\n  com_m: [0.3, 0, 1.1]\n"
                       "  inertia_kgm2: {xx: 1.2, yy: 1.3, zz: 0.4, xy: 0, xz: 0, yz: 0}\n  stiffness_Nm_per_rad: 1000\n"
                       "  hinge_height_m: -0.9\n", 3, "rider_lean.hinge_height_m"},
                      {"rider_lean:\n  damping_Nms_per_rad: 1\n  hinge_height_m: 0.85\n  com_m: [0.3, 0, 1.1]\n"
                       "  inertia_kgm2: {xx: 1.2, yy: 1.3, zz: 0.4, xy: 0, xz: 0, yz: 0}\n  stiffness_Nm_per_rad: 1000\n"
                       "  mass_kg: 90\n", 3, "rider_lean.mass_kg"},  // more than the rear frame's 85 kg
                      {"rider_lean:\n  damping_Nms_per_rad: 1\n  hinge_height_m: 0.85\n  mass_kg: 25\n"
                       "  inertia_kgm2: {xx: 1.2, yy: 1.3, zz: 0.4, xy: 0, xz: 0, yz: 0}\n  stiffness_Nm_per_rad: 1000\n"
                       "  com_m: [0.3, 0.1, 1.1]\n", 3, "rider_lean.com_m"},
                      {"rider_lean:\n  damping_Nms_per_rad: 1\n  hinge_height_m: 0.85\n  mass_kg: 25\n"
                       "  inertia_kgm2: {xx: 1.2, yy: 1.3, zz: 0.4, xy: 0, xz: 0, yz: 0}\n  stiffness_Nm_per_rad: 1000\n"
                       "  com_m: high\n", 3, "rider_lean.com_m"},
                      {"rider_lean:\n  damping_Nms_per_rad: 1\n  hinge_height_m: 0.85\n  mass_kg: 25\n"
                       "  com_m: [0.3, 0, 1.1]\n  inertia_kgm2: {xx: 1.2, yy: 1.3, zz: 0.4, xy: 0, xz: 0, yz: 0}\n"
                       "  stiffness_Nm_per_rad: -1000\n", 3, "rider_lean.stiffness_Nm_per_rad"},
                  });
}

}  // namespace
}  // namespace motostab::extensions

// Plausibility warnings: each check fires on the unit slips and swaps it is for (values drawn at random,
// seeded, outside its documented range), at the key's file:line:col, and stays quiet inside the range and
// on every bundled scenario.
#include <gtest/gtest.h>

#include "tests/support/text_file.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <fstream>
#include <sstream>

#include "core/portable_random.h"
#include "scenario/plausibility.h"
#include "scenario/scenario.h"
#include "tests/support/temp_dir.h"

namespace motostab::scenario {

using Check = ScenarioWarning::Check;
using core::PortableRandom;

namespace {

const std::string kDir = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/";

// `base` with the first `from` replaced by `to`, loaded; `line` receives the line holding `to`.
Scenario loadVariant(const std::string& base, const std::string& from, const std::string& to, int& line) {
  std::string text = readText(kDir + base);
  const size_t pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  text.replace(pos, from.size(), to);
  line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
  static int n = 0;
  const auto p = makeTempDir("plausibility") / ("variant" + std::to_string(++n) + ".yaml");
  std::ofstream(p) << text;
  return loadScenario(p.string());
}

// The warnings of check `c` in `s`.
std::vector<ScenarioWarning> find(const Scenario& s, Check c) {
  std::vector<ScenarioWarning> out;
  for (const auto& w : s.warnings)
    if (w.check == c) out.push_back(w);
  return out;
}

std::string num(double v) {
  std::ostringstream os;
  os << std::setprecision(10) << v;
  return os.str();
}

}  // namespace

TEST(Plausibility, BundledScenariosHaveNoWarnings) {
  for (const char* f : {"whipple-benchmark", "whipple-benchmark-tyres", "kooijman-silvercity", "browser-jason-rider",
                        "balance-assist", "supersport", "supersport-mf", "enduro"}) {
    const Scenario s = loadScenario(kDir + f + ".yaml");
    for (const auto& w : s.warnings) ADD_FAILURE() << f << ": " << formatWarning(w);
  }
}

// The issue's own slips: a tilt in radians, the head angle for the caster, a wheelbase in millimetres.
TEST(Plausibility, UnitSlipsOfTheGeometryAreNamedAtTheirKey) {
  PortableRandom rng(7);
  for (int k = 0; k < 5; ++k) {
    int line = 0;
    const double radians = rng.drawUniform(0.25, 0.5), head = rng.drawUniform(60, 75), mm = rng.drawUniform(1000, 1600);
    for (const double tilt : {radians, head}) {
      const Scenario s = loadVariant("supersport.yaml", "steer_axis_tilt_deg: 23.7", "steer_axis_tilt_deg: " + num(tilt), line);
      const auto w = find(s, Check::SteerAxisTilt);
      ASSERT_EQ(w.size(), 1u) << tilt;
      EXPECT_EQ(w[0].where.line, line);
      EXPECT_EQ(w[0].where.column, 3);
      EXPECT_EQ(w[0].where.key, "geometry.steer_axis_tilt_deg");
    }
    const Scenario s = loadVariant("whipple-benchmark.yaml", "wheelbase_m: 1.02", "wheelbase_m: " + num(mm), line);
    ASSERT_EQ(find(s, Check::Wheelbase).size(), 1u);
    EXPECT_EQ(find(s, Check::Wheelbase)[0].where.line, line);
    // Inside the ranges: quiet.
    const double fine = rng.drawUniform(15, 35);
    EXPECT_TRUE(loadVariant("supersport.yaml", "steer_axis_tilt_deg: 23.7", "steer_axis_tilt_deg: " + num(fine), line).warnings.empty());
  }
}

// Linear tyres: signs against tyres/relaxation_linear.h and a cornering stiffness per unit load of 2-40 /rad.
TEST(Plausibility, TyreCoefficientsAgainstTheConvention) {
  PortableRandom rng(11);
  int line = 0;
  const double camber = -rng.drawUniform(0.5, 2), aligning = rng.drawUniform(0.1, 0.5), perDegree = rng.drawUniform(0.1, 0.3);
  Scenario s = loadVariant("supersport.yaml", "camber_stiffness_per_rad: 1.24", "camber_stiffness_per_rad: " + num(camber), line);
  ASSERT_EQ(find(s, Check::TyreSign).size(), 1u);
  EXPECT_EQ(find(s, Check::TyreSign)[0].where.key, "contact.front.camber_stiffness_per_rad");
  EXPECT_EQ(find(s, Check::TyreSign)[0].where.line, line);
  s = loadVariant("supersport.yaml", "self_aligning_stiffness_m_per_rad: -0.47", "self_aligning_stiffness_m_per_rad: " + num(aligning), line);
  ASSERT_EQ(find(s, Check::TyreSign).size(), 1u);
  EXPECT_EQ(find(s, Check::TyreSign)[0].where.key, "contact.rear.self_aligning_stiffness_m_per_rad");
  s = loadVariant("supersport.yaml", "cornering_stiffness_per_rad: 12.3", "cornering_stiffness_per_rad: " + num(perDegree), line);
  ASSERT_EQ(find(s, Check::CorneringStiffness).size(), 1u);
  s = loadVariant("supersport.yaml", "cornering_stiffness_per_rad: 12.3", "cornering_stiffness_per_rad: " + num(perDegree * 180 / M_PI * 30), line);
  EXPECT_EQ(find(s, Check::CorneringStiffness).size(), 1u);  // per load not divided out
  // A lateral carcass stiffness in N/mm (Sharp et al. 2004: about 100 N/mm) gives sigma = Fz k_alpha / k_y
  // of tens of metres at the static load; in N/m, 0.1-0.2 m.
  const double kyPerMm = rng.drawUniform(60, 200);
  s = loadVariant("supersport.yaml", "relaxation_length_m: 0.122", "lateral_carcass_stiffness_N_per_m: " + num(kyPerMm), line);
  ASSERT_EQ(find(s, Check::RelaxationLength).size(), 1u);
  EXPECT_EQ(find(s, Check::RelaxationLength)[0].where.key, "contact.rear.lateral_carcass_stiffness_N_per_m");
  EXPECT_EQ(find(s, Check::RelaxationLength)[0].where.line, line);
  s = loadVariant("supersport.yaml", "relaxation_length_m: 0.122", "lateral_carcass_stiffness_N_per_m: " + num(kyPerMm * 1000), line);
  EXPECT_EQ(find(s, Check::RelaxationLength).size(), 0u);
}

// Mass properties: kg cm^2 for kg m^2, pitch below roll, a wheel spinning about a diameter, a CoM ahead of
// the front contact.
TEST(Plausibility, MassPropertySlipsAndSwaps) {
  int line = 0;
  Scenario s = loadVariant("supersport.yaml", "{xx: 26.7, yy: 51.0, zz: 28.1,", "{xx: 267000, yy: 510000, zz: 281000,", line);
  EXPECT_EQ(find(s, Check::RadiusOfGyration).size(), 1u);
  // A rear frame spread widest sideways (second moments x 1.5, y 20.5, z 9.5 kg m^2): roll above pitch.
  s = loadVariant("whipple-benchmark.yaml", "{xx: 9.2, yy: 11, zz: 2.8, xy: 0, xz: -2.4, yz: 0}",
                  "{xx: 30, yy: 11, zz: 22, xy: 0, xz: 0, yz: 0}", line);
  EXPECT_EQ(find(s, Check::InertiaOrder).size(), 1u);
  s = loadVariant("whipple-benchmark.yaml", "spin_inertia_kgm2: 0.12\n  diametral_inertia_kgm2: 0.0603",
                  "spin_inertia_kgm2: 0.0603\n  diametral_inertia_kgm2: 0.12", line);
  ASSERT_EQ(find(s, Check::WheelInertia).size(), 1u);
  EXPECT_EQ(find(s, Check::WheelInertia)[0].where.key, "rear_wheel.spin_inertia_kgm2");
  s = loadVariant("whipple-benchmark.yaml", "com_m: [0.3, 0, 0.9]", "com_m: [-3, 0, 0.9]", line);
  ASSERT_EQ(find(s, Check::CentreOfMass).size(), 1u);
  EXPECT_EQ(find(s, Check::CentreOfMass)[0].where.key, "rear_frame.com_m");
  s = loadVariant("whipple-benchmark.yaml", "gravity_mps2: 9.81", "gravity_mps2: 32.2", line);
  EXPECT_EQ(find(s, Check::Gravity).size(), 1u);
}

}  // namespace motostab::scenario

// The scenario's `uncertainty:` section: strict reading (unknown path, negative sigma, bad
// distribution at file:line:col), paths into plugin sections, and the sigmas imported from a
// BicycleParameters file (Moore et al. 2010).
#include <gtest/gtest.h>

#include "tests/support/text_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "tests/support/temp_dir.h"
#include "core/portable_random.h"
#include "scenario/bicycle_parameters.h"
#include "scenario/bicycle_parameters_uncertainty.h"
#include "scenario/scenario.h"

namespace motostab::scenario {

using core::PortableRandom;
using io::InputError;

namespace {

// The bundled scenario with `section` appended; the section starts at line (returned .second).
std::pair<std::string, int> writeWith(const std::string& bundled, const std::string& section, const std::string& tag) {
  const std::string base = readText(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/" + bundled) + "\n";
  const auto file = makeTempDir("uqsec") / ("motostab-uqsec-" + tag + ".yaml");
  std::ofstream(file) << base << section;
  const int lines = static_cast<int>(std::count(base.begin(), base.end(), '\n'));
  return {file.string(), lines + 1};
}

TEST(UncertaintySection, ReadsSigmasDistributionsAndAnyNumericPath) {
  PortableRandom g(31);
  const double s1 = 1e-3 * static_cast<double>(1 + g.drawBits() % 9), s2 = static_cast<double>(100 + g.drawBits() % 2000);
  std::ostringstream sec;
  sec.precision(17);
  sec << "uncertainty:\n  geometry.normal_trail_m: " << s1 << "\n  total.com_m[2]: {sigma: 0.01, distribution: uniform}\n"
      << "  swingarm.torsion.stiffness_Nm_per_rad: {sigma: " << s2 << ", distribution: lognormal}\n";
  const auto [file, line] = writeWith("enduro.yaml", sec.str(), "good");
  const Scenario s = loadScenario(file);
  ASSERT_EQ(s.uncertainty.size(), 3u);
  EXPECT_EQ(s.uncertainty[0].path, "geometry.normal_trail_m");
  EXPECT_EQ(s.uncertainty[0].sigma, s1);
  EXPECT_EQ(s.uncertainty[0].distribution, ParameterUncertainty::Distribution::Normal);
  EXPECT_EQ(s.uncertainty[0].where.line, line + 1);
  EXPECT_EQ(s.uncertainty[1].path, "total.com_m[2]");
  EXPECT_EQ(s.uncertainty[1].distribution, ParameterUncertainty::Distribution::Uniform);
  EXPECT_EQ(s.uncertainty[2].sigma, s2);
  EXPECT_EQ(s.uncertainty[2].distribution, ParameterUncertainty::Distribution::Lognormal);
}

void expectError(const std::string& section, int lineOffset, const std::string& key, const std::string& fragment) {
  const auto [file, line] = writeWith("whipple-benchmark.yaml", section, "bad");
  try {
    loadScenario(file);
    ADD_FAILURE() << "accepted: " << section;
  } catch (const InputError& e) {
    EXPECT_EQ(e.getLocation().file, file);
    EXPECT_EQ(e.getLocation().line, line + lineOffset) << e.what();
    EXPECT_GT(e.getLocation().column, 0);
    EXPECT_EQ(e.getLocation().key, key) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(UncertaintySection, RejectsBadEntriesAtTheirLocation) {
  expectError("uncertainty:\n  geometry.trail_m: 0.001\n  geometry.rake_m: 0.01\n", 2, "uncertainty.geometry.rake_m", "not a numeric parameter");
  expectError("uncertainty:\n  rear_frame.com_m[7]: 0.01\n", 1, "uncertainty.rear_frame.com_m[7]", "not a numeric parameter");
  expectError("uncertainty:\n  name: 0.01\n", 1, "uncertainty.name", "not a numeric parameter");
  expectError("uncertainty:\n  rear_frame.mass_kg: -0.5\n", 1, "uncertainty.rear_frame.mass_kg", "must not be negative");
  expectError("uncertainty:\n  rear_frame.mass_kg: {sigma: -2}\n", 1, "uncertainty.rear_frame.mass_kg.sigma", "must not be negative");
  expectError("uncertainty:\n  rear_frame.mass_kg: {sigma: 2, distribution: weibull}\n", 1,
              "uncertainty.rear_frame.mass_kg.distribution", "expected normal, uniform or lognormal");
  expectError("uncertainty:\n  rear_frame.mass_kg: {sigma: 2, shape: 3}\n", 1, "uncertainty.rear_frame.mass_kg.shape", "unknown key");
  expectError("uncertainty:\n  rear_frame.mass_kg: lots\n", 1, "uncertainty.rear_frame.mass_kg", "expected a finite number");
}

TEST(UncertaintySection, ImportedBicycleParametersSigmasReachTheSection) {
  // Crescendo (Moore 2010 data): every one of its 26 parameters states a sigma; v has no scenario key.
  const std::string src = std::string(MOTOSTAB_TEST_DATA_DIR) +
                          "/measured-data/BicycleParameters/data/bicycles/Crescendo/Parameters/CrescendoBenchmark.txt";
  // The test's own reading of the file: name -> sigma after "+/-".
  std::map<std::string, double> own;
  std::ifstream in(src);
  for (std::string l; std::getline(in, l);) {
    const auto eq = l.find('='), pm = l.find("+/-");
    if (eq == std::string::npos || pm == std::string::npos) continue;
    std::string k = l.substr(0, eq);
    k.erase(k.find_last_not_of(" \t") + 1);
    own[k] = std::stod(l.substr(pm + 3));
  }
  size_t nonzero = 0;
  for (const auto& [k, v] : own) nonzero += v > 0 && k != "v" ? 1 : 0;
  const auto out = makeTempDir("uqsec-crescendo") / "uqsec-crescendo.yaml";
  std::ofstream(out) << convertBicycleParametersToScenario(src, "crescendo")
                     << formatBicycleParametersUncertainty(readBicycleParameterSigmas(src));
  const Scenario s = loadScenario(out.string());
  ASSERT_EQ(s.uncertainty.size(), nonzero);
  std::map<std::string, double> got;
  for (const auto& u : s.uncertainty) got[u.path] = u.sigma;
  EXPECT_NEAR(got.at("geometry.trail_m"), own.at("c"), 1e-15);
  EXPECT_NEAR(got.at("geometry.steer_axis_tilt_deg"), own.at("lam") * 180 / M_PI, 1e-12);
  EXPECT_NEAR(got.at("rear_frame.mass_kg"), own.at("mB"), 1e-15);
  EXPECT_NEAR(got.at("rear_frame.com_m[2]"), own.at("zB"), 1e-15);
  EXPECT_NEAR(got.at("front_frame.inertia_kgm2.xz"), own.at("IHxz"), 1e-15);
  EXPECT_NEAR(got.at("front_wheel.spin_inertia_kgm2"), own.at("IFyy"), 1e-15);
  EXPECT_NEAR(got.at("rear_wheel.diametral_inertia_kgm2"), own.at("IRxx"), 1e-15);
}

}  // namespace
}  // namespace motostab::scenario

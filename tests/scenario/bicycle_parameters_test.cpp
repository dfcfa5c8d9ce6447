// BicycleParameters import: impossible measured inertias explained and repaired, and
// scenario names that YAML would read as null, numbers or booleans written quoted (item 5). Browser's rear
// frame has I_yy > I_xx + I_zz (lowered onto it); the Yellow front frames have their largest moment about
// an axis near x, exceeding I_yy + the smallest (I_yy raised onto |l_1 - l_2|).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/catch_input_error.h"
#include "tests/support/temp_dir.h"
#include "tests/apps/cli_support.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "scenario/bicycle_parameters.h"
#include "scenario/scenario.h"

namespace motostab::scenario {

using io::InputError;
using io::writeFileAtomically;

namespace {

const std::string kBicycles = std::string(MOTOSTAB_TEST_DATA_DIR) + "/measured-data/BicycleParameters/data/bicycles/";

std::string getParameterFile(const std::string& bike) { return kBicycles + bike + "/Parameters/" + bike + "Benchmark.txt"; }

// Largest principal moment minus the other two of a symmetric x-z inertia, computed here in closed form:
// the y moment is principal; the x-z block has moments m +/- r with m = (xx + zz)/2, r = hypot((xx - zz)/2, xz).
double calcExcess(double xx, double yy, double zz, double xz) {
  const double m = 0.5 * (xx + zz), r = std::hypot(0.5 * (xx - zz), xz);
  const double l[3] = {m - r, m + r, yy};
  const double big = std::max({l[0], l[1], l[2]});
  return 2 * big - (l[0] + l[1] + l[2]);
}

struct Case {
  const char* bike;
  const char* key;  // the frame inertia that breaks the inequality (Browser rear, Yellow(rev) front)
  char brokenAxis;  // the principal moment that exceeds the other two is about this axis (closed form above)
};
const Case kCases[] = {{"Browser", "IByy", 'y'}, {"Yellow", "IHyy", 'x'}, {"Yellowrev", "IHyy", 'x'}};

TEST(BicycleParameters, ImpossibleInertiaIsExplainedWithTheExcess) {
  for (const auto& c : kCases) {
    const auto p = readBicycleParameters(getParameterFile(c.bike));
    const std::string s(1, c.key[1]);
    const double excess = calcExcess(p.at("I" + s + "xx"), p.at("I" + s + "yy"), p.at("I" + s + "zz"), p.at("I" + s + "xz"));
    ASSERT_GT(excess, 0) << c.bike;
    try {
      convertBicycleParametersToScenario(getParameterFile(c.bike), "x");
      ADD_FAILURE() << c.bike << ": accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.getLocation().key, c.key);
      EXPECT_NE(what.find("triangle inequality"), std::string::npos) << what;
      EXPECT_NE(what.find(std::string("of ") + c.brokenAxis), std::string::npos) << what;
      char by[32];
      std::snprintf(by, sizeof by, "by %.4g kg m^2", excess);
      EXPECT_NE(what.find(by), std::string::npos) << what << " (expected '" << by << "')";
      EXPECT_NE(what.find("--repair-inertia"), std::string::npos) << what;
    }
  }
}

// A frame inertia with a principal moment <= 0 (IBxx = 0.5, IBzz = 2.8, IBxz = 2.4: the x-z block's
// smaller moment m - r = 1.65 - 2.65 = -1.01, computed here) is not positive definite: said at IBxx's
// line, with or without --repair-inertia, and never offered the repair (it was reported as a
// triangle-inequality problem that --repair-inertia would fix).
TEST(BicycleParameters, InertiaNotPositiveDefiniteIsSaidAtItsLine) {
  const auto dir = makeTempDir("bp_not_pd");
  std::ifstream in(getParameterFile("Benchmark"));
  std::stringstream text;
  text << in.rdbuf();
  std::string t = text.str();
  const std::vector<std::pair<std::string, std::string>> edits{{"IBxx", "0.5"}, {"IByy", "11.0"}, {"IBzz", "2.8"}, {"IBxz", "2.4"}};
  int line = 0;
  for (const auto& [key, value] : edits) {
    const size_t at = t.find("\n" + key + " ") + 1;
    ASSERT_GT(at, 0u) << key;
    t.replace(at, t.find('\n', at) - at, key + " = " + value);
    if (key == "IBxx") line = static_cast<int>(std::count(t.begin(), t.begin() + at, '\n')) + 1;
  }
  const std::string file = (dir / "notpd.txt").string();
  writeFileAtomically(file, t);
  const double m = 0.5 * (0.5 + 2.8), r = std::hypot(0.5 * (0.5 - 2.8), 2.4);
  ASSERT_LT(m - r, 0);
  for (const bool repair : {false, true}) {
    const InputError e = test::catchInputError([&] { convertBicycleParametersToScenario(file, "x", {repair}); });
    EXPECT_EQ(e.getLocation().key, "IBxx") << e.what();
    EXPECT_EQ(e.getLocation().line, line) << e.what();
    EXPECT_NE(e.getReason().find("not positive definite"), std::string::npos) << e.what();
    EXPECT_EQ(e.getReason().find("--repair-inertia"), std::string::npos) << e.what();
    char moment[32];
    std::snprintf(moment, sizeof moment, "%.6g", m - r);
    EXPECT_NE(e.getReason().find(moment), std::string::npos) << e.what() << " (expected " << moment << ")";
  }
}

TEST(BicycleParameters, RepairMovesYyExactlyOntoTheBound) {
  for (const auto& c : kCases) {
    const auto original = readBicycleParameters(getParameterFile(c.bike));
    std::vector<InertiaRepair> repairs;
    const std::string text = convertBicycleParametersToScenario(getParameterFile(c.bike), "r", {true}, &repairs);
    ASSERT_EQ(repairs.size(), 1u) << c.bike;
    const std::string s(1, c.key[1]);
    const double xx = original.at("I" + s + "xx"), zz = original.at("I" + s + "zz"), xz = original.at("I" + s + "xz");
    EXPECT_EQ(repairs[0].key, c.key);
    EXPECT_EQ(repairs[0].before, original.at(c.key));
    // Just onto the violated bound: I_yy <= I_xx + I_zz (Browser) or I_yy >= l_1 - l_2 = 2 hypot((xx - zz)/2, xz).
    const double bound = c.brokenAxis == 'y' ? xx + zz : 2 * std::hypot(0.5 * (xx - zz), xz);
    EXPECT_NEAR(repairs[0].after, bound, 1e-15 * bound);
    EXPECT_NEAR(calcExcess(xx, repairs[0].after, zz, xz), 0.0, 1e-14);
    const std::string verb = c.brokenAxis == 'y' ? " lowered" : " raised";
    EXPECT_NE(text.find("# --repair-inertia: " + std::string(c.key) + verb), std::string::npos) << text;
    const auto tmp = makeTempDir("repair") / ("motostab_repair_" + std::string(c.bike) + ".yaml");
    writeFileAtomically(tmp, text);
    EXPECT_NO_THROW(loadScenario(tmp.string())) << c.bike;
  }
}

TEST(BicycleParameters, ValidFilesAreNotTouched) {
  std::vector<InertiaRepair> repairs;
  const std::string a = convertBicycleParametersToScenario(getParameterFile("Benchmark"), "b", {true}, &repairs);
  EXPECT_TRUE(repairs.empty());
  EXPECT_EQ(a, convertBicycleParametersToScenario(getParameterFile("Benchmark"), "b"));
}

TEST(BicycleParameters, NamesThatYamlWouldRetypeStayStrings) {
  for (const std::string name : {"null", "1", "true", "~", "1e3", "no", "a: b", "say \"hi\"", "back\\slash"}) {
    const auto tmp = makeTempDir("import_name") / "import_name.yaml";
    writeFileAtomically(tmp, convertBicycleParametersToScenario(getParameterFile("Benchmark"), name));
    EXPECT_EQ(loadScenario(tmp.string()).name, name);
  }
}

// Through the command line: the default name is the output file's stem, and it must stay a string.
TEST(BicycleParameters, ImportCommandToNullOneAndTrueYaml) {
  const auto dir = makeTempDir("import_cli");
  std::filesystem::create_directories(dir);
  std::string output;
  for (const std::string stem : {"null", "1", "true"}) {
    const auto out = dir / (stem + ".yaml");
    const int code = motostab::test::runMotostab(
        {"import", getParameterFile("Benchmark"), "--format", "bicycleparameters", "--out", out.string()}, dir.string(), output);
    ASSERT_EQ(code, 0) << output;
    EXPECT_EQ(loadScenario(out.string()).name, stem);
  }
  const std::vector<std::string> browser{"import", getParameterFile("Browser"), "--format", "bicycleparameters", "--out",
                                         (dir / "b.yaml").string()};
  EXPECT_EQ(motostab::test::runMotostab(browser, dir.string(), output), 2);
  EXPECT_NE(output.find("--repair-inertia"), std::string::npos) << output;
  auto repaired = browser;
  repaired.push_back("--repair-inertia");
  EXPECT_EQ(motostab::test::runMotostab(repaired, dir.string(), output), 0) << output;
  EXPECT_NE(output.find("repaired IByy"), std::string::npos) << output;
  EXPECT_NE(output.find("lowered from 1.3164"), std::string::npos) << output;
}

}  // namespace
}  // namespace motostab::scenario

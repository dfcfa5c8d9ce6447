// Bad input is an InputError naming the file, line and key.
#include <gtest/gtest.h>

#include "tests/support/catch_input_error.h"

#include <fstream>
#include <functional>
#include <random>
#include <sstream>

#include "io/input_error.h"
#include "swingarm/identification/hammer_frf.h"
#include "swingarm/identification/static_laser.h"
#include "tests/support/temp_dir.h"

using motostab::io::InputError;
using motostab::swingarm::identification::StaticTest;
using motostab::swingarm::identification::readFrfTest;
using motostab::swingarm::identification::readHits;
using motostab::swingarm::identification::readStaticReadings;
using motostab::swingarm::identification::readStaticTest;


namespace {

using namespace motostab::swingarm::identification;

const char* kStaticHead =
    "test: static\nframe: \"x along the swingarm\"\nforce_point: {x: 0.55, z: 0.0}\n";
const char* kSensors =
    "sensors:\n  - {name: L1, x: 0.50, z: 0.04}\n  - {name: L2, x: 0.60, z: 0.04}\n  - {name: L3, x: 0.55, z: -0.05}\n";
const char* kGoodCsv = "force_N,L1_m,L2_m,L3_m\n0,0.005,0.006,0.007\n1000,0.0059,0.0069,0.0079\n2000,0.0068,0.0078,0.0088\n";

struct Files {
  std::filesystem::path dir;
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
};

using motostab::test::catchInputError;

TEST(StaticInput, AcceptsTheIssueFormatAsIs) {
  const Files f{makeTempDir("static_ok")};
  f.write("static.csv", kGoodCsv);
  // A bad file with comments.
  const auto y = f.write("static.yaml",
      "test: static\n"
      "frame: \"x along the swingarm from the pivot towards the hub, z up, y lateral (the force direction); metres\"\n"
      "force_point: {x: 0.55, z: 0.0}        # where the lateral force is applied (hub)\n"
      "sensors:                               # laser spots on the reference plate, each measuring y displacement\n"
      "  - {name: L1, x: 0.50, z: 0.04}\n  - {name: L2, x: 0.60, z: 0.04}\n  - {name: L3, x: 0.55, z: -0.05}\n"
      "readings: static.csv                   # header: force_N,L1_m,L2_m,L3_m   (a 0 N row is the unloaded plate)\n");
  const StaticTest t = readStaticTest(y);
  EXPECT_EQ(t.sensors.size(), 3u);
  EXPECT_EQ(readStaticReadings(t).force.size(), 3u);
}

TEST(StaticInput, TooFewSensors) {
  const Files f{makeTempDir("few")};
  const auto y = f.write("s.yaml", std::string(kStaticHead) +
                                       "sensors:\n  - {name: L1, x: 0.50, z: 0.04}\n  - {name: L2, x: 0.60, z: 0.04}\n"
                                       "readings: s.csv\n");
  const InputError e = catchInputError([&] { readStaticTest(y); });
  EXPECT_EQ(e.getLocation().key, "sensors");
  EXPECT_EQ(e.getLocation().line, 4);  // the key (YamlMap locates keys)
  EXPECT_NE(e.getReason().find("at least three"), std::string::npos);
}

TEST(StaticInput, CollinearSensors) {
  const Files f{makeTempDir("collinear")};
  const auto y = f.write("s.yaml", std::string(kStaticHead) +
                                       "sensors:\n  - {name: L1, x: 0.50, z: 0.0}\n  - {name: L2, x: 0.55, z: 0.0}\n"
                                       "  - {name: L3, x: 0.60, z: 0.0}\nreadings: s.csv\n");
  const InputError e = catchInputError([&] { readStaticTest(y); });
  EXPECT_EQ(e.getLocation().key, "sensors");
  EXPECT_NE(e.getReason().find("collinear"), std::string::npos);
}

TEST(StaticInput, MissingColumnAndNoUnloadedRow) {
  const Files f{makeTempDir("columns")};
  const auto y = f.write("s.yaml", std::string(kStaticHead) + kSensors + "readings: s.csv\n");
  f.write("s.csv", "force_N,L1_m,L2_m\n0,1,2\n1000,1,2\n2000,1,2\n");
  InputError e = catchInputError([&] { readStaticReadings(readStaticTest(y)); });
  EXPECT_EQ(e.getLocation().key, "L3_m");
  EXPECT_EQ(e.getLocation().file, (f.dir / "s.csv").string());
  f.write("s.csv", "force_N,L1_m,L2_m,L3_m\n500,1,2,3\n1000,1,2,3\n2000,1,2,3\n");
  e = catchInputError([&] { readStaticReadings(readStaticTest(y)); });
  EXPECT_EQ(e.getLocation().key, "force_N");
  EXPECT_NE(e.getReason().find("unloaded"), std::string::npos);
}

TEST(StaticInput, UnknownKeyNegativeValueAndWrongKind) {
  const Files f{makeTempDir("keys")};
  auto y = f.write("s.yaml", std::string(kStaticHead) + kSensors + "readings: s.csv\nsensor_resolutoin_m: 4e-6\n");
  InputError e = catchInputError([&] { readStaticTest(y); });
  EXPECT_EQ(e.getLocation().key, "sensor_resolutoin_m");
  EXPECT_EQ(e.getLocation().line, 9);
  y = f.write("s.yaml", std::string(kStaticHead) + kSensors + "readings: s.csv\nsensor_resolution_m: -4e-6\n");
  e = catchInputError([&] { readStaticTest(y); });
  EXPECT_EQ(e.getLocation().key, "sensor_resolution_m");
  EXPECT_EQ(e.getLocation().line, 9);
  y = f.write("s.yaml", std::string(kStaticHead) + kSensors + "readings: s.csv\nreadings: t.csv\n");
  e = catchInputError([&] { readStaticTest(y); });
  EXPECT_EQ(e.getLocation().key, "readings");
  EXPECT_EQ(e.getLocation().line, 9);
  y = f.write("s.yaml", "test: frf\n");
  e = catchInputError([&] { readStaticTest(y); });
  EXPECT_EQ(e.getLocation().key, "test");
  y = f.write("s.yaml", std::string(kStaticHead) + "sensors:\n  - {name: L1, x: 0.5, zz: 0.04}\n");
  e = catchInputError([&] { readStaticTest(y); });
  // The sensor misses z; the message shows the keys given, so the typo zz is named.
  EXPECT_EQ(e.getLocation().key, "sensors[0]");
  EXPECT_EQ(e.getLocation().line, 5);
  EXPECT_NE(e.getReason().find("missing key 'sensors[0].z' (keys given here: name, x, zz)"), std::string::npos)
      << e.getReason();
}

const char* kFrfYaml =
    "test: frf\nframe: \"same convention as the static test\"\nforce_point: {x: 0.55, z: 0.0}\n"
    "channels:                                   # accelerometers on the reference plate, measuring along y\n"
    "  - {name: A1, x: 0.50, z: 0.04}\n  - {name: A2, x: 0.60, z: 0.04}\n  - {name: A3, x: 0.55, z: -0.05}\n"
    "hits: [hit1.csv]        # header: time_s,force_N,A1_mps2,A2_mps2,A3_mps2\n";

std::string makeHitCsv(int badRow) {
  std::string s = "time_s,force_N,A1_mps2,A2_mps2,A3_mps2\n";
  for (int k = 0; k < 64; ++k) {
    const double t = (k == badRow ? k - 2 : k) * 1e-3;
    s += std::to_string(t) + "," + (k == 5 ? "100" : "0") + ",0.1,0.2,0.3\n";
  }
  return s;
}

TEST(FrfInput, NonMonotonicTimeColumn) {
  const Files f{makeTempDir("time")};
  const auto y = f.write("frf.yaml", kFrfYaml);
  f.write("hit1.csv", makeHitCsv(-1));
  EXPECT_EQ(readHits(readFrfTest(y)).size(), 1u);
  f.write("hit1.csv", makeHitCsv(20));
  const InputError e = catchInputError([&] { readHits(readFrfTest(y)); });
  EXPECT_EQ(e.getLocation().key, "time_s");
  EXPECT_EQ(e.getLocation().line, 22);  // header is line 1, row k is line k + 2
  EXPECT_NE(e.getReason().find("not strictly increasing"), std::string::npos);
}

// A sample beyond any physical magnitude, in a random row and column, is named where it is.
TEST(FrfInput, SampleBeyondAnyPhysicalMagnitude) {
  const Files f{makeTempDir("magnitude")};
  const auto y = f.write("frf.yaml", kFrfYaml);
  std::mt19937 rng(4711);
  const int row = std::uniform_int_distribution<int>(0, 63)(rng), column = std::uniform_int_distribution<int>(1, 4)(rng);
  std::string csv = makeHitCsv(-1), out;
  std::istringstream in(csv);
  std::string line;
  for (int n = 0; std::getline(in, line); ++n) {
    if (n == row + 1) {
      std::vector<std::string> fields;
      std::stringstream ss(line);
      for (std::string x; std::getline(ss, x, ',');) fields.push_back(x);
      fields[column] = "-1e300";
      line = fields[0];
      for (size_t k = 1; k < fields.size(); ++k) line += "," + fields[k];
    }
    out += line + "\n";
  }
  f.write("hit1.csv", out);
  const InputError e = catchInputError([&] { readHits(readFrfTest(y)); });
  const char* names[] = {"time_s", "force_N", "A1_mps2", "A2_mps2", "A3_mps2"};
  EXPECT_EQ(e.getLocation().key, names[column]);
  EXPECT_EQ(e.getLocation().line, row + 2);
  EXPECT_EQ(e.getLocation().column, column + 1);
  EXPECT_NE(e.getReason().find("magnitude above 1e12"), std::string::npos) << e.getReason();
}

TEST(FrfInput, MissingChannelColumnCollinearChannelsAndBadProcessing) {
  const Files f{makeTempDir("frfbad")};
  std::string csv = makeHitCsv(-1);
  csv.replace(csv.find("A3_mps2"), 7, "A4_mps2");
  f.write("hit1.csv", csv);
  const auto y = f.write("frf.yaml", kFrfYaml);
  InputError e = catchInputError([&] { readHits(readFrfTest(y)); });
  EXPECT_EQ(e.getLocation().key, "A3_mps2");
  auto y2 = f.write("frf2.yaml", std::string("test: frf\nforce_point: {x: 0.55, z: 0.0}\nchannels:\n"
                                             "  - {name: A1, x: 0.5, z: 0}\n  - {name: A2, x: 0.6, z: 0}\n"
                                             "  - {name: A3, x: 0.7, z: 0}\nhits: [hit1.csv]\n"));
  e = catchInputError([&] { readFrfTest(y2); });
  EXPECT_EQ(e.getLocation().key, "channels");
  y2 = f.write("frf3.yaml", std::string(kFrfYaml) + "processing:\n  band_hz: [400, 60]\n");
  e = catchInputError([&] { readFrfTest(y2); });
  EXPECT_EQ(e.getLocation().key, "processing.band_hz");
  EXPECT_EQ(e.getLocation().line, 10);
}

}  // namespace

// The writers of `motostab identify static|frf|swingarm`: static.json keys, the FRF files and a
// swingarm.yaml with the schema of docs/swingarm-identification.md, holding the identified values.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "output/swingarm_output.h"
#include "swingarm/identification/virtual_rig.h"
#include "tests/support/temp_dir.h"

namespace {

using namespace motostab::swingarm::identification;
using motostab::output::writeFrfOutputs;
using motostab::output::writeStaticOutputs;
using motostab::output::writeSwingarmOutputs;

// The virtual rig's static and hammer tests (realistic noise), read back and identified.
struct Identified {
  StaticTest staticTest;
  FrfTest frfTest;
  StaticResult stat;
  FrfResult frf;
  SwingarmIdentification id;
};

Identified identifyVirtualRig(std::uint64_t seed) {
  const VirtualSwingarm rig;
  const RigNoise noise;
  const auto dir = makeTempDir("swingarm_output_inputs");
  std::vector<double> loads;
  for (int i = 0; i <= 32; ++i) loads.push_back(250.0 * (i <= 16 ? i : 32 - i));  // 0-4000-0 N
  writeStaticTestFiles(dir, rig, simulateStaticReadings(rig, loads, noise, seed), noise.laserResolution);
  writeFrfTestFiles(dir, rig, simulateHammerHits(rig, {}, noise, seed + 7), "  band_hz: [60, 400]\n  model_order: [4, 24]\n");
  Identified r;
  r.staticTest = readStaticTest(dir / "static.yaml");
  r.frfTest = readFrfTest(dir / "frf.yaml");
  r.stat = identifyStatic(r.staticTest, readStaticReadings(r.staticTest));
  r.frf = identifyFrf(r.frfTest, readHits(r.frfTest));
  r.id = identifySwingarm(r.stat, r.frf);
  return r;
}

// The CLI's writers: static.json keys, FRF outputs and a swingarm.yaml with the documented schema.
TEST(SwingarmOutput, OutputsFollowTheDocumentedSchema) {
  const Identified r = identifyVirtualRig(21);
  const auto dir = makeTempDir("outputs_written");
  writeStaticOutputs(r.staticTest, r.stat, dir);
  writeFrfOutputs(r.frfTest, r.frf, dir / "frf");
  writeSwingarmOutputs(r.id, r.staticTest, r.frfTest, dir);
  nlohmann::json j;
  std::ifstream(dir / "static.json") >> j;
  for (const char* k : {"k_lat_N_per_m", "a_tw_m", "k_tw_Nm_per_rad", "beta_deg", "axis_point_m", "axis_direction"}) {
    ASSERT_TRUE(j.contains(k)) << k;
    ASSERT_TRUE(j.contains(std::string(k) + "_stderr")) << k;
  }
  EXPECT_DOUBLE_EQ(j["k_tw_Nm_per_rad"].get<double>(), r.stat.kTw);
  for (const char* f : {"static_axis.png", "static_axis.svg", "frf/frf.csv", "frf/modes.csv", "frf/frf.json",
                        "frf/frf_magnitude_phase.png", "frf/coherence.png", "frf/stabilisation.png",
                        "frf/modal_axes.png", "swingarm_axes.png"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  nlohmann::json fj;
  std::ifstream(dir / "frf" / "frf.json") >> fj;
  ASSERT_EQ(fj["modes"].size(), 2u);
  for (const char* k : {"frequency_hz", "frequency_hz_stderr", "damping_ratio", "damping_ratio_stderr", "loss_factor",
                        "loss_factor_stderr"})
    EXPECT_TRUE(fj["modes"][0].contains(k)) << k;
  EXPECT_DOUBLE_EQ(fj["modes"][0]["loss_factor"].get<double>(), 2 * fj["modes"][0]["damping_ratio"].get<double>());
  const YAML::Node y = YAML::LoadFile((dir / "swingarm.yaml").string());
  for (const char* m : {"bending", "torsion", "twist"}) {
    ASSERT_TRUE(y[m]) << m;
    for (const char* k : {"arm_m", "arm_m_stderr", "beta_deg", "beta_deg_stderr", "point_m", "direction"})
      EXPECT_TRUE(y[m]["axis"][k]) << m << ".axis." << k;
    for (const char* k : {"stiffness_Nm_per_rad", "stiffness_Nm_per_rad_stderr", "damping_Nms_per_rad",
                          "damping_Nms_per_rad_stderr"})
      EXPECT_TRUE(y[m][k]) << m << "." << k;
  }
  EXPECT_NEAR(y["bending"]["stiffness_Nm_per_rad"].as<double>(), r.id.bending.stiffness.value, 1e-6 * r.id.bending.stiffness.value);
  EXPECT_NEAR(y["twist"]["damping_Nms_per_rad"].as<double>(), r.id.twist.damping.value, 1e-6);
}

}  // namespace

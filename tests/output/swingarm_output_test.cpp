// The writers of `motostab identify static|frf|swingarm|cog|inertia`: static.json keys, the FRF files, a
// swingarm.yaml with the schema of docs/swingarm-identification.md, and the mass-property files, holding
// the identified values.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <nlohmann/json.hpp>

#include "output/swingarm_output.h"
#include "tests/swingarm/rig_round_trip.h"
#include "tests/support/temp_dir.h"

namespace {

using namespace motostab::swingarm::identification;
using motostab::output::writeCogOutputs;
using motostab::output::writeCogTestFiles;
using motostab::output::writeFrfOutputs;
using motostab::output::writeInertiaOutputs;
using motostab::output::writeInertiaTestFiles;
using motostab::output::writeStaticOutputs;
using motostab::output::writeSwingarmOutputs;

// The CLI's writers: static.json keys, FRF outputs and a swingarm.yaml with the documented schema.
TEST(SwingarmOutput, OutputsFollowTheDocumentedSchema) {
  const IdentifiedRig r = identifyRigTests(VirtualSwingarm(), RigNoise(), 21, makeTempDir("swingarm_output_inputs"),
                                           "  band_hz: [60, 400]\n  model_order: [4, 24]\n");
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

// cog.json and inertia.json hold the identified values; the fit tables have one row per tilt or set-up.
TEST(SwingarmOutput, MassPropertyFilesHoldTheResults) {
  const auto dir = makeTempDir("mass_property_outputs");
  writeCogTestFiles(dir, simulateCogReadings(VirtualPart(), {0.05, 0.0, 0.04}, 0.05, 3));
  const CogTest cogTest = readCogTest(dir / "cog.yaml");
  const CogResult cog = identifyCog(cogTest);
  writeInertiaTestFiles(dir, simulateTrifilarTest(VirtualPart(), 1e-3, 4));
  const InertiaTest inertiaTest = readInertiaTest(dir / "inertia.yaml");
  const InertiaResult inertia = identifyInertia(inertiaTest);
  writeCogOutputs(cogTest, cog, dir / "out");
  writeInertiaOutputs(inertiaTest, inertia, dir / "out");
  auto countLines = [](const std::filesystem::path& p) {
    std::ifstream in(p);
    int n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
  };
  nlohmann::json cj, ij;
  std::ifstream(dir / "out" / "cog.json") >> cj;
  std::ifstream(dir / "out" / "inertia.json") >> ij;
  EXPECT_EQ(cj["mass_kg"].get<double>(), cog.mass);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(cj["cog_m"][i].get<double>(), cog.cog[i]) << i;
  EXPECT_EQ(countLines(dir / "out" / "cog_fit.csv"), 1 + static_cast<int>(cogTest.tiltDeg.size()));
  EXPECT_EQ(ij["I_xx_kg_m2"].get<double>(), inertia.tensor(0, 0));
  EXPECT_EQ(ij["I_xz_kg_m2_stderr"].get<double>(), inertia.tensorStderr(0, 2));
  EXPECT_EQ(ij["setups"].size(), inertiaTest.setups.size());
  EXPECT_EQ(countLines(dir / "out" / "inertia_setups.csv"), 1 + static_cast<int>(inertiaTest.setups.size()));
  for (const char* f : {"cog_fit.png", "cog_fit.svg", "inertia_setups.png", "inertia_setups.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
}

}  // namespace

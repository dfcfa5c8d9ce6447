// One diagnosis of closed-loop data taken with three controller gains (diagnosis/controller_groups.h):
// the "measured" weave of each gain comes from the Whipple benchmark with a hidden effective gain
// factor (drawn here, with seeded noise: hidden_effect.h), the measurement file names each file's
// gain, and diagnose must name `steer_controller_gain` at the hidden factor (within 2 standard errors
// and 15 %) and improve the cross-validated RMS by a factor of at least 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "diagnosis/diagnosis.h"
#include "hidden_effect.h"
#include "core/portable_random.h"
#include "scenario/parameter_paths.h"

namespace motostab::diagnosis {

using core::PortableRandom;
using io::formatNumber;
using scenario::formatOverride;


namespace {

namespace fs = std::filesystem;
const std::string kBenchmark = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

TEST(ControllerDiagnosis, EffectiveGainFromThreeGainSettings) {
  PortableRandom rng(2023);
  const double factor = rng.drawUniform(0.5, 0.8);
  const std::string base = "steer_controller={roll_rate_Nms_per_rad: -4, schedule: {below_mps: 7}}";
  const fs::path dir = fs::temp_directory_path() / ("motostab-controller-diagnosis-" + std::to_string(::getpid()));
  std::string yaml = "name: three-gains\neigenvalues:\n";
  for (double gain : {-2.0, -4.0, -6.0}) {
    testing::HiddenEffect h;
    h.scenario = kBenchmark;
    h.overrides = {base, formatOverride("steer_controller.roll_rate_Nms_per_rad", gain),
                   formatOverride("steer_controller.gain_factor", factor)};
    h.start = 1.5, h.stop = 6.5, h.step = 1;
    h.seed = static_cast<uint64_t>(-gain);
    const fs::path sub = dir / ("gain" + formatNumber(-gain));
    testing::Draw draw(h.seed);
    fs::create_directories(sub);
    testing::writeEigenvalueData(h, sub, draw);
    yaml += "  - file: " + sub.filename().string() + "/eigenvalues.csv\n    controller: {roll_rate_Nms_per_rad: " +
            formatNumber(gain) + "}\n";
  }
  std::ofstream(dir / "measured.yaml") << yaml;
  const MeasuredData data = loadMeasuredData((dir / "measured.yaml").string());
  ASSERT_EQ(data.eigenvalues.size(), 18u);
  DiagnosisOptions opt;
  opt.overrides = {base};
  opt.candidates = {"steer_controller_gain", "steer_controller_delay", "parameter:geometry.trail_m"};
  opt.maxCauses = 2;
  opt.threads = 2;
  const DiagnosisResult r = runDiagnosis(kBenchmark, data, opt);
  fs::remove_all(dir);
  ASSERT_FALSE(r.causes.empty()) << "nothing named; first candidate " << (r.candidates.empty() ? "" : r.candidates[0].name);
  EXPECT_EQ(r.causes[0].fit.name, "steer_controller_gain");
  ASSERT_EQ(r.causes[0].fit.parameters.size(), 1u);
  const ParameterEstimate& p = r.causes[0].fit.parameters[0];
  std::cout << "hidden gain factor " << factor << ": named " << p.value << " +/- " << p.stderr_ << "; CV RMS "
            << r.baseline.cvRms << " -> " << r.extended.cvRms << "\n";
  EXPECT_NEAR(p.value, factor, 2 * p.stderr_);
  EXPECT_NEAR(p.value, factor, 0.15 * factor);
  EXPECT_GE(r.baseline.cvRms / r.extended.cvRms, 2.0);
}

}  // namespace
}  // namespace motostab::diagnosis

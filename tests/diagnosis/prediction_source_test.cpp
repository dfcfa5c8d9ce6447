// Predictions through the one scenario source: typed changes predict what the same values written
// into the scenario file predict; a whole Kooijman diagnosis reads the scenario file at most 3 times;
// a weave split into two real roots is predicted by their mean (checked against the benchmark's
// published linear equations).
#include <gtest/gtest.h>

#include "tests/support/text_file.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <fstream>
#include <sstream>

#include "diagnosis/diagnosis.h"
#include "diagnosis/prediction.h"
#include "core/portable_random.h"
#include "io/yaml_map.h"
#include "output/diagnosis_output.h"
#include "scenario/scenario_source.h"
#include "tests/support/benchmark_equations.h"
#include "tests/support/temp_dir.h"

namespace motostab::diagnosis {

using core::PortableRandom;
using io::getYamlFileOpenCount;
using output::writeDiagnosisOutputs;
using scenario::ParameterOverrides;
using scenario::Scenario;
using scenario::ScenarioSource;

namespace {

const std::string kDir = MOTOSTAB_SOURCE_DIR;
const std::string kKooijman = kDir + "/scenarios/kooijman-silvercity.yaml";
const std::string kExample = kDir + "/examples/diagnosis/kooijman2008.yaml";
const std::string kBenchmark = kDir + "/scenarios/whipple-benchmark.yaml";

// The scenario text with the line `  key: old` (first occurrence after `section:`) replaced.
std::string replaceValue(std::string text, const std::string& section, const std::string& key, double value) {
  const size_t s = text.find("\n" + section + ":");
  const size_t k = text.find("\n  " + key + ":", s);
  const size_t end = text.find('\n', k + 1);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return text.replace(k, end - k, "\n  " + key + ": " + buf);
}

// Kooijman's measured data predicted with typed changes (trail, front radius, a steer damper), and
// by a scenario file with the same values written in: the same predictions.
TEST(PredictionSource, TypedChangesPredictWhatTheWrittenFilePredicts) {
  const MeasuredData data = loadMeasuredData(kExample);
  PortableRandom random(1125);
  const double trail = random.drawUniform(0.17, 0.21), radius = random.drawUniform(0.33, 0.35);
  const double damping = random.drawUniform(0.05, 0.5);
  ParameterOverrides changes;
  changes.set("geometry.trail_m", trail);
  changes.set("front_wheel.radius_m", radius);
  changes.setNode("steer_damper", YAML::Node(YAML::NodeType::Map));
  changes.set("steer_damper.damping_Nms_per_rad", damping);
  const auto dir = makeTempDir("prediction_source");
  std::string text = replaceValue(readText(kKooijman), "geometry", "trail_m", trail);
  text = replaceValue(text, "front_wheel", "radius_m", radius);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", damping);
  text += std::string("\nsteer_damper:\n  damping_Nms_per_rad: ") + buf + "\n";
  const std::string written = (dir / "written.yaml").string();
  std::ofstream(written) << text;
  const std::vector<std::vector<double>> sigma(data.responses.size(), std::vector<double>(1, 1.0));
  const Prediction typed = Predictor(kKooijman, {}, data).predict(changes, sigma);
  const Prediction file = Predictor(written, {}, data).predict({}, sigma);
  ASSERT_EQ(typed.eigenvalues.size(), file.eigenvalues.size());
  for (size_t i = 0; i < typed.eigenvalues.size(); ++i)
    EXPECT_NEAR(std::abs(typed.eigenvalues[i] - file.eigenvalues[i]), 0, 1e-10 * std::abs(file.eigenvalues[i]));
  ASSERT_EQ(typed.responses.size(), 1u);
  const auto& a = typed.responses[0].predicted[0];
  const auto& b = file.responses[0].predicted[0];
  double scale = 0;
  for (double x : b) scale = std::max(scale, std::abs(x));
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-9 * scale);
}

// The bundled example diagnosed as `motostab diagnose` does it (load, diagnose with the robustness
// reruns, write the outputs), with two candidates to stay quick: the scenario file is read at most
// 3 times (the command's check, the diagnosis's source, extended.yaml).
TEST(PredictionSource, AWholeKooijmanDiagnosisReadsTheScenarioAtMostThreeTimes) {
  const long before = getYamlFileOpenCount(kKooijman);
  const MeasuredData data = loadMeasuredData(kExample);
  const ParameterOverrides changes;
  const Scenario scenario = ScenarioSource(kKooijman).load(changes);
  DiagnosisOptions opt;
  opt.candidates = {"steer_damper", "parameter:geometry.trail_m"};
  opt.threads = 2;
  opt.robustness = true;
  opt.overrides = changes;
  const DiagnosisResult result = runDiagnosis(kKooijman, data, opt);
  EXPECT_FALSE(result.robustness.empty());
  const auto dir = makeTempDir("kooijman_reads");
  writeDiagnosisOutputs(dir.string(), result);
  EXPECT_LE(getYamlFileOpenCount(kKooijman) - before, 3);
  EXPECT_GE(getYamlFileOpenCount(kKooijman) - before, 2);
  EXPECT_EQ(scenario.name.empty(), false);
}

// The four eigenvalues of the benchmark bicycle at speed v (benchmark_equations.h).
Eigen::VectorXcd calcBenchmarkEigenvalues(double v) {
  return Eigen::EigenSolver<Eigen::Matrix4d>(testing::calcBenchmarkStateMatrix(v)).eigenvalues();
}

// Below about 0.68 m/s the benchmark's weave is two positive real roots (Meijaard et al. 2007,
// Fig. 3); they join into the weave pair above. Rows at speeds on both sides, drawn in the test: a
// split weave is predicted by the mean of its two roots, imag 0 (continuous through the branch
// point), and the joined weave by the pair.
TEST(PredictionSource, AWeaveSplitIntoTwoRealRootsIsPredictedByTheirMean) {
  PortableRandom random(68);
  MeasuredData data;
  std::vector<double> speeds{random.drawUniform(0.45, 0.55), random.drawUniform(0.58, 0.64)};
  for (double v = 1.0; v <= 6.0; v += 1.0) speeds.push_back(v + random.drawUniform(-0.2, 0.2));
  for (double v : speeds) {
    MeasuredEigenvalue e;
    e.speed = e.speedMin = e.speedMax = v;
    e.mode = analysis::ModeLabel::Weave;
    data.eigenvalues.push_back(e);
  }
  const Prediction p = Predictor(kBenchmark, {}, data).predict({}, {});
  for (size_t i = 0; i < speeds.size(); ++i) {
    const Eigen::VectorXcd l = calcBenchmarkEigenvalues(speeds[i]);
    std::complex<double> expected;
    if (i < 2) {  // the two positive real roots
      std::vector<double> positive;
      for (int k = 0; k < 4; ++k)
        if (l[k].real() > 0 && std::abs(l[k].imag()) < 1e-12) positive.push_back(l[k].real());
      ASSERT_EQ(positive.size(), 2u) << speeds[i];
      expected = 0.5 * (positive[0] + positive[1]);
    } else {  // the complex pair
      for (int k = 0; k < 4; ++k)
        if (l[k].imag() > 1e-9) expected = l[k];
    }
    EXPECT_NEAR(p.eigenvalues[i].real(), expected.real(), 1e-6) << speeds[i];
    EXPECT_NEAR(p.eigenvalues[i].imag(), expected.imag(), 1e-6) << speeds[i];
  }
}

}  // namespace
}  // namespace motostab::diagnosis

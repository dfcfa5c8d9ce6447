// The writers of a diagnosis (output/diagnosis_output.h) on a result made up here: diagnosis.json's
// pinned keys hold the values handed in, residuals.csv's normalised residuals are (measured -
// predicted) / sigma computed here, and report.md has its sections, including the contradiction and
// robustness ones only when there is something to say.
#include "output/diagnosis_output.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/portable_random.h"

namespace motostab::output {

using core::PortableRandom;
using diagnosis::Cause;
using diagnosis::DiagnosisResult;
using diagnosis::FitSummary;
using diagnosis::MeasuredData;
using diagnosis::MeasuredEigenvalue;
using diagnosis::ParameterEstimate;
using diagnosis::RobustnessRun;
using diagnosis::RobustnessVerdict;

namespace {

namespace fs = std::filesystem;

FitSummary makeFit(const std::string& name, const std::string& key, double value, double se, double deltaBic) {
  FitSummary f;
  f.name = name;
  ParameterEstimate e;
  e.name = key, e.path = name, e.value = value, e.stderr_ = se;
  f.parameters = {e};
  f.allParameters = f.parameters;
  f.deltaBic = deltaBic;
  f.correlation = Eigen::MatrixXd::Identity(1, 1);
  return f;
}

struct Made {
  MeasuredData data;
  DiagnosisResult result;
};

// Two weave rows (real and imaginary parts each), values drawn.
Made makeResult(PortableRandom& rng, bool withRobustness) {
  Made m;
  m.data.name = "made-up";
  m.data.file = "made-up.yaml";
  for (double v : {4.0, 5.0}) {
    MeasuredEigenvalue e;
    e.speed = e.speedMin = e.speedMax = v;
    e.mode = analysis::ModeLabel::Weave;
    e.real = rng.drawUniform(-2, 0), e.imag = rng.drawUniform(3, 6);
    m.data.eigenvalues.push_back(e);
  }
  DiagnosisResult& r = m.result;
  r.scenarioFile = "made-up-scenario.yaml";
  r.numObservations = 4, r.numFolds = 2;
  r.baseline.rms = 2, r.baseline.cvRms = 2.2, r.extended.rms = 1, r.extended.cvRms = 1.1;
  const double c = rng.drawUniform(0.1, 1);
  Cause cause{makeFit("steer_damper", "damping_Nms_per_rad", c, 0.01, -30), {}};
  cause.fit.parameters[0].hasProfile = true, cause.fit.parameters[0].profileLow = c - 0.02, cause.fit.parameters[0].profileHigh = c + 0.02;
  cause.indistinguishable.push_back(makeFit("fork_compliance", "stiffness_Nm_per_rad", 1000 * c, 10, -30));
  r.causes.push_back(cause);
  r.candidates = {cause.fit};
  FitSummary contra = makeFit("parameter:geometry.trail_m", "value", 0.09, 0.001, -20);
  contra.parameters[0].priorSigma = 0.0005, contra.parameters[0].priorMeasured = true, contra.parameters[0].sigmas = 20;
  contra.contradictsMeasurement = true;
  r.contradicting.push_back(contra);
  r.noise.push_back({"weave.real", 0.1, true, {}, 0.1});
  r.noise.push_back({"weave.imag", 0.2, true, {0.9}, 0.2 / std::sqrt(1 - 0.81)});
  if (withRobustness) {
    RobustnessRun same{"eigenvalues: a.csv", {"steer_damper"}, {cause.fit}, RobustnessVerdict::Same, ""};
    RobustnessRun other{"speed ranges -> mid speeds", {"parameter:geometry.trail_m"}, {contra}, RobustnessVerdict::OtherCause, ""};
    r.robustness = {same, other};
  }
  for (int i = 0; i < 4; ++i) {
    const int row = i / 2, part = i % 2;
    r.observed.push_back(part ? m.data.eigenvalues[row].imag : m.data.eigenvalues[row].real);
    r.sigma.push_back(rng.drawUniform(0.05, 0.2));
    r.predictedBefore.push_back(r.observed.back() + rng.drawNormal(0, 0.3));
    r.predictedAfter.push_back(r.observed.back() + rng.drawNormal(0, 0.1));
    r.whitenedBefore.push_back(rng.drawNormal()), r.whitenedAfter.push_back(rng.drawNormal());
    r.observationComponent.push_back(part ? "weave.imag" : "weave.real");
    r.observationSpeed.push_back(m.data.eigenvalues[row].speed);
    r.observationTime.push_back(std::nan(""));
    r.observationRow.push_back(row), r.observationPart.push_back(part), r.observationRun.push_back(-1), r.observationSignal.push_back(0);
  }
  r.data = &m.data;
  return m;
}

TEST(DiagnosisOutput, JsonHoldsTheCausesNoiseContradictionsAndRobustness) {
  PortableRandom rng(8080);
  Made m = makeResult(rng, true);
  m.result.data = &m.data;
  const nlohmann::json j = makeDiagnosisJson(m.result);
  ASSERT_EQ(j["causes"].size(), 1u);
  EXPECT_EQ(j["causes"][0]["name"], "steer_damper");
  EXPECT_DOUBLE_EQ(j["causes"][0]["parameters"]["damping_Nms_per_rad"]["value"].get<double>(), m.result.causes[0].fit.parameters[0].value);
  EXPECT_EQ(j["causes"][0]["parameters"]["damping_Nms_per_rad"]["profile_interval_95"].size(), 2u);
  EXPECT_EQ(j["causes"][0]["indistinguishable"][0]["name"], "fork_compliance");  // named with its value
  EXPECT_DOUBLE_EQ(j["causes"][0]["indistinguishable"][0]["parameters"]["stiffness_Nm_per_rad"]["value"].get<double>(),
                   m.result.causes[0].indistinguishable[0].parameters[0].value);
  EXPECT_EQ(j["contradicts_measurement"][0]["name"], "parameter:geometry.trail_m");
  EXPECT_DOUBLE_EQ(j["contradicts_measurement"][0]["parameters"]["value"]["change_in_sigmas"].get<double>(), 20);
  EXPECT_DOUBLE_EQ(j["noise"]["weave.imag"]["ar"][0].get<double>(), 0.9);
  EXPECT_NEAR(j["noise"]["weave.imag"]["marginal_sigma"].get<double>(), 0.2 / std::sqrt(0.19), 1e-12);
  ASSERT_EQ(j["robustness"].size(), 2u);
  EXPECT_EQ(j["robustness"][0]["left_out"], "eigenvalues: a.csv");
  EXPECT_EQ(j["robustness"][1]["causes"][0]["name"], "parameter:geometry.trail_m");
  EXPECT_EQ(j["robustness"][1]["verdict"], "other cause");
  EXPECT_EQ(j["robustness"][1]["fragile"], true);
  EXPECT_EQ(j["robustness"][0]["fragile"], false);
  EXPECT_EQ(j["fragile"], true);
  EXPECT_NEAR(j["gain"]["factor"].get<double>(), 2.2 / 1.1, 1e-12);
}

TEST(DiagnosisOutput, ReportHasItsSections) {
  PortableRandom rng(9090);
  Made m = makeResult(rng, true);
  m.result.data = &m.data;
  const std::string report = makeDiagnosisReport(m.result);
  for (const char* section : {"## The data", "## What the model gets wrong", "## Candidates", "## The cause",
                              "## Fits, but contradicts the measurement", "## Robustness", "## The extension", "## The gain"})
    EXPECT_NE(report.find(section), std::string::npos) << section;
  EXPECT_NE(report.find("**Fragile**"), std::string::npos);
  EXPECT_NE(report.find("fork_compliance"), std::string::npos);  // the indistinguishable look-alike is named
  EXPECT_NE(report.find("20 sigma"), std::string::npos);
  m.result.robustness.clear();
  m.result.contradicting.clear();
  const std::string bare = makeDiagnosisReport(m.result);
  EXPECT_EQ(bare.find("## Robustness"), std::string::npos);
  EXPECT_EQ(bare.find("## Fits, but contradicts"), std::string::npos);
}

TEST(DiagnosisOutput, FilesAreWrittenWithTheirResiduals) {
  PortableRandom rng(7070);
  Made m = makeResult(rng, false);
  m.result.data = &m.data;
  m.result.scenarioFile = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";
  m.result.extendedOverrides = {"steer_damper={damping_Nms_per_rad: 0.25}"};
  const fs::path dir = fs::temp_directory_path() / ("motostab-diagnosis-output-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  writeDiagnosisOutputs(dir, m.result);
  for (const char* f : {"diagnosis.json", "report.md", "residuals.csv", "extended.yaml", "eigen_weave.csv"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  std::ifstream yaml(dir / "extended.yaml");
  std::stringstream extended;
  extended << yaml.rdbuf();
  EXPECT_NE(extended.str().find("damping_Nms_per_rad: 0.25"), std::string::npos);
  std::ifstream in(dir / "residuals.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("component,speed_mps,time_s,measured,sigma,predicted_before,predicted_after,residual_before,residual_after,whitened_before,whitened_after", 0), 0u);
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(std::getline(in, line));
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    ASSERT_EQ(cells.size(), 11u) << line;
    const auto& r = m.result;
    EXPECT_NEAR(std::stod(cells[7]), (r.observed[i] - r.predictedBefore[i]) / r.sigma[i], 1e-9);
    EXPECT_NEAR(std::stod(cells[8]), (r.observed[i] - r.predictedAfter[i]) / r.sigma[i], 1e-9);
    EXPECT_NEAR(std::stod(cells[9]), r.whitenedBefore[i], 1e-9);
    EXPECT_NEAR(std::stod(cells[10]), r.whitenedAfter[i], 1e-9);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace motostab::output

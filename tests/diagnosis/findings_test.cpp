// Findings in measured data: the strict reader (every bad input named at file:line:col and key), the
// violation of each kind against a calculation written here, and a diagnosis that uses findings only.
#include "diagnosis/findings.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "analysis/sweep.h"
#include "diagnosis/diagnosis.h"
#include "hidden_effect.h"
#include "scenario/scenario.h"
#include "vehicle/vehicle_model.h"

namespace motostab::diagnosis {

using io::InputError;

namespace {

namespace fs = std::filesystem;
const std::string kBenchmark = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

class FindingsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("motostab-findings-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string yaml(const std::string& text) {
    std::ofstream(dir_ / "f.yaml") << text;
    return (dir_ / "f.yaml").string();
  }
  // The location of the InputError of loading `text` ("line:col:key"), or "loads".
  std::string where(const std::string& text) {
    try {
      loadMeasuredData(yaml(text));
    } catch (const InputError& e) {
      const auto& w = e.getLocation();
      return std::to_string(w.line) + ":" + std::to_string(w.column) + ":" + w.key;
    }
    return "loads";
  }
  fs::path dir_;
};

TEST_F(FindingsTest, ReadsEveryKind) {
  const MeasuredData d = loadMeasuredData(yaml(
      "findings:\n"
      "  - {kind: stable, mode: wobble, speeds_mps: [10, 50], tolerance_per_s: 0.2, source: 'sec. 4'}\n"
      "  - {kind: unstable, mode: weave, speeds_mps: [0.5, 2], tolerance_per_s: 0.1}\n"
      "  - {kind: frequency_within, mode: wobble, speeds_mps: [10, 50], frequency_hz: [9, 11], tolerance_hz: 0.5}\n"
      "  - {kind: most_stable_near, mode: weave, speeds_mps: [10, 40], speed_mps: 18, tolerance_mps: 2}\n"
      "  - kind: change_below\n"
      "    mode: wobble\n"
      "    speeds_mps: [10, 40]\n"
      "    change: {swingarm.compliance: torsion, steer_damper: {damping_Nms_per_rad: 2}}\n"
      "    percent: 5\n"
      "    tolerance_percent: 1\n"));
  ASSERT_EQ(d.findings.size(), 5u);
  EXPECT_EQ(d.findings[0].kind, FindingKind::Stable);
  EXPECT_EQ(d.findings[0].mode, analysis::ModeLabel::Wobble);
  EXPECT_EQ(d.findings[0].source, "sec. 4");
  EXPECT_EQ(d.findings[0].where.line, 2);
  EXPECT_DOUBLE_EQ(d.findings[1].tolerance, 0.1);
  EXPECT_DOUBLE_EQ(d.findings[2].frequencyMax, 11);
  EXPECT_DOUBLE_EQ(d.findings[3].speed, 18);
  ASSERT_EQ(d.findings[4].change.size(), 2u);
  EXPECT_EQ(d.findings[4].change[0], "swingarm.compliance=torsion");
  EXPECT_EQ(scenario::ParameterOverrides(d.findings[4].change).size(), 2u);
  // 41 speeds 1 m/s apart; the change doubles the probe rows.
  EXPECT_EQ(getFindingSpeeds(d.findings[0]).size(), 41u);
  EXPECT_EQ(countProbeRows(d.findings[4]), 62u);
  const auto probes = makeProbeRows(d.findings);
  EXPECT_EQ(probes.size(), 41u + 3u + 41u + 31u + 62u);  // [0.5, 2]: 3 speeds (at least 3)
  EXPECT_TRUE(probes.back().controller == d.findings[4].change);
}

// Each bad entry is named at line 2, at the column of its key (computed here from the text), with the
// key path; a missing key at the entry itself.
TEST_F(FindingsTest, BadInputIsNamedAtItsLineColumnAndKey) {
  const std::string head = "findings:\n";
  const std::string ok = "mode: wobble, speeds_mps: [10, 50], tolerance_per_s: 0.2";
  const auto at = [&](const std::string& entry, const std::string& key) {
    const std::string line = "  - {" + entry + "}";
    const size_t col = key.empty() ? 4 : line.find(key + ":");
    return "2:" + std::to_string(col + 1) + ":findings[0]" + (key.empty() ? "" : "." + key) + " <- " + line;
  };
  const auto check = [&](const std::string& entry, const std::string& key) {
    const std::string expected = at(entry, key);
    EXPECT_EQ(where(head + "  - {" + entry + "}\n") + expected.substr(expected.find(" <- ")), expected);
  };
  check("kind: stabel, " + ok, "kind");
  check("kind: stable, mode: wobbel, speeds_mps: [10, 50], tolerance_per_s: 0.2", "mode");
  check("kind: stable, mode: wobble, speeds_mps: [50, 10], tolerance_per_s: 0.2", "speeds_mps");
  check("kind: stable, mode: wobble, speeds_mps: [10, 500], tolerance_per_s: 0.2", "speeds_mps");
  check("kind: stable, mode: wobble, speeds_mps: [10, 50], tolerance_hz: 0.2", "tolerance_hz");
  check("kind: stable, mode: wobble, speeds_mps: [10, 50], tolerance_per_s: 0", "tolerance_per_s");
  check("kind: stable, " + ok + ", frequency_hz: [1, 2]", "frequency_hz");
  check("kind: frequency_within, mode: wobble, speeds_mps: [10, 50], frequency_hz: [11, 9], tolerance_hz: 1", "frequency_hz");
  check("kind: most_stable_near, mode: weave, speeds_mps: [10, 40], speed_mps: 45, tolerance_mps: 1", "speed_mps");
  check("kind: change_below, mode: wobble, speeds_mps: [10, 40], percent: 5, tolerance_percent: 1", "");
  check("kind: change_below, mode: wobble, speeds_mps: [10, 40], percent: 5, tolerance_percent: 1, change: {}", "change");
  check("kind: stable, " + ok + ", variant: {}", "variant");
  EXPECT_EQ(where("findings: {kind: stable}\n"), "1:1:findings");
  EXPECT_EQ(where("name: x\n"), "1:1:");
}

// Probe eigenvalues drawn at random; the violation computed here from its definition.
TEST(FindingViolation, IntervalKindsAreTheRmsOfTheirHinges) {
  testing::Draw draw(3030);
  for (int trial = 0; trial < 20; ++trial) {
    Finding f;
    f.speedMin = draw.uniform(0, 20), f.speedMax = f.speedMin + draw.uniform(2, 30);
    f.frequencyMin = draw.uniform(1, 5), f.frequencyMax = f.frequencyMin + draw.uniform(0, 3);
    f.percent = draw.uniform(0, 10);
    const size_t n = getFindingSpeeds(f).size();
    std::vector<std::complex<double>> l(2 * n);
    for (auto& x : l) x = {draw.uniform(-2, 2), 2 * M_PI * draw.uniform(0, 8)};
    double stable = 0, unstable = 0, freq = 0, change = 0;
    for (size_t i = 0; i < n; ++i) {
      const double hz = l[i].imag() / (2 * M_PI);
      const double out = hz < f.frequencyMin ? f.frequencyMin - hz : hz > f.frequencyMax ? hz - f.frequencyMax : 0;
      const double moved = 100 * std::abs(l[n + i] - l[i]) / std::abs(l[i]);
      stable += l[i].real() > 0 ? l[i].real() * l[i].real() : 0;
      unstable += l[i].real() < 0 ? l[i].real() * l[i].real() : 0;
      freq += out * out;
      change += moved > f.percent ? (moved - f.percent) * (moved - f.percent) : 0;
    }
    f.kind = FindingKind::Stable;
    EXPECT_NEAR(calcFindingViolation(f, l.data()), std::sqrt(stable / n), 1e-12);
    f.kind = FindingKind::Unstable;
    EXPECT_NEAR(calcFindingViolation(f, l.data()), std::sqrt(unstable / n), 1e-12);
    f.kind = FindingKind::FrequencyWithin;
    EXPECT_NEAR(calcFindingViolation(f, l.data()), std::sqrt(freq / n), 1e-12);
    f.kind = FindingKind::ChangeBelow;
    EXPECT_NEAR(calcFindingViolation(f, l.data()), std::sqrt(change / n), 1e-9);
  }
}

// A real part quadratic in speed has its minimum found exactly between grid speeds.
TEST(FindingViolation, MostStableSpeedOfAQuadraticIsExact) {
  testing::Draw draw(4040);
  for (int trial = 0; trial < 20; ++trial) {
    Finding f;
    f.kind = FindingKind::MostStableNear;
    f.speedMin = draw.uniform(5, 10), f.speedMax = f.speedMin + draw.uniform(10, 30);
    f.speed = draw.uniform(f.speedMin, f.speedMax);
    const double v0 = draw.uniform(f.speedMin + 1, f.speedMax - 1), a = draw.uniform(0.001, 0.1), b = draw.uniform(-3, -0.5);
    std::vector<std::complex<double>> l;
    for (double v : getFindingSpeeds(f)) l.push_back({a * (v - v0) * (v - v0) + b, 10.0});
    EXPECT_NEAR(calcFindingViolation(f, l.data()), v0 - f.speed, 1e-9);
  }
}

// Findings of the benchmark bicycle (with `overrides` hidden) as a rider or paper would state them:
// the weave unstable below its critical speed and stable above it (each 0.15 m/s clear of it), and its
// frequency at 3, 5 and 7 m/s within +/- 0.02 Hz. From the labelled sweep of the extended model.
std::string writeBenchmarkFindings(const fs::path& dir, const std::vector<std::string>& overrides) {
  const scenario::Scenario s = scenario::loadScenario(kBenchmark, overrides);
  analysis::SweepOptions opt;
  opt.start = 2, opt.stop = 8, opt.step = 0.05;
  const analysis::SweepResult sweep = analysis::runSweep(vehicle::VehicleModel(s), opt);
  const auto weave = std::find_if(sweep.branches.begin(), sweep.branches.end(), [](const auto& b) { return b.label == analysis::ModeLabel::Weave; });
  EXPECT_NE(weave, sweep.branches.end());
  double vc = NAN;
  for (size_t k = 1; k < sweep.speeds.size() && std::isnan(vc); ++k) {
    const double a = weave->eigenvalue[k - 1].real(), b = weave->eigenvalue[k].real();
    if (a > 0 && b <= 0) vc = sweep.speeds[k - 1] + (sweep.speeds[k] - sweep.speeds[k - 1]) * a / (a - b);
  }
  EXPECT_FALSE(std::isnan(vc));
  using io::formatNumber;
  std::string y = "findings:\n";
  y += "  - {kind: unstable, mode: weave, speeds_mps: [2.5, " + formatNumber(vc - 0.15) + "], tolerance_per_s: 0.02}\n";
  y += "  - {kind: stable, mode: weave, speeds_mps: [" + formatNumber(vc + 0.15) + ", 8], tolerance_per_s: 0.02}\n";
  for (double v : {3.0, 5.0, 7.0}) {
    const size_t k = std::lround((v - opt.start) / opt.step);
    const double f = std::abs(weave->eigenvalue[k].imag()) / (2 * M_PI);
    y += "  - {kind: frequency_within, mode: weave, speeds_mps: [" + formatNumber(v) + ", " + formatNumber(v) +
         "], frequency_hz: [" + formatNumber(f - 0.02) + ", " + formatNumber(f + 0.02) + "], tolerance_hz: 0.01}\n";
  }
  std::ofstream(dir / "findings.yaml") << y;
  return (dir / "findings.yaml").string();
}

DiagnosisResult diagnoseBenchmarkFindings(const fs::path& dir, const std::vector<std::string>& hidden) {
  const MeasuredData data = loadMeasuredData(writeBenchmarkFindings(dir, hidden));
  DiagnosisOptions opt;
  opt.candidates = {"steer_damper", "parameter:geometry.trail_m"};
  opt.maxCauses = 2;
  opt.threads = 2;
  DiagnosisResult r = runDiagnosis(kBenchmark, data, opt);
  r.data = nullptr;
  return r;
}

// A steer damper of drawn damping: findings alone make it the best candidate by far, with every finding
// held at its fit, and name it: where every finding holds the interval terms are flat and the Wald
// standard error is zero, so "off" is excluded by the profile likelihood (docs/diagnosis.md, Off outside
// the interval), whose 95 % interval covers the drawn value.
TEST_F(FindingsTest, HiddenSteerDamperIsNamedFromFindings) {
  const double c = testing::Draw(5150).uniform(0.8, 1.6);
  const DiagnosisResult r = diagnoseBenchmarkFindings(dir_, {"steer_damper={damping_Nms_per_rad: " + io::formatNumber(c) + "}"});
  std::string why;
  for (const auto& f : r.candidates) {
    why += "\n" + f.name + " dBIC " + io::formatNumber(f.deltaBic, 4) + " p " + io::formatNumber(f.pValue, 3) + ":";
    for (const auto& x : f.failed) why += " " + x + ";";
    for (const auto& e : f.parameters) why += " " + e.name + " = " + io::formatNumber(e.value, 4) + " +/- " + io::formatNumber(e.stderr_, 3);
  }
  ASSERT_FALSE(r.candidates.empty());
  const FitSummary& best = r.candidates[0];
  EXPECT_EQ(best.name, "steer_damper") << "true c " << c << why;
  EXPECT_LT(best.deltaBic, -10) << why;
  EXPECT_LT(best.pValue, 0.01) << why;
  EXPECT_LT(best.deviance, 1) << why;                 // every finding holds at the fit
  EXPECT_GT(r.baseline.deviance, 100) << why;         // and the undamped bicycle violates them
  EXPECT_NEAR(best.parameters[0].value, c, 0.5 * c) << why;
  ASSERT_EQ(r.causes.size(), 1u) << why;
  EXPECT_EQ(r.causes[0].fit.name, "steer_damper") << why;
  EXPECT_LE(r.causes[0].fit.parameters[0].profileLow, c) << why;
  EXPECT_GE(r.causes[0].fit.parameters[0].profileHigh, c) << why;
}

// Findings of the unchanged bicycle name nothing.
TEST_F(FindingsTest, FindingsOfTheUnchangedBicycleNameNothing) {
  const DiagnosisResult r = diagnoseBenchmarkFindings(dir_, {});
  EXPECT_TRUE(r.causes.empty()) << r.causes[0].fit.name;
  EXPECT_LT(r.baseline.deviance, 1);
}

// A finding's change that the scenario refuses is bad input at the finding, also when the refusal comes
// from a model-extension section (read by its plugin, not by the loader).
TEST(Findings, ChangeTheScenarioRefusesIsNamedAtTheFinding) {
  const auto source = scenario::ScenarioSource::open(kBenchmark);
  for (const char* change : {"steer_damper={damping_Nms_per_rad: -1}", "steer_dampr={damping_Nms_per_rad: 1}",
                             "geometry.trail_m=.nan"}) {
    Finding f;
    f.change = {change};
    f.where = {"findings.yaml", 7, 5, ""};
    try {
      checkFindingChanges(*source, {}, {f});
      ADD_FAILURE() << change << ": accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.getLocation().line, 7) << e.what();
      EXPECT_EQ(e.getLocation().key, "change") << e.what();
      EXPECT_NE(std::string(e.what()).find("refuses this change"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace motostab::diagnosis

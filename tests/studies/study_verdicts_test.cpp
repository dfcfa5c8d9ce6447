// The study's verdicts on findings and its extended.yaml: findings written here from a labelled sweep of
// the supersport with a hidden steering damper of drawn value; the verdicts of the scenario without it
// disagree, the diagnosis names the damper, and extended.yaml, loaded back and swept here, reproduces
// the extended motorcycle's reported figures and verdicts.
#include "tests/support/extension_sections.h"
#include "studies/study_verdicts.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "analysis/sweep.h"
#include "core/portable_random.h"
#include "diagnosis/findings.h"
#include "io/csv.h"
#include "output/study_verdicts_output.h"
#include "scenario/scenario.h"
#include "vehicle/vehicle_model.h"

namespace motostab::studies {
namespace {

namespace fs = std::filesystem;
using io::formatNumber;
const std::string kSupersport = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/supersport.yaml";

const analysis::ModeBranch& getWobble(const analysis::SweepResult& s) {
  const auto b = std::find_if(s.branches.begin(), s.branches.end(), [](const auto& x) {
    return x.label == analysis::ModeLabel::Wobble && x.eigenvalue.back().imag() >= 0;
  });
  if (b == s.branches.end()) throw std::runtime_error("no wobble");
  return *b;
}

analysis::SweepResult sweep(const scenario::Scenario& s, double a, double b, double step) {
  analysis::SweepOptions opt;
  opt.start = a, opt.stop = b, opt.step = step;
  return analysis::runSweep(vehicle::VehicleModel(s), opt);
}

// Wobble stable below its critical speed and unstable above it (0.5 m/s clear), and its frequency at
// 30, 45 and 60 m/s within +/- 0.1 Hz, from the sweep of the supersport with `hidden`.
std::string writeFindings(const fs::path& dir, const std::string& hidden) {
  const analysis::SweepResult s = sweep(scenario::loadScenario(kSupersport, {hidden}), 30, 60, 0.5);
  const auto& w = getWobble(s);
  double vc = NAN;
  for (size_t k = 1; k < s.speeds.size() && std::isnan(vc); ++k) {
    const double a = w.eigenvalue[k - 1].real(), b = w.eigenvalue[k].real();
    if (a < 0 && b >= 0) vc = s.speeds[k - 1] + (s.speeds[k] - s.speeds[k - 1]) * a / (a - b);
  }
  EXPECT_FALSE(std::isnan(vc));
  std::string y = "findings:\n";
  y += "  - {kind: stable, mode: wobble, speeds_mps: [30, " + formatNumber(vc - 0.5) + "], tolerance_per_s: 0.05, source: here}\n";
  y += "  - {kind: unstable, mode: wobble, speeds_mps: [" + formatNumber(vc + 0.5) + ", 60], tolerance_per_s: 0.05}\n";
  for (double v : {30.0, 45.0, 60.0}) {
    const double f = std::abs(w.eigenvalue[std::lround((v - 30) / 0.5)].imag()) / (2 * M_PI);
    y += "  - {kind: frequency_within, mode: wobble, speeds_mps: [" + formatNumber(v) + ", " + formatNumber(v) +
         "], frequency_hz: [" + formatNumber(f - 0.1) + ", " + formatNumber(f + 0.1) + "], tolerance_hz: 0.05}\n";
  }
  std::ofstream(dir / "findings.yaml") << y;
  return (dir / "findings.yaml").string();
}

TEST(StudyVerdictsTest, ExtendedYamlReproducesTheReportedFigures) {
  const fs::path dir = fs::temp_directory_path() / ("motostab-study-verdicts-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  core::PortableRandom rng(3107);
  const double c = 0.9 + 0.6 * rng.drawUniform();
  VerdictOptions opt;
  opt.findingsFile = writeFindings(dir, "steer_damper={damping_Nms_per_rad: " + formatNumber(c) + "}");
  opt.candidates = {"steer_damper", "no_such_candidate"};
  opt.maxCauses = 1;
  const StudyVerdicts v = runStudyVerdicts(scenario::ScenarioSource::open(kSupersport), opt);
  ASSERT_EQ(v.findings.size(), 5u);
  EXPECT_EQ(v.findings[0].base.verdict, Verdict::Disagrees);  // no damper: the wobble is unstable from 35 m/s
  ASSERT_EQ(v.causes.size(), 1u);
  EXPECT_EQ(v.causes[0].fit.name, "steer_damper");
  EXPECT_LE(v.causes[0].fit.values[0].low, c);
  EXPECT_GE(v.causes[0].fit.values[0].high, c);
  EXPECT_LT(v.devianceAfter, v.devianceBefore);
  EXPECT_TRUE(std::any_of(v.unavailable.begin(), v.unavailable.end(),
                          [](const std::string& u) { return u.rfind("no_such_candidate:", 0) == 0; }));
  output::writeVerdictOutputs(dir, kSupersport, v);
  // extended.yaml on its own: a complete scenario with the named damping.
  const scenario::Scenario ext = scenario::loadScenario((dir / "extended.yaml").string());
  EXPECT_NEAR(testing::getExtensionValue(ext, "steer_damper", "damping_Nms_per_rad").as<double>(),
              v.causes[0].fit.values[0].value, 1e-12 * c);
  for (const auto& f : v.findings) {
    EXPECT_EQ(f.extended.verdict, Verdict::Agrees) << f.statement << ": " << f.extended.text;
    const std::vector<double> speeds = diagnosis::getFindingSpeeds(f.finding);
    const double step = speeds.size() > 1 ? speeds[1] - speeds[0] : 1.0;
    const analysis::SweepResult s = sweep(ext, speeds.front(), speeds.back(), step);
    const auto& w = getWobble(s);
    double reMax = -INFINITY, reMin = INFINITY, hz = 0;
    for (const auto& l : w.eigenvalue) reMax = std::max(reMax, l.real()), reMin = std::min(reMin, l.real()), hz = std::abs(l.imag()) / (2 * M_PI);
    const double expected = f.finding.kind == diagnosis::FindingKind::Stable     ? reMax
                            : f.finding.kind == diagnosis::FindingKind::Unstable ? reMin
                                                                                 : hz;
    if (f.finding.kind == diagnosis::FindingKind::Stable || f.finding.kind == diagnosis::FindingKind::Unstable ||
        f.finding.kind == diagnosis::FindingKind::FrequencyWithin) {
      EXPECT_NEAR(f.extended.value, expected, 1e-3) << f.statement;
    }
  }
  const auto json = output::makeVerdictJson(v);
  EXPECT_EQ(json["extended_scenario"], "extended.yaml");
  EXPECT_EQ(json["findings"][0]["verdict"], "disagrees");
  EXPECT_EQ(json["diagnosis"]["causes"][0]["name"], "steer_damper");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace motostab::studies

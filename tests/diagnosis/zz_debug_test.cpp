#include <gtest/gtest.h>
#include <filesystem>
#include <iostream>
#include "diagnosis/diagnosis.h"
#include "diagnosis/fit_problem.h"
#include "hidden_effect.h"
namespace motostab { namespace {
TEST(ZzDebug, Capsize) {
  const std::string kBenchmark = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";
  const double c = testing::Draw(707).uniform(0.15, 0.45);
  testing::HiddenEffect h; h.scenario = kBenchmark; h.seed = 101;
  h.overrides = {"steer_damper={damping_Nms_per_rad: " + formatNumber(c) + "}"};
  h.modes = {"weave", "capsize"}; h.start = 3; h.relativeNoise = 0; h.absoluteNoise = 1e-6;
  auto dir = std::filesystem::temp_directory_path() / "zzdebug";
  std::string f = testing::writeHiddenEffectData(h, dir, true);
  MeasuredData data = loadMeasuredData(f);
  Predictor pr(kBenchmark, {}, data);
  for (bool exact : {true, false}) {
    Prediction p = pr.predict({"steer_damper={damping_Nms_per_rad: " + formatNumber(c) + "}"}, {}, exact);
    for (size_t i = 0; i < data.eigenvalues.size(); ++i) {
      auto& e = data.eigenvalues[i];
      std::cout << exact << " " << e.speed << " " << e.mode << " meas " << e.real << " " << e.imag << " pred " << p.eigenvalues[i] << "\n";
    }
  }
}
}}
namespace motostab { namespace {
TEST(ZzDebug, Run) {
  const std::string kBenchmark = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";
  const double c = testing::Draw(getenv("ZZC") ? atoi(getenv("ZZC")) : 707).uniform(0.15, 0.45);
  testing::HiddenEffect h; h.scenario = kBenchmark; h.seed = 101;
  h.overrides = {"steer_damper={damping_Nms_per_rad: " + formatNumber(c) + "}"};
  h.modes = {"weave", "capsize"}; h.start = 3;
  h.withStderr = getenv("ZZSTDERR") != nullptr;
  if (getenv("ZZSEED")) h.seed = atoi(getenv("ZZSEED"));
  if (getenv("ZZNOISE")) h.relativeNoise = atof(getenv("ZZNOISE"));
  auto dir = std::filesystem::temp_directory_path() / "zzdebug2";
  std::string f = testing::writeHiddenEffectData(h, dir, true);
  MeasuredData data = loadMeasuredData(f);
  DiagnosisOptions opt; opt.threads = 2;
  opt.candidates = splitFields(getenv("ZZCAND") ? getenv("ZZCAND") : "steer_damper,tyre_slip,parameter:geometry.*,parameter:front_frame.inertia_kgm2.zz", ',');
  DiagnosisResult r = runDiagnosis(kBenchmark, data, opt);
  std::cout << "true c " << c << "\n";
  for (auto& n : r.noise) std::cout << "noise " << n.component << " " << n.sigma << "\n";
  for (auto& k : r.causes) { std::cout << "cause " << k.fit.name; for (auto& p : k.fit.parameters) std::cout << " " << p.value << "+-" << p.stderr_; std::cout << " dbic " << k.fit.deltaBic << "\n"; }
  for (auto& k : r.candidates) { std::cout << "cand " << k.name; for (auto& p : k.parameters) std::cout << " " << p.value << "+-" << p.stderr_; std::cout << " dbic " << k.deltaBic << " chi2 " << k.chi2 << "\n"; }
  std::cout << "ext chi2 " << r.extended.chi2 << " rms " << r.extended.rms << "\n";
  for (auto& c : r.residualsAfter) std::cout << "resid " << c.name << " mean " << c.meanReal << " rms " << c.rmsReal << "\n";
}
}}
namespace motostab { namespace {
TEST(ZzDebug, Chi2) {
  const std::string kBenchmark = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";
  const double c = testing::Draw(707).uniform(0.15, 0.45);
  testing::HiddenEffect h; h.scenario = kBenchmark; h.seed = 101;
  h.overrides = {"steer_damper={damping_Nms_per_rad: " + formatNumber(c) + "}"};
  h.modes = {"weave", "capsize"}; h.start = 3; h.withStderr = true;
  auto dir = std::filesystem::temp_directory_path() / "zzdebug3";
  std::string f = testing::writeHiddenEffectData(h, dir, true);
  MeasuredData data = loadMeasuredData(f);
  Predictor pr(kBenchmark, {}, data);
  for (double cc : {c, 0.4165, 0.43}) for (bool exact : {true, false}) {
    Prediction p = pr.predict({"steer_damper={damping_Nms_per_rad: " + formatNumber(cc) + "}"}, {}, exact);
    double chi2 = 0;
    for (size_t i = 0; i < data.eigenvalues.size(); ++i) {
      auto& e = data.eigenvalues[i];
      double a = (e.real - p.eigenvalues[i].real()) / e.realStderr;
      double b = e.imag ? (e.imag - p.eigenvalues[i].imag()) / e.imagStderr : 0;
      chi2 += a*a + b*b;
      if (cc == c && exact) std::cout << e.mode << " " << e.speed << " z " << a << " " << b << "\n";
    }
    std::cout << "c " << cc << " exact " << exact << " chi2 " << chi2 << "\n";
  }
}
}}

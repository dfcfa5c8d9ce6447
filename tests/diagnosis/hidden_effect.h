#pragma once
// Test helper: "measured" data generated from a scenario carrying an effect the diagnosed scenario
// lacks (the hidden overrides), with seeded Gaussian noise. Independent of diagnosis/: eigenvalues
// come from runSweep's labelled branches of the extended model on the sweep grid; responses are the
// extended model's linear free responses exp(A t) x0 from a random initial state.
#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/portable_random.h"
#include "analysis/sweep.h"
#include "io/csv.h"
#include "scenario/scenario.h"
#include "tests/support/analysis_chain.h"
#include "vehicle/vehicle_model.h"

namespace motostab::testing {

using core::PortableRandom;
using io::formatNumber;


/// Portable draws: uniform in [0, 1) from the top 53 bits, normal by Box-Muller.
struct Draw {
  explicit Draw(uint64_t seed) : rng(seed) {}
  double uniform() { return rng.drawUniform(); }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  double normal() {
    const double u = std::max(uniform(), 1e-300), v = uniform();
    return std::sqrt(-2 * std::log(u)) * std::cos(2 * M_PI * v);
  }
  PortableRandom rng;
};

struct HiddenEffect {
  std::string scenario;                 ///< absolute path
  std::vector<std::string> overrides;   ///< the hidden effect
  double start = 2, stop = 8, step = 0.5;  ///< speeds of the eigenvalue rows, m/s
  std::vector<std::string> modes{"weave"};
  double relativeNoise = 0.01;          ///< noise std as a fraction of each mode's RMS |real| and |imag|
  double absoluteNoise = 0.01;          ///< plus this, 1/s
  bool withStderr = false;              ///< write real_stderr/imag_stderr columns
  uint64_t seed = 1;
  double runNoiseRho = 0;               ///< responses: AR(1) noise e_t = rho e_{t-1} + sqrt(1 - rho^2) w_t (stationary)
  int runSamples = 300;                 ///< responses: samples per run (0.01 s apart)
  double steerRateAmplitude = 0;        ///< > 0: written as the data's steer_rate_amplitude_rad_s (rad/s)
};

inline std::string writeEigenvalueData(const HiddenEffect& h, const std::filesystem::path& dir, Draw& draw) {
  const Scenario s = loadScenario(h.scenario, h.overrides);
  const VehicleModel model(s);
  SweepOptions opt;
  opt.start = h.start, opt.stop = h.stop, opt.step = h.step;
  const SweepResult sweep = runSweep(model, opt);
  std::string csv = h.withStderr ? "speed_mps,mode,real,imag,real_stderr,imag_stderr\n" : "speed_mps,mode,real,imag\n";
  for (const auto& mode : h.modes)
    for (const auto& b : sweep.branches) {
      if (analysis::toString(b.label) != mode) continue;
      double scaleRe = 0, scaleIm = 0;
      for (const auto& l : b.eigenvalue) scaleRe += l.real() * l.real() / b.eigenvalue.size(), scaleIm += l.imag() * l.imag() / b.eigenvalue.size();
      const double sr = h.relativeNoise * std::sqrt(scaleRe) + h.absoluteNoise, si = h.relativeNoise * std::sqrt(scaleIm) + h.absoluteNoise;
      for (size_t k = 0; k < sweep.speeds.size(); ++k) {
        const auto l = b.eigenvalue[k];
        const double im = std::abs(l.imag()) > 1e-9 ? std::abs(l.imag()) + si * draw.normal() : 0.0;
        csv += formatNumber(sweep.speeds[k]) + "," + mode + "," + formatNumber(l.real() + sr * draw.normal()) + "," +
               formatNumber(std::max(im, 0.0));
        if (h.withStderr) csv += "," + formatNumber(sr) + "," + formatNumber(si);
        csv += "\n";
      }
      break;
    }
  std::ofstream(dir / "eigenvalues.csv") << csv;
  return "eigenvalues:\n  - file: eigenvalues.csv\n";
}

/// Linear free responses (roll rate calibrated, steer angle with an unknown gain) at `speeds`.
inline std::string writeResponseData(const HiddenEffect& h, const std::vector<double>& speeds, double noise,
                                     const std::filesystem::path& dir, Draw& draw) {
  const Scenario s = loadScenario(h.scenario, h.overrides);
  const VehicleModel model(s);
  std::string yaml = "responses:\n";
  for (size_t r = 0; r < speeds.size(); ++r) {
    TrimResult trim = calcTrim(model, speeds[r]);
    const LinearModel lin = linearize(model, trim);
    const int roll = lin.findState("roll"), rollRate = lin.findState("roll_rate"), steer = lin.findState("steer");
    Eigen::VectorXd x0 = Eigen::VectorXd::Zero(lin.A.rows());
    x0(roll) = draw.uniform(0.02, 0.05), x0(rollRate) = draw.uniform(-0.3, 0.3), x0(steer) = draw.uniform(-0.05, 0.05);
    const double gain = draw.uniform(2, 5), offset = draw.uniform(-0.5, 0.5), dt = 0.01;
    const Eigen::MatrixXd step = (lin.A * dt).exp();
    std::string csv = "time_s,roll_rate_radps,steer_V\n";
    Eigen::VectorXd x = x0;
    const double rho = h.runNoiseRho, innovation = std::sqrt(1 - rho * rho);
    double e1 = draw.normal(), e2 = draw.normal();  // stationary start
    for (int i = 0; i < h.runSamples; ++i, x = step * x) {
      if (i > 0) e1 = rho * e1 + innovation * draw.normal(), e2 = rho * e2 + innovation * draw.normal();
      csv += formatNumber(i * dt) + "," + formatNumber(x(rollRate) + noise * e1) + "," +
             formatNumber(gain * x(steer) + offset + noise * gain * e2) + "\n";
    }
    const std::string name = "run" + std::to_string(r + 1) + ".csv";
    std::ofstream(dir / name) << csv;
    yaml += "  - file: " + name + "\n    speed_mps: " + formatNumber(speeds[r]) + "\n    time_column: time_s\n"
            "    signals:\n      - {column: roll_rate_radps, quantity: roll_rate}\n"
            "      - {column: steer_V, quantity: steer_angle, scale: free}\n";
  }
  return yaml;
}

/// Writes dir/measured.yaml with eigenvalues (if `eigen`) and response runs at `runSpeeds`.
inline std::string writeHiddenEffectData(const HiddenEffect& h, const std::filesystem::path& dir, bool eigen,
                                         const std::vector<double>& runSpeeds = {}, double runNoise = 0.002) {
  std::filesystem::create_directories(dir);
  Draw draw(h.seed);
  std::string yaml = "name: hidden-effect\n";
  if (eigen) yaml += writeEigenvalueData(h, dir, draw);
  if (!runSpeeds.empty()) yaml += writeResponseData(h, runSpeeds, runNoise, dir, draw);
  if (h.steerRateAmplitude > 0) yaml += "steer_rate_amplitude_rad_s: " + formatNumber(h.steerRateAmplitude) + "\n";
  std::ofstream(dir / "measured.yaml") << yaml;
  return (dir / "measured.yaml").string();
}

}  // namespace motostab::testing

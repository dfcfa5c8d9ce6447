// Schema of the files `motostab sweep` and `motostab linearize` write (docs/commands.md, "Output files"):
// eigenvalues.csv, summary.json, A.csv, B.csv, eigenvectors.csv, linear_model.json. Written from
// random results drawn here, then read back and checked against the definitions there
// (frequency = imag/2pi, damping ratio = -real/|lambda|, seed eq. 27, empty at a zero root; 17 digits round-trip).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <string>
#include <vector>

#include "core/portable_random.h"
#include "nlohmann/json.hpp"
#include "output/sweep_output.h"
#include "scenario/scenario.h"
#include "tests/support/temp_dir.h"
#include "tests/support/text_csv.h"

namespace motostab::output {

using analysis::LinearModel;
using analysis::ModeBranch;
using analysis::SweepResult;
using analysis::TrimOptions;
using analysis::calcTrim;
using analysis::linearize;
using analysis::ModeLabel;
using core::PortableRandom;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

using cd = std::complex<double>;

// A sweep over a random grid: a weave pair, capsize, castor, wobble pair and a zero neutral mode,
// with random real parts that change sign, and made-up critical speeds (the writer only copies them).
SweepResult makeRandomSweep(PortableRandom& rng) {
  SweepResult s;
  const int n = 5 + static_cast<int>(rng.drawUniform() * 8);
  const double start = rng.drawUniform(0, 3), step = rng.drawUniform(0.1, 1.5);
  for (int k = 0; k < n; ++k) s.speeds.push_back(start + k * step);
  // Each speed's label at random among the branch's own and `other` (labels are per speed).
  auto drawLabels = [&](ModeLabel label) {
    std::vector<ModeLabel> l;
    for (int k = 0; k < n; ++k) l.push_back(rng.drawUniform() < 0.8 ? label : ModeLabel::Other);
    return l;
  };
  auto addPair = [&](ModeLabel label) {
    ModeBranch a{label, drawLabels(label), {}, {}}, b = a;
    for (int k = 0; k < n; ++k) {
      const cd l(rng.drawNormal(-1.2, 1), std::abs(rng.drawNormal(0, 5)) + 0.1);
      a.eigenvalue.push_back(l), b.eigenvalue.push_back(std::conj(l));
    }
    s.branches.push_back(a), s.branches.push_back(b);
  };
  auto addReal = [&](ModeLabel label, double scale) {
    ModeBranch b{label, drawLabels(label), {}, {}};
    if (label == ModeLabel::Neutral) b.labels.assign(n, label);
    for (int k = 0; k < n; ++k) b.eigenvalue.push_back(cd(scale * rng.drawNormal(-1.2, 1), 0));
    s.branches.push_back(b);
  };
  addPair(ModeLabel::Weave), addReal(ModeLabel::Capsize, 1), addReal(ModeLabel::Castor, 10), addPair(ModeLabel::Wobble),
      addReal(ModeLabel::Neutral, 0);
  s.criticalSpeeds = {{ModeLabel::Weave, rng.drawUniform(0, 10), true, 1.5},
                      {ModeLabel::Capsize, rng.drawUniform(0, 10), false, 0.0},
                      {ModeLabel::Weave, rng.drawUniform(10, 20), false, 2.5}};
  s.failures = {{rng.drawUniform(0, 20), rng.drawUniform(0, 1), "trim failed"}};
  return s;
}

// Stable grid ranges as docs/commands.md defines them: runs of grid speeds where every mode but the
// neutral one has a negative real part.
std::vector<std::pair<double, double>> calcStableRanges(const SweepResult& s) {
  std::vector<std::pair<double, double>> out;
  bool open = false;
  for (size_t k = 0; k < s.speeds.size(); ++k) {
    bool stable = true;
    for (const auto& b : s.branches) stable = stable && (b.labels[k] == ModeLabel::Neutral || b.eigenvalue[k].real() < 0);
    if (stable && open) out.back().second = s.speeds[k];
    if (stable && !open) out.push_back({s.speeds[k], s.speeds[k]});
    open = stable;
  }
  return out;
}

void expectFrequencyAndDamping(cd l, const std::string& freqCell, const std::string& dampCell) {
  EXPECT_NEAR(parseCell(freqCell), l.imag() / (2 * M_PI), 1e-15 * (1 + std::abs(l.imag())));
  if (std::abs(l) == 0)
    EXPECT_EQ(dampCell, "");  // undefined: an empty cell, never "nan"
  else
    EXPECT_NEAR(parseCell(dampCell), -l.real() / std::abs(l), 1e-15);
}

TEST(SweepOutput, EigenvaluesCsvAndSummaryJsonFollowTheReadme) {
  PortableRandom rng(20261124);
  for (int trial = 0; trial < 5; ++trial) {
    const SweepResult s = makeRandomSweep(rng);
    const auto dir = makeTempDir("sweep_output_" + std::to_string(trial));
    writeSweepData(dir, "random-bike", s);

    const TextCsv csv = readTextCsv(dir / "eigenvalues.csv");
    ASSERT_EQ(csv.header, (std::vector<std::string>{"speed_mps", "mode", "real", "imag", "frequency_hz", "damping_ratio"}));
    ASSERT_EQ(csv.rows.size(), s.speeds.size() * s.branches.size());
    size_t row = 0;
    for (size_t k = 0; k < s.speeds.size(); ++k)
      for (const auto& b : s.branches) {
        const auto& r = csv.rows[row++];
        EXPECT_EQ(parseCell(r[0]), s.speeds[k]);  // 17 digits: exact
        EXPECT_EQ(r[1], toString(b.labels[k]));  // each speed's own label
        EXPECT_EQ(parseCell(r[2]), b.eigenvalue[k].real());
        EXPECT_EQ(parseCell(r[3]), b.eigenvalue[k].imag());
        expectFrequencyAndDamping(b.eigenvalue[k], r[4], r[5]);
      }

    std::ifstream in(dir / "summary.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j.at("scenario"), "random-bike");
    EXPECT_EQ(j.at("speeds_mps").at("start").get<double>(), s.speeds.front());
    EXPECT_EQ(j.at("speeds_mps").at("stop").get<double>(), s.speeds.back());
    EXPECT_EQ(j.at("speeds_mps").at("count").get<size_t>(), s.speeds.size());
    ASSERT_EQ(j.at("critical_speeds").size(), s.criticalSpeeds.size());
    for (size_t i = 0; i < s.criticalSpeeds.size(); ++i) {
      const auto& c = j["critical_speeds"][i];
      EXPECT_EQ(c.at("mode"), toString(s.criticalSpeeds[i].mode));
      EXPECT_EQ(c.at("speed_mps").get<double>(), s.criticalSpeeds[i].speed);
      EXPECT_EQ(c.at("direction"), s.criticalSpeeds[i].stabilising ? "stabilising" : "destabilising");
      EXPECT_EQ(c.at("frequency_hz").get<double>(), s.criticalSpeeds[i].frequency);
      EXPECT_TRUE(c.at("refined").get<bool>());
    }
    ASSERT_EQ(j.at("failed_speeds").size(), 1u);
    EXPECT_EQ(j["failed_speeds"][0].at("speed_mps").get<double>(), s.failures[0].speed);
    EXPECT_EQ(j["failed_speeds"][0].at("residual").get<double>(), s.failures[0].residual);
    // First critical speed of each mode, null when it has none.
    EXPECT_EQ(j.at("weave_speed_mps").get<double>(), s.criticalSpeeds[0].speed);
    EXPECT_EQ(j.at("capsize_speed_mps").get<double>(), s.criticalSpeeds[1].speed);
    EXPECT_TRUE(j.at("wobble_speed_mps").is_null());
    const auto ranges = calcStableRanges(s);
    ASSERT_EQ(j.at("stable_grid_ranges_mps").size(), ranges.size()) << j.dump();
    for (size_t i = 0; i < ranges.size(); ++i) {
      EXPECT_EQ(j["stable_grid_ranges_mps"][i][0].get<double>(), ranges[i].first);
      EXPECT_EQ(j["stable_grid_ranges_mps"][i][1].get<double>(), ranges[i].second);
    }
  }
}

// `motostab linearize` labels each eigenvalue from its content at the one speed (labelModes): the
// Whipple bicycle at 5 m/s has Meijaard et al. (2007) Table 2's weave pair
// -0.77534188219585 +/- 4.46486771378823i, capsize -0.32286642900409 and castor -14.07838969279820.
TEST(SweepOutput, LinearModelEigenvaluesNameTheirModes) {
  const Scenario scenario = loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml");
  const VehicleModel model(scenario);
  const LinearModel lin = linearize(model, calcTrim(model, 5.0, TrimOptions()));
  const auto dir = makeTempDir("linear_output_modes");
  writeLinearModel(dir, lin);
  const TextCsv ev = readTextCsv(dir / "eigenvalues.csv");
  const std::vector<std::pair<std::string, cd>> table2{{"weave", {-0.77534188219585, 4.46486771378823}},
                                                       {"weave", {-0.77534188219585, -4.46486771378823}},
                                                       {"capsize", {-0.32286642900409, 0}},
                                                       {"castor", {-14.07838969279820, 0}}};
  for (const auto& [mode, value] : table2) {
    int found = 0;
    for (const auto& r : ev.rows)
      if (std::abs(cd(parseCell(r[2]), parseCell(r[3])) - value) < 1e-6) {
        EXPECT_EQ(r[1], mode) << value;
        ++found;
      }
    EXPECT_EQ(found, 1) << value;
  }
}

TEST(SweepOutput, LinearModelFilesFollowTheReadme) {
  PortableRandom rng(77);
  LinearModel lin;
  lin.speed = rng.drawUniform(0, 20);
  const int n = 5, m = 3;
  for (const char* name : {"roll", "steer", "roll_rate", "vx", "steer_rate"}) lin.states.push_back({name, {}});
  lin.inputNames = {"steer_torque", "drive_torque", "roll_torque"};
  lin.A.resize(n, n), lin.B.resize(n, m), lin.eigenvectors.resize(n, n), lin.eigenvalues.resize(n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) lin.A(i, j) = rng.drawNormal(), lin.eigenvectors(i, j) = cd(rng.drawNormal(), rng.drawNormal());
    for (int j = 0; j < m; ++j) lin.B(i, j) = rng.drawNormal();
    lin.eigenvalues[i] = i == 3 ? cd(0, 0) : cd(rng.drawNormal(), rng.drawNormal());
  }
  const auto dir = makeTempDir("linear_output");
  lin.labels.assign(n - 1, ModeLabel::Weave);
  EXPECT_THROW(writeLinearModel(dir, lin), std::logic_error);
  lin.labels.clear();
  for (int k = 0; k < n; ++k)
    lin.labels.push_back(std::vector<ModeLabel>{ModeLabel::Weave, ModeLabel::Capsize, ModeLabel::Castor, ModeLabel::Other}[rng.drawIndex(4)]);
  writeLinearModel(dir, lin);

  auto expectMatrix = [&](const std::string& file, const Eigen::MatrixXd& M, const std::vector<std::string>& cols) {
    const TextCsv t = readTextCsv(dir / file);
    std::vector<std::string> header{"state"};
    header.insert(header.end(), cols.begin(), cols.end());
    ASSERT_EQ(t.header, header) << file;
    ASSERT_EQ(t.rows.size(), static_cast<size_t>(M.rows())) << file;
    for (int i = 0; i < M.rows(); ++i) {
      EXPECT_EQ(t.rows[i][0], lin.states[i].name);
      for (int j = 0; j < M.cols(); ++j) EXPECT_EQ(parseCell(t.rows[i][j + 1]), M(i, j)) << file;
    }
  };
  std::vector<std::string> names;
  for (const auto& s : lin.states) names.push_back(s.name);
  expectMatrix("A.csv", lin.A, names);
  expectMatrix("B.csv", lin.B, lin.inputNames);

  const TextCsv ev = readTextCsv(dir / "eigenvalues.csv");
  ASSERT_EQ(ev.header, (std::vector<std::string>{"index", "mode", "real", "imag", "frequency_hz", "damping_ratio"}));
  ASSERT_EQ(ev.rows.size(), static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    EXPECT_EQ(ev.rows[k][0], std::to_string(k));
    EXPECT_EQ(ev.rows[k][1], toString(lin.labels[k]));
    EXPECT_EQ(parseCell(ev.rows[k][2]), lin.eigenvalues[k].real());
    EXPECT_EQ(parseCell(ev.rows[k][3]), lin.eigenvalues[k].imag());
    expectFrequencyAndDamping(lin.eigenvalues[k], ev.rows[k][4], ev.rows[k][5]);
  }
  const TextCsv vec = readTextCsv(dir / "eigenvectors.csv");
  ASSERT_EQ(vec.header.size(), static_cast<size_t>(1 + 2 * n));
  for (int k = 0; k < n; ++k) {
    ASSERT_EQ(vec.header[1 + 2 * k], "re_" + std::to_string(k));
    ASSERT_EQ(vec.header[2 + 2 * k], "im_" + std::to_string(k));
  }
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      EXPECT_EQ(parseCell(vec.rows[i][1 + 2 * k]), lin.eigenvectors(i, k).real());
      EXPECT_EQ(parseCell(vec.rows[i][2 + 2 * k]), lin.eigenvectors(i, k).imag());
    }

  std::ifstream in(dir / "linear_model.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("speed_mps").get<double>(), lin.speed);
  EXPECT_EQ(j.at("states").get<std::vector<std::string>>(), names);
  EXPECT_EQ(j.at("inputs").get<std::vector<std::string>>(), lin.inputNames);
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < n; ++c) EXPECT_EQ(j["A"][i][c].get<double>(), lin.A(i, c));
    for (int c = 0; c < m; ++c) EXPECT_EQ(j["B"][i][c].get<double>(), lin.B(i, c));
    EXPECT_EQ(j["eigenvalues"][i][0].get<double>(), lin.eigenvalues[i].real());
    EXPECT_EQ(j["eigenvalues"][i][1].get<double>(), lin.eigenvalues[i].imag());
  }
}

}  // namespace
}  // namespace motostab::output

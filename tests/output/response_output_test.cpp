// The writer of `identify response` and `simulate --identify`: modes.json holds the generating parameters
// of a synthetic record, and the data, fit and plot files are written beside it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "output/response_output.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;

// y = 0.2 + 1.3 e^{-0.5 t} cos(4 t + 0.6), 0..6 s in steps of 0.01 s.
motostab::response::ResponseRecord makeRecord() {
  motostab::response::ResponseRecord r;
  r.source = "synthetic";
  r.timeColumn = "time_s";
  r.signalColumns = {"roll_rate"};
  r.signals.resize(1);
  for (int i = 0; i <= 600; ++i) {
    const double t = 0.01 * i;
    r.time.push_back(t);
    r.signals[0].push_back(0.2 + 1.3 * std::exp(-0.5 * t) * std::cos(4 * t + 0.6));
  }
  return r;
}

TEST(ResponseOutput, WritesModesJsonAndPlot) {
  const auto record = makeRecord();
  const auto result = motostab::response::identifyModes(record.time, record.signals);
  const fs::path out = makeTempDir("response_output") / "out";
  motostab::output::writeResponseReport(out, record, result);
  std::ifstream in(out / "modes.json");
  const auto j = nlohmann::json::parse(in);
  ASSERT_EQ(j.at("modes").size(), 1u);
  const auto& m = j.at("modes")[0];
  EXPECT_NEAR(m.at("real").get<double>(), -0.5, 1e-8);
  EXPECT_NEAR(m.at("imag").get<double>(), 4.0, 1e-8);
  EXPECT_NEAR(m.at("frequency_hz").get<double>(), 4.0 / (2 * M_PI), 1e-8);
  EXPECT_NEAR(m.at("damping_ratio").get<double>(), 0.5 / std::hypot(0.5, 4.0), 1e-8);
  EXPECT_NEAR(m.at("amplitude")[0].get<double>(), 1.3, 1e-8);
  EXPECT_NEAR(m.at("phase_rad")[0].get<double>(), 0.6, 1e-8);
  EXPECT_NEAR(j.at("offset")[0].get<double>(), 0.2, 1e-8);
  EXPECT_GT(j.at("fit").at("r_squared").get<double>(), 1 - 1e-12);
  EXPECT_EQ(j.at("signals")[0], "roll_rate");
  EXPECT_EQ(j.at("source").at("time_column"), "time_s");
  for (const char* f : {"response_fit.png", "response_fit.svg", "response_fit.gp", "response_fit.csv",
                        "response_data.csv"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
}

// makeModesJson rejects a name list that does not match the signals; the table names each signal.
TEST(ResponseOutput, ModesJsonNeedsOneNamePerSignal) {
  const auto record = makeRecord();
  const auto result = motostab::response::identifyModes(record.time, record.signals);
  EXPECT_THROW(motostab::output::makeModesJson(result, {"a", "b"}), std::logic_error);  // a caller's bug
  const std::string table = motostab::output::formatModesTable(result, {"roll_rate"});
  EXPECT_NE(table.find("roll_rate: offset 0.2"), std::string::npos) << table;
  EXPECT_NE(table.find("order 2"), std::string::npos) << table;
}

}  // namespace

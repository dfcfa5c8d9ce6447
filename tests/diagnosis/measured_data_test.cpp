// loadMeasuredData: the pinned format and every bad input it names by file and line.
#include "diagnosis/measured_data.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace motostab::diagnosis {

using io::InputError;

namespace {

namespace fs = std::filesystem;

class MeasuredDataTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("motostab-measured-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    write("weave.csv", "# comment\nspeed_mps,mode,real,imag,speed_min_mps,speed_max_mps\n4,weave,-0.5,4.2,3.8,4.3\n5,,-1,5,5,5\n");
    std::string run = "t,gyro,v\n";
    for (int i = 0; i < 40; ++i) run += std::to_string(0.01 * i) + "," + std::to_string(0.1 * i) + ",5\n";
    write("run.csv", run);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
  std::string yaml(const std::string& text) {
    write("m.yaml", text);
    return (dir_ / "m.yaml").string();
  }
  // The InputError message of loading `text`, or "" when it loads.
  std::string error(const std::string& text) {
    try {
      loadMeasuredData(yaml(text));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
  const std::string run_ =
      "responses:\n  - file: run.csv\n    speed_column: v\n    time_column: t\n    window_s: [0.05, 0.35]\n"
      "    signals:\n      - {column: gyro, quantity: roll_rate, scale: free}\n";
};

TEST_F(MeasuredDataTest, ReadsEigenvaluesAndRuns) {
  const MeasuredData d = loadMeasuredData(yaml("name: x\neigenvalues:\n  - file: weave.csv\n" + run_));
  ASSERT_EQ(d.eigenvalues.size(), 2u);
  EXPECT_EQ(d.eigenvalues[0].mode, analysis::ModeLabel::Weave);
  EXPECT_TRUE(d.eigenvalues[0].hasRange);
  EXPECT_DOUBLE_EQ(d.eigenvalues[0].speedMin, 3.8);
  EXPECT_FALSE(d.eigenvalues[1].mode.has_value());
  EXPECT_EQ(d.eigenvalues[1].where.line, 4);
  ASSERT_EQ(d.responses.size(), 1u);
  EXPECT_EQ(d.responses[0].time.size(), 31u);  // 0.05 ... 0.35 s at 0.01 s
  EXPECT_DOUBLE_EQ(d.responses[0].speed, 5);
  EXPECT_TRUE(d.responses[0].signals[0].freeScale);
}

TEST_F(MeasuredDataTest, BadEigenvalueFilesNameFileAndLine) {
  write("nocol.csv", "speed_mps,mode,real\n4,weave,1\n");
  EXPECT_NE(error("eigenvalues:\n  - file: nocol.csv\n").find("nocol.csv:1: imag"), std::string::npos);
  write("nan.csv", "speed_mps,mode,real,imag\n4,weave,nan,1\n");
  EXPECT_NE(error("eigenvalues:\n  - file: nan.csv\n").find("nan.csv:2"), std::string::npos);
  write("neg.csv", "speed_mps,mode,real,imag,real_stderr,imag_stderr\n4,weave,1,1,0.1,0.1\n4,weave,1,1,-0.1,0.1\n");
  EXPECT_NE(error("eigenvalues:\n  - file: neg.csv\n").find("neg.csv:3"), std::string::npos);
  write("mode.csv", "speed_mps,mode,real,imag\n\n4,wiggle,1,1\n");
  EXPECT_NE(error("eigenvalues:\n  - file: mode.csv\n").find("mode.csv:3"), std::string::npos);
  EXPECT_NE(error("eigenvalues:\n  - file: absent.csv\n").find("m.yaml:2:5"), std::string::npos);
}

TEST_F(MeasuredDataTest, BadYamlNamesKeyAndLine) {
  EXPECT_NE(error("eigenvalues:\n  - file: weave.csv\ncolour: red\n").find("m.yaml:3:1: colour"), std::string::npos);
  std::string shortWindow = run_;
  shortWindow.replace(shortWindow.find("[0.05, 0.35]"), 12, "[0.05, 0.1]");
  EXPECT_NE(error(shortWindow).find("window_s"), std::string::npos);
  std::string quantity = run_;
  quantity.replace(quantity.find("roll_rate"), 9, "pitch_rate");
  EXPECT_NE(error(quantity).find("m.yaml:7"), std::string::npos);
  EXPECT_NE(error("name: empty\n").find("no measurements"), std::string::npos);
}

}  // namespace
}  // namespace motostab::diagnosis

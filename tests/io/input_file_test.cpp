// Input files (io/input_file.h): regular files of bounded size only, read whole, and recorded as the
// run's inputs.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "tests/support/catch_input_error.h"
#include "tests/support/temp_dir.h"
#include "io/input_file.h"

namespace motostab::io {
namespace {
namespace fs = std::filesystem;

using motostab::test::catchInputError;

TEST(InputFile, ReadsARegularFileWholeAndRecordsIt) {
  const fs::path dir = makeTempDir("input_file_read");
  std::string content;
  for (int i = 0; i < 100000; ++i) content += static_cast<char>('a' + i % 26);  // more than one read buffer
  std::ofstream(dir / "a.txt", std::ios::binary) << content;
  EXPECT_EQ(readInputFile(dir / "a.txt"), content);
  const auto inputs = getInputFiles();
  EXPECT_NE(std::find(inputs.begin(), inputs.end(), fs::canonical(dir / "a.txt")), inputs.end());
}

// Devices (/dev/zero would be read forever), folders, FIFOs (an open would block) and missing files are
// InputErrors naming the file and what it is, before anything is read.
TEST(InputFile, OnlyRegularFiles) {
  const fs::path dir = makeTempDir("input_file_kinds");
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  const std::pair<fs::path, std::string> cases[] = {
      {"/dev/zero", "is a device"}, {dir, "is a folder"}, {dir / "pipe", "is a pipe"}, {dir / "missing", "cannot open"}};
  for (const auto& [path, needle] : cases) {
    const InputError e = catchInputError([&] { readInputFile(path); });
    EXPECT_EQ(e.getLocation().file, path.string());
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    EXPECT_THROW(requireInputFile(path), InputError) << path;
  }
}

TEST(InputFile, SizeIsBounded) {
  const fs::path dir = makeTempDir("input_file_size");
  std::ofstream(dir / "big.txt") << std::string(1001, 'x');
  EXPECT_EQ(readInputFile(dir / "big.txt", 1001).size(), 1001u);
  const InputError e = catchInputError([&] { readInputFile(dir / "big.txt", 1000); });
  EXPECT_NE(std::string(e.what()).find("more than the 1000 bytes"), std::string::npos) << e.what();
}

TEST(InputFile, ByteOrderMarkIsStripped) {
  EXPECT_EQ(stripByteOrderMark("\xEF\xBB\xBFspeed_mps"), "speed_mps");
  EXPECT_EQ(stripByteOrderMark("speed_mps"), "speed_mps");
  EXPECT_EQ(stripByteOrderMark("\xEF\xBB"), "\xEF\xBB");
}

}  // namespace
}  // namespace motostab::io

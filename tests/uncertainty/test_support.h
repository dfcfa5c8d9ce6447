#pragma once
// Shared helpers of the uncertainty tests: scenario files with an uncertainty section, each in its
// own temporary folder.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/temp_dir.h"

namespace motostab::test {

inline std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// A copy of a bundled scenario with `section` appended, in a fresh temporary folder.
inline std::string writeScenarioWith(const std::string& bundled, const std::string& section, const std::string& tag) {
  const auto dir = makeTempDir("uq-" + tag);
  const auto file = dir / "scenario.yaml";
  std::ofstream(file) << readText(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/" + bundled) << "\n" << section;
  return file.string();
}

/// "uncertainty:\n  path: sigma\n..." with 17 significant digits.
inline std::string makeSection(const std::vector<std::pair<std::string, double>>& entries) {
  std::ostringstream s;
  s.precision(17);
  s << "uncertainty:\n";
  for (const auto& [path, sigma] : entries) s << "  " << path << ": " << sigma << "\n";
  return s.str();
}

}  // namespace motostab::test

#pragma once
// Shared helpers of the uncertainty tests: a portable seeded generator and scenario files with an
// uncertainty section.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace motostab::test {

/// Uniform in [a, b) from the top 53 bits of std::mt19937_64 (portable, unlike uniform_real_distribution).
inline double drawUniformIn(std::mt19937_64& g, double a, double b) {
  return a + (b - a) * static_cast<double>(g() >> 11) * 0x1.0p-53;
}

inline std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// A copy of a bundled scenario with `section` appended, in a fresh temporary folder.
inline std::string writeScenarioWith(const std::string& bundled, const std::string& section, const std::string& tag) {
  const auto dir = std::filesystem::temp_directory_path() / ("motostab-uq-" + tag);
  std::filesystem::create_directories(dir);
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

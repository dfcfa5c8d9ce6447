#pragma once
// Import of BicycleParameters benchmark parameter files (Moore et al. 2010; `name = value+/-sigma`),
// given in the Meijaard et al. (2007) frame: x forward, y right, z down, origin at the rear contact.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace motostab::scenario {

/// One parameter of a benchmark file: its value (the file's unit; lam in rad), its standard deviation
/// (0 without `+/-`) and its line.
struct BicycleParameter {
  double value = 0, sigma = 0;
  int line = 0;  ///< 1-based
};

/// Reads `name = value+/-sigma` lines (`+/-sigma` optional; several comma-separated repeats are averaged,
/// their sigma is sqrt(sum sigma_k^2) / n). Strict: an unknown name, a name given twice, a value or sigma
/// that is not a finite decimal number (a negative sigma, `+/-abc`, `+/-0x10`) or an empty repeat is an
/// InputError naming file, line and parameter. The file must be a regular file (io/input_file.h).
std::map<std::string, BicycleParameter> readBicycleParameterFile(const std::string& file);

/// The values of readBicycleParameterFile.
std::map<std::string, double> readBicycleParameters(const std::string& file);

/// Import settings.
struct BicycleImportOptions {
  bool repairInertia = false;  ///< move a frame's I_yy onto the triangle-inequality bound (see repairFrameInertias)
};

/// One inertia lowered by the repair.
struct InertiaRepair {
  std::string key;             ///< parameter, e.g. "IByy"
  double before = 0, after = 0;  ///< kg m^2
  std::string explanation;     ///< which principal moment broke the inequality and by how much
};

/// Why the measured inertia of frame `s` ("B" rear frame, "H" front frame) is physically impossible, or ""
/// if it is not: the principal moments, the one exceeding the sum of the other two (I_c > I_a + I_b) and
/// by how much (kg m^2 and %). Needs the I<s>xx, yy, zz, xz keys (xy, yz optional, 0).
std::string explainFrameInertia(const std::map<std::string, double>& parameters, const std::string& s);

/// Moves I<s>yy of each frame (s = B, H) whose inertia breaks the triangle inequality just onto the
/// violated bound. For a frame symmetric about the x-z plane (I_xy = I_yz = 0, as the format assumes) y is
/// principal and the inequality reads |l_1 - l_2| <= I_yy <= l_1 + l_2 = I_xx + I_zz (l_1, l_2 the x-z
/// principal moments): I_yy too large is lowered to I_xx + I_zz (Browser rear frame), too small raised to
/// |l_1 - l_2| (Yellow, Yellowrev front frames, whose largest moment is about an axis near x). Why y: the
/// linearised Whipple model (Meijaard et al. 2007, App. A) uses only I_xx, I_xz and I_zz of the frames
/// (roll and yaw about x and z); pitch I_yy is absent, so the eigenvalues are those of the file's values.
/// A frame with I_xy or I_yz is an InputError. Returns the changes (kg m^2).
std::vector<InertiaRepair> repairFrameInertias(std::map<std::string, double>& parameters, const std::string& file);

/// A scenario YAML text for the bicycle in `file`, with the rolling_no_slip contact. Missing
/// required parameters are InputErrors naming the parameter. A frame inertia breaking the triangle
/// inequality is an InputError with explainFrameInertia's reason unless options.repairInertia, which
/// repairs it (repairFrameInertias) and lists the changes in `repairs` and in the scenario's comments.
/// The scenario name is written quoted, so names such as "null", "1" or "true" stay strings.
std::string convertBicycleParametersToScenario(const std::string& file, const std::string& name,
                                               const BicycleImportOptions& options = {},
                                               std::vector<InertiaRepair>* repairs = nullptr);

/// Writes the scenario of `file` (convertBicycleParametersToScenario, with the `uncertainty:` section of
/// its sigmas) to `out`, atomically and only once it loads as a scenario: an error in the converted
/// scenario is an InputError at the parameter file's line of the parameters behind it, and `out` is
/// left as it was.
void writeBicycleParametersScenario(const std::string& file, const std::string& name, const std::filesystem::path& out,
                                    const BicycleImportOptions& options = {},
                                    std::vector<InertiaRepair>* repairs = nullptr);

/// `text` as a double-quoted YAML scalar (backslash, quote and control characters escaped).
std::string quoteYamlString(const std::string& text);

}  // namespace motostab::scenario

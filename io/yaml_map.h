#pragma once
// The one strict YAML input layer of motostab (scenarios, identification tests, plugin sections,
// measured data): every key must be consumed, a key given twice is an error (yaml-cpp alone would
// keep one silently), numbers go through parseFiniteNumber (io/number.h: no NaN or infinity), file
// names are relative to the file that names them, and every error names file:line:column and the
// key path ("rear_frame.mass_kg", "sensors[2].x").
#include <yaml-cpp/yaml.h>

#include <array>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "io/input_store.h"

namespace motostab::io {

/// A YAML mapping read strictly (Drake-style): a missing key, a wrong type, or a key that
/// finish() finds unused is an InputError naming file:line:column and the dotted key path. Every
/// number is finite and at most kMaxMagnitude in magnitude (io/number.h).
class YamlMap {
 public:
  /// `node` must be a mapping with unique scalar keys; else an InputError at it.
  YamlMap(const YAML::Node& node, std::string file, std::string path);
  /// The same, reading the files it names through `inputs` (io/input_store.h) and recording its
  /// warnings there; maps taken from it (getMap, getMapList, loadFileMap) share the store.
  YamlMap(const YAML::Node& node, std::string file, std::string path, std::shared_ptr<InputStore> inputs);

  bool has(const std::string& key) const;
  double getDouble(const std::string& key);
  /// A value that must be > 0 (masses, radii, lengths): at least kMinMagnitude (io/number.h).
  double getPositive(const std::string& key);
  /// A value that must be >= 0.
  double getNonNegative(const std::string& key);
  double getDouble(const std::string& key, double fallback);
  /// Optional value > 0 with a default.
  double getPositive(const std::string& key, double fallback);
  /// Optional value >= 0 with a default.
  double getNonNegative(const std::string& key, double fallback);
  /// A value that is 0 (the effect off) or at least `floor`, in `unit` (a delay, a relaxation
  /// length): smaller positive values are below anything physical and make the model numerically
  /// singular, so they are an InputError naming the floor.
  double getZeroOrAtLeast(const std::string& key, double floor, const std::string& unit);
  /// Optional such value with a default.
  double getZeroOrAtLeast(const std::string& key, double floor, const std::string& unit, double fallback);
  bool getBool(const std::string& key, bool fallback);
  std::string getString(const std::string& key);
  std::string getString(const std::string& key, const std::string& fallback);
  std::array<double, 3> getVec3(const std::string& key);
  std::vector<double> getDoubleList(const std::string& key);
  /// A list of exactly `size` finite numbers.
  std::vector<double> getDoubleList(const std::string& key, size_t size);
  std::vector<std::string> getStringList(const std::string& key);
  YamlMap getMap(const std::string& key);
  /// A list of mappings, each read strictly (key paths "key[i]"); finish() each.
  std::vector<YamlMap> getMapList(const std::string& key);
  /// A file name, relative to the folder of the file this map was read from unless absolute (the
  /// one rule for every path in every input file, docs/scenario-format.md). Not checked to exist.
  std::string getFilePath(const std::string& key);
  /// A list of such file names.
  std::vector<std::string> getFilePathList(const std::string& key);
  /// The text of the file named at `key` (getFilePath), at most `maxBytes`: through the store, read
  /// once and kept; without a store, read now (io/input_file.h).
  std::string readFileText(const std::string& key, std::uintmax_t maxBytes);
  /// The YAML file named at `key` as a root map (as loadYamlFile, read through readFileText).
  YamlMap loadFileMap(const std::string& key);
  /// Records a warning at `key` in the store (reported by the command that loaded the input; a
  /// library never prints). Without a store the warning is dropped.
  void warn(const std::string& key, const std::string& message) const;
  /// Marks a key as handled by someone else (e.g. a plugin's own parameters).
  void markUsed(const std::string& key);
  /// "missing key 'PATH.key' (keys given here: ...)": a typo of the missing key is usually among them.
  /// `alternative`, if given, is named as the key that may replace it.
  [[noreturn]] void failMissing(const std::string& key, const std::string& alternative = "") const;
  /// Throws InputError for the first key never read.
  void finish() const;
  /// The keys never read (nor marked used), in file order.
  std::vector<std::string> getUnreadKeys() const;

  /// Location of a key (or of this map when key is empty) for error messages.
  InputLocation locate(const std::string& key = "") const;
  /// An InputError at `key` with `message`.
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  /// An InputError at element `index` of the list under `key` (path "key[index]").
  [[noreturn]] void failElement(const std::string& key, size_t index, const std::string& message) const;

  const YAML::Node& getNode() const { return node_; }
  const std::string& getFile() const { return file_; }
  const std::string& getPath() const { return path_; }

 private:
  YAML::Node require(const std::string& key);
  YAML::Node requireList(const std::string& key);
  std::string childPath(const std::string& key) const;
  double toFinite(const YAML::Node& n, const std::string& key, size_t index) const;

  YAML::Node node_;
  std::string file_;
  std::string path_;
  std::shared_ptr<std::set<std::string>> used_;
  std::shared_ptr<InputStore> inputs_;
};

/// Nodes a YAML input may hold, each alias counted as the node it names.
constexpr long kMaxYamlNodes = 100000;

/// Parses YAML text (a file's content, or a --set value) within bounds: one document; an alias may name
/// only a complete node that holds no alias itself (aliases expand at most once); at most kMaxYamlNodes
/// nodes after expansion. A syntax error or a bound exceeded is an InputError at `file`, line, column,
/// with `key` as the key path.
YAML::Node parseYamlText(const std::string& text, const std::string& file, const std::string& key);

/// Loads a YAML file as the root map: a regular file of bounded size (io/input_file.h), parsed by
/// parseYamlText. Syntax errors and duplicate keys anywhere in the document are InputErrors with line and
/// column (a duplicate at its second occurrence).
YamlMap loadYamlFile(const std::string& file);

/// `name` as named in `namingFile`: unchanged if absolute, else relative to namingFile's folder; always
/// with a folder ("./x.so" for a file of the working folder, never a bare name).
std::string resolveRelativeTo(const std::string& namingFile, const std::string& name);

/// One segment of a key path such as `rear_frame.com_m[2]`: a mapping key and, optionally, a
/// sequence index into its value (-1: none).
struct KeyPathSegment {
  std::string key;
  int index = -1;
};
/// Splits "a.b[2].c" into segments; a malformed path is an InputError naming it.
std::vector<KeyPathSegment> parseKeyPath(const std::string& path);
/// The node at a key path, or an undefined node when absent; never modifies `root`.
YAML::Node findKeyPath(const YAML::Node& root, const std::string& path);

/// Applies "a.b.c=value" overrides (from --set) to a YAML tree; the value is parsed as YAML, and the
/// last key may be new (so a whole section can be added: `steer_damper={damping_Nms_per_rad: 0.4}`),
/// and missing intermediate maps are created (`swingarm.suspension.wheel_rate_N_per_m=2e4`); the
/// scenario reader validates what was created. Sequence elements are addressed as `key[i]`
/// (`rear_frame.com_m[2]=0.9`). A path through a non-map, an index out of range, or a value that
/// is not YAML is an InputError naming the override.
void applyOverride(YAML::Node& root, const std::string& assignment);

/// The key path and the value (read as YAML, its keys checked) of "a.b.c=value"; InputError naming
/// the assignment as applyOverride reports it.
struct ParsedOverride {
  std::string path;
  YAML::Node value;
};
ParsedOverride parseOverride(const std::string& assignment);

/// Sets the node at key path `path` of `root` to `value`, as applyOverride does (missing intermediate
/// maps created, `key[i]` addressing an existing element); `assignment` names the change in errors.
void setKeyPath(YAML::Node& root, const std::string& path, const YAML::Node& value, const std::string& assignment);

/// A deep copy of a YAML tree that keeps every node's mark (line and column), unlike YAML::Clone,
/// so that a copy reports errors at the places of the file the original was read from.
YAML::Node copyTree(const YAML::Node& node);

/// A scalar node holding `text`, marked at line 1, column 1 as a value parsed from `--set` text is.
YAML::Node makeOverrideScalar(const std::string& text);

/// How many times loadYamlFile has opened `file` in this process (as named; for tests that count reads).
long getYamlFileOpenCount(const std::string& file);

}  // namespace motostab::io

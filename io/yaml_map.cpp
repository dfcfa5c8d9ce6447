#include "io/yaml_map.h"

#include <yaml-cpp/eventhandler.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>

#include "io/csv.h"
#include "io/input_file.h"
#include "io/number.h"

// yaml-cpp 0.7 has no public setter of a node's mark: YAML::as_if is a friend of YAML::Node, and
// this specialisation for a motostab type uses that to reach the node's mark (copyTree).
namespace motostab::io {
struct NodeMarkSetter {};
}  // namespace motostab::io

template <>
struct YAML::as_if<motostab::io::NodeMarkSetter, void> {
  static void set(YAML::Node& node, const YAML::Mark& mark) {
    node.EnsureNodeExists();
    node.m_pNode->set_mark(mark);
  }
};

namespace motostab::io {
namespace {

void setNodeMark(YAML::Node& node, const YAML::Mark& mark) { YAML::as_if<NodeMarkSetter, void>::set(node, mark); }

InputLocation locationOf(const YAML::Node& n, const std::string& file, const std::string& path) {
  const YAML::Mark m = n.Mark();
  return {file, m.line >= 0 ? m.line + 1 : 0, m.column >= 0 ? m.column + 1 : 0, path};
}

std::string joinPath(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

// Keys of a mapping must be scalars and unique; `recursive` checks every mapping below it too.
void checkKeys(const YAML::Node& node, const std::string& file, const std::string& path, bool recursive) {
  if (node.IsSequence() && recursive) {
    for (size_t i = 0; i < node.size(); ++i) checkKeys(node[i], file, path + "[" + std::to_string(i) + "]", true);
  }
  if (!node.IsMap()) return;
  std::map<std::string, int> seen;  // key -> line of its first occurrence
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) throw InputError(locationOf(kv.first, file, path), "a key must be a plain name");
    const std::string k = kv.first.Scalar();
    const InputLocation at = locationOf(kv.first, file, joinPath(path, k));
    if (!seen.emplace(k, at.line).second)
      throw InputError(at, "duplicate key (first given on line " + std::to_string(seen[k]) + ")");
    if (recursive) checkKeys(kv.second, file, joinPath(path, k), true);
  }
}

// The bounds of a YAML text, checked on the parser's events before any tree is built: one document,
// each alias naming a complete node that holds no alias itself (so an alias expands at most once, never
// into further aliases), and at most kMaxYamlNodes nodes with every alias counted as the node it names.
class YamlBoundsCheck : public YAML::EventHandler {
 public:
  YamlBoundsCheck(std::string file, std::string key) : file_(std::move(file)), key_(std::move(key)) {}

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ > 1) fail(mark, "a second YAML document ('---'): a file holds one document");
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string&) override {
    leaf(mark, anchor);
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const auto it = anchors_.find(anchor);
    if (it == anchors_.end()) fail(mark, "an alias inside the node it names (a recursive alias)");
    if (it->second.holdsAlias)
      fail(mark, "an alias to a node that holds aliases itself: an alias is expanded at most once");
    add(mark, it->second.nodes, true);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Open {
    YAML::anchor_t anchor;
    long nodes;
    bool holdsAlias;
  };
  struct Anchored {
    long nodes;
    bool holdsAlias;
  };

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& why) const {
    throw InputError({file_, mark.line + 1, mark.column + 1, key_}, why);
  }
  void add(const YAML::Mark& mark, long nodes, bool alias) {
    total_ += nodes;
    if (total_ > kMaxYamlNodes)
      fail(mark, "more than " + std::to_string(kMaxYamlNodes) + " YAML nodes (aliases counted as the nodes they name)");
    if (!stack_.empty()) {
      stack_.back().nodes += nodes;
      stack_.back().holdsAlias = stack_.back().holdsAlias || alias;
    }
  }
  void leaf(const YAML::Mark& mark, YAML::anchor_t anchor) {
    add(mark, 1, false);
    if (anchor) anchors_[anchor] = {1, false};
  }
  void open(const YAML::Mark& mark, YAML::anchor_t anchor) {
    add(mark, 1, false);
    stack_.push_back({anchor, 0, false});
  }
  void close() {
    const Open done = stack_.back();
    stack_.pop_back();
    if (!stack_.empty()) {
      stack_.back().nodes += done.nodes;
      stack_.back().holdsAlias = stack_.back().holdsAlias || done.holdsAlias;
    }
    if (done.anchor) anchors_[done.anchor] = {done.nodes + 1, done.holdsAlias};
  }

  std::string file_, key_;
  int documents_ = 0;
  long total_ = 0;
  std::vector<Open> stack_;
  std::map<YAML::anchor_t, Anchored> anchors_;
};

}  // namespace

YAML::Node parseYamlText(const std::string& text, const std::string& file, const std::string& key) {
  try {
    std::istringstream events{text};
    YAML::Parser parser(events);
    YamlBoundsCheck bounds(file, key);
    while (parser.HandleNextDocument(bounds)) {
    }
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError({file, e.mark.line + 1, e.mark.column + 1, key}, "YAML syntax error: " + e.msg);
  }
}

YamlMap::YamlMap(const YAML::Node& node, std::string file, std::string path)
    : YamlMap(node, std::move(file), std::move(path), nullptr) {}

YamlMap::YamlMap(const YAML::Node& node, std::string file, std::string path, std::shared_ptr<InputStore> inputs)
    : node_(node), file_(std::move(file)), path_(std::move(path)),
      used_(std::make_shared<std::set<std::string>>()), inputs_(std::move(inputs)) {
  if (!node_.IsMap()) fail("", "expected a mapping of keys to values");
  checkKeys(node_, file_, path_, false);
}

std::string YamlMap::childPath(const std::string& key) const {
  return path_.empty() ? key : (key.empty() ? path_ : path_ + "." + key);
}

InputLocation YamlMap::locate(const std::string& key) const {
  if (!key.empty()) {
    for (const auto& kv : node_)
      if (kv.first.Scalar() == key) return locationOf(kv.first, file_, childPath(key));
  }
  return locationOf(node_, file_, childPath(key));
}

void YamlMap::fail(const std::string& key, const std::string& message) const {
  throw InputError(locate(key), message);
}

void YamlMap::failElement(const std::string& key, size_t index, const std::string& message) const {
  const YAML::Node list = static_cast<const YAML::Node&>(node_)[key];
  const std::string at = childPath(key) + "[" + std::to_string(index) + "]";
  if (list && list.IsSequence() && index < list.size()) throw InputError(locationOf(list[index], file_, at), message);
  InputLocation where = locate(key);
  where.key = at;
  throw InputError(where, message);
}

double YamlMap::toFinite(const YAML::Node& n, const std::string& key, size_t index) const {
  const auto v = n.IsScalar() ? parseFiniteNumber(n.Scalar()) : std::nullopt;
  const std::string got = n.IsScalar() ? " (got '" + n.Scalar() + "')" : "";
  const std::string why = !v ? "expected a finite number" + got
                             : std::abs(*v) > kMaxMagnitude ? "a magnitude above 1e12, beyond any physical parameter" + got
                                                            : "";
  if (why.empty()) return *v;
  if (index == static_cast<size_t>(-1)) fail(key, why);
  failElement(key, index, why);
}

bool YamlMap::has(const std::string& key) const { return static_cast<bool>(node_[key]); }

void YamlMap::markUsed(const std::string& key) { used_->insert(key); }

void YamlMap::failMissing(const std::string& key, const std::string& alternative) const {
  std::string given;
  for (const auto& kv : node_) given += (given.empty() ? "" : ", ") + kv.first.Scalar();
  const std::string other = alternative.empty() ? "" : " (or '" + childPath(alternative) + "')";
  fail("", "missing key '" + childPath(key) + "'" + other + " (keys given here: " + (given.empty() ? "none" : given) + ")");
}

YAML::Node YamlMap::require(const std::string& key) {
  const YAML::Node n = static_cast<const YAML::Node&>(node_)[key];
  if (!n) failMissing(key);
  used_->insert(key);
  return n;
}

double YamlMap::getDouble(const std::string& key) { return toFinite(require(key), key, static_cast<size_t>(-1)); }

double YamlMap::getDouble(const std::string& key, double fallback) {
  return has(key) ? getDouble(key) : fallback;
}

double YamlMap::getPositive(const std::string& key) {
  const double v = getDouble(key);
  if (!(v > 0)) fail(key, "must be positive (got " + std::to_string(v) + ")");
  if (v < kMinMagnitude)
    fail(key, "must be positive and at least 1e-12 (got " + static_cast<const YAML::Node&>(node_)[key].Scalar() + ")");
  return v;
}

double YamlMap::getNonNegative(const std::string& key) {
  const double v = getDouble(key);
  if (v < 0) fail(key, "must not be negative (got " + std::to_string(v) + ")");
  return v;
}

double YamlMap::getPositive(const std::string& key, double fallback) { return has(key) ? getPositive(key) : fallback; }

double YamlMap::getNonNegative(const std::string& key, double fallback) {
  return has(key) ? getNonNegative(key) : fallback;
}

double YamlMap::getZeroOrAtLeast(const std::string& key, double floor, const std::string& unit, double fallback) {
  return has(key) ? getZeroOrAtLeast(key, floor, unit) : fallback;
}

double YamlMap::getZeroOrAtLeast(const std::string& key, double floor, const std::string& unit) {
  const double v = getNonNegative(key);
  if (v > 0 && v < floor)
    fail(key, "must be 0 (off) or at least " + formatNumber(floor, 6) + " " + unit + " (got " +
                  static_cast<const YAML::Node&>(node_)[key].Scalar() + ")");
  return v;
}

bool YamlMap::getBool(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const YAML::Node n = require(key);
  bool v = false;
  if (!n.IsScalar() || !YAML::convert<bool>::decode(n, v)) fail(key, "expected true or false");
  return v;
}

std::string YamlMap::getString(const std::string& key) {
  const YAML::Node n = require(key);
  if (!n.IsScalar()) fail(key, "expected a string");
  return n.as<std::string>();
}

std::string YamlMap::getString(const std::string& key, const std::string& fallback) {
  return has(key) ? getString(key) : fallback;
}

YAML::Node YamlMap::requireList(const std::string& key) {
  const YAML::Node n = require(key);
  if (!n.IsSequence()) fail(key, "expected a list");
  return n;
}

std::vector<double> YamlMap::getDoubleList(const std::string& key) {
  const YAML::Node n = requireList(key);
  std::vector<double> out;
  for (size_t i = 0; i < n.size(); ++i) out.push_back(toFinite(n[i], key, i));
  return out;
}

std::vector<double> YamlMap::getDoubleList(const std::string& key, size_t size) {
  const auto v = getDoubleList(key);
  if (v.size() != size) fail(key, "expected " + std::to_string(size) + " numbers, found " + std::to_string(v.size()));
  return v;
}

std::array<double, 3> YamlMap::getVec3(const std::string& key) {
  const auto v = getDoubleList(key);
  if (v.size() != 3) fail(key, "expected 3 numbers [x, y, z], found " + std::to_string(v.size()));
  return {v[0], v[1], v[2]};
}

std::vector<std::string> YamlMap::getStringList(const std::string& key) {
  const YAML::Node n = requireList(key);
  std::vector<std::string> out;
  for (size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsScalar()) failElement(key, i, "expected a string");
    out.push_back(n[i].Scalar());
  }
  return out;
}

YamlMap YamlMap::getMap(const std::string& key) {
  const YAML::Node n = require(key);
  if (!n.IsMap()) fail(key, "expected a mapping");
  return YamlMap(n, file_, childPath(key), inputs_);
}

std::vector<YamlMap> YamlMap::getMapList(const std::string& key) {
  const YAML::Node n = requireList(key);
  std::vector<YamlMap> out;
  for (size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsMap()) failElement(key, i, "expected a mapping");
    out.emplace_back(n[i], file_, childPath(key) + "[" + std::to_string(i) + "]", inputs_);
  }
  return out;
}

std::string resolveRelativeTo(const std::string& namingFile, const std::string& name) {
  const std::filesystem::path p(name);
  if (p.is_absolute()) return name;
  const std::filesystem::path resolved = (std::filesystem::path(namingFile).parent_path() / p).lexically_normal();
  // A file of the working folder keeps its "./": a name without a folder is one the loader searches
  // for (a plugin library, ./libx.so named by ./p.yaml, must stay a path).
  return resolved.has_parent_path() ? resolved.string() : "./" + resolved.string();
}

std::string YamlMap::getFilePath(const std::string& key) {
  const std::string name = getString(key);
  if (name.empty()) fail(key, "expected a file name");
  return resolveRelativeTo(file_, name);
}

std::vector<std::string> YamlMap::getFilePathList(const std::string& key) {
  std::vector<std::string> out = getStringList(key);
  for (size_t i = 0; i < out.size(); ++i) {
    if (out[i].empty()) failElement(key, i, "expected a file name");
    out[i] = resolveRelativeTo(file_, out[i]);
  }
  return out;
}

void YamlMap::finish() const {
  for (const auto& kv : node_) {
    const std::string k = kv.first.Scalar();
    if (!used_->count(k)) throw InputError(locationOf(kv.first, file_, childPath(k)), "unknown key", InputProblem::UnknownKey);
  }
}

std::vector<std::string> YamlMap::getUnreadKeys() const {
  std::vector<std::string> out;
  for (const auto& kv : node_)
    if (!used_->count(kv.first.Scalar())) out.push_back(kv.first.Scalar());
  return out;
}

namespace {

std::mutex gOpenCountLock;
std::map<std::string, long> gOpenCounts;  // per file name as given to loadYamlFile

}  // namespace

long getYamlFileOpenCount(const std::string& file) {
  std::lock_guard<std::mutex> guard(gOpenCountLock);
  const auto it = gOpenCounts.find(file);
  return it == gOpenCounts.end() ? 0 : it->second;
}

std::string YamlMap::readFileText(const std::string& key, std::uintmax_t maxBytes) {
  const std::string path = getFilePath(key);
  return inputs_ ? inputs_->readText(path, maxBytes) : readInputFile(path, maxBytes);
}

YamlMap YamlMap::loadFileMap(const std::string& key) {
  const std::string path = getFilePath(key);
  const YAML::Node root = parseYamlText(readFileText(key, kMaxTextFileBytes), path, "");
  checkKeys(root, path, "", true);
  return YamlMap(root, path, "", inputs_);
}

void YamlMap::warn(const std::string& key, const std::string& message) const {
  if (inputs_) inputs_->addWarning(locate(key), message);
}

YamlMap loadYamlFile(const std::string& file) {
  {
    std::lock_guard<std::mutex> guard(gOpenCountLock);
    ++gOpenCounts[file];
  }
  const YAML::Node root = parseYamlText(readInputFile(file), file, "");
  checkKeys(root, file, "", true);
  return YamlMap(root, file, "");
}

std::vector<KeyPathSegment> parseKeyPath(const std::string& path) {
  std::vector<KeyPathSegment> out;
  size_t start = 0;
  while (true) {
    const size_t dot = path.find('.', start);
    std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    KeyPathSegment seg;
    const size_t open = part.find('[');
    if (open != std::string::npos) {
      const size_t close = part.find(']', open);
      const std::string digits = close == std::string::npos ? "" : part.substr(open + 1, close - open - 1);
      if (close != part.size() - 1 || digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos ||
          digits.size() > 6)
        throw InputError({"", 0, 0, path}, "malformed index in key path (expected key[N])");
      seg.index = std::stoi(digits);
      part = part.substr(0, open);
    }
    if (part.empty()) throw InputError({"", 0, 0, path}, "empty key in key path");
    seg.key = part;
    out.push_back(seg);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return out;
}

YAML::Node findKeyPath(const YAML::Node& root, const std::string& path) {
  YAML::Node node;  // a handle walked with const lookups only: the caller's tree gains no keys
  node.reset(root);
  for (const auto& seg : parseKeyPath(path)) {
    if (!node.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
    const YAML::Node next = static_cast<const YAML::Node&>(node)[seg.key];
    if (!next) return YAML::Node(YAML::NodeType::Undefined);
    node.reset(next);
    if (seg.index >= 0) {
      if (!node.IsSequence() || seg.index >= static_cast<int>(node.size())) return YAML::Node(YAML::NodeType::Undefined);
      const YAML::Node element = static_cast<const YAML::Node&>(node)[static_cast<size_t>(seg.index)];
      node.reset(element);
    }
  }
  return node;
}

ParsedOverride parseOverride(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError({"--set", 0, 0, assignment}, "expected KEY.PATH=VALUE");
  ParsedOverride out;
  out.path = assignment.substr(0, eq);
  try {
    out.value = parseYamlText(assignment.substr(eq + 1), "--set", assignment);
  } catch (const InputError& e) {
    throw InputError({"--set", 0, 0, assignment}, "the value is not valid YAML: " + e.getReason());
  }
  checkKeys(out.value, "--set " + assignment, out.path, true);
  try {
    parseKeyPath(out.path);
  } catch (const InputError& e) {
    throw InputError({"--set", 0, 0, assignment}, e.getReason());
  }
  return out;
}

void applyOverride(YAML::Node& root, const std::string& assignment) {
  const ParsedOverride o = parseOverride(assignment);
  setKeyPath(root, o.path, o.value, assignment);
}

void setKeyPath(YAML::Node& root, const std::string& path, const YAML::Node& value, const std::string& assignment) {
  std::vector<KeyPathSegment> segments;
  try {
    segments = parseKeyPath(path);
  } catch (const InputError& e) {
    throw InputError({"--set", 0, 0, assignment}, e.getReason());
  }
  // yaml-cpp nodes are handles: walk with fresh handles so the tree itself is edited.
  std::vector<YAML::Node> chain{root};
  for (size_t i = 0; i < segments.size(); ++i) {
    const KeyPathSegment& seg = segments[i];
    const bool last = i + 1 == segments.size();
    if (!chain.back().IsMap())
      throw InputError({"--set", 0, 0, path}, "'" + (i ? segments[i - 1].key : std::string("the scenario")) +
                                                 "' is not a mapping in the scenario");
    if (last && seg.index < 0) {
      chain.back()[seg.key] = value;
      return;
    }
    YAML::Node next = chain.back()[seg.key];
    if (seg.index >= 0) {
      if (!next || !next.IsSequence() || seg.index >= static_cast<int>(next.size()))
        throw InputError({"--set", 0, 0, path}, "'" + seg.key + "' has no element " + std::to_string(seg.index) +
                                                   " in the scenario");
      if (last) {
        next[static_cast<size_t>(seg.index)] = value;
        return;
      }
      chain.push_back(next);
      next = chain.back()[static_cast<size_t>(seg.index)];
    } else if (!next) {
      // A missing intermediate section is created; the scenario reader then validates its keys.
      chain.back()[seg.key] = YAML::Node(YAML::NodeType::Map);
      next = chain.back()[seg.key];
    }
    chain.push_back(next);
  }
}

YAML::Node makeOverrideScalar(const std::string& text) {
  YAML::Node n(text);
  YAML::Mark first;  // line 0, column 0: shown as 1:1, as for a value parsed from --set text
  setNodeMark(n, first);
  return n;
}

YAML::Node copyTree(const YAML::Node& node) {
  YAML::Node out;
  switch (node.Type()) {
    case YAML::NodeType::Map:
      out = YAML::Node(YAML::NodeType::Map);
      for (const auto& kv : node) out.force_insert(copyTree(kv.first), copyTree(kv.second));
      break;
    case YAML::NodeType::Sequence:
      out = YAML::Node(YAML::NodeType::Sequence);
      for (const auto& element : node) out.push_back(copyTree(element));
      break;
    case YAML::NodeType::Scalar:
      out = YAML::Node(node.Scalar());
      break;
    case YAML::NodeType::Null:
      out = YAML::Node(YAML::NodeType::Null);
      break;
    case YAML::NodeType::Undefined:
      return YAML::Node(YAML::NodeType::Undefined);
  }
  out.SetTag(node.Tag());
  out.SetStyle(node.Style());
  setNodeMark(out, node.Mark());
  return out;
}

}  // namespace motostab::io

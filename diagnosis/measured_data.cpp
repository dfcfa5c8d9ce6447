#include "diagnosis/measured_data.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "diagnosis/findings.h"
#include "io/csv.h"
#include "extensions/steer_controller.h"
#include "scenario/parameter_paths.h"
#include "io/yaml_map.h"

namespace motostab::diagnosis {

using io::CsvTable;
using io::InputError;
using io::YamlMap;
using io::formatNumber;
using io::loadYamlFile;
using io::readCsv;
using scenario::formatOverride;
using extensions::getSteerControllerScalarKeys;
using extensions::readSteerController;

namespace {

namespace fs = std::filesystem;

Quantity parseQuantity(YamlMap& m, const std::string& key) {
  const std::string s = m.getString(key);
  for (Quantity q : {Quantity::RollAngle, Quantity::RollRate, Quantity::SteerAngle, Quantity::SteerRate, Quantity::YawRate})
    if (getQuantityName(q) == s) return q;
  m.fail(key, "unknown quantity '" + s + "' (roll_angle, roll_rate, steer_angle, steer_rate, yaw_rate)");
}

// The list under `key` (absent: empty), each element as a strict map.
std::vector<YamlMap> getMapList(YamlMap& m, const std::string& key) {
  std::vector<YamlMap> out;
  if (!m.has(key)) return out;
  m.markUsed(key);
  const YAML::Node list = m.getNode()[key];
  if (!list.IsSequence()) m.fail(key, "expected a list");
  for (size_t i = 0; i < list.size(); ++i)
    out.emplace_back(list[i], m.getFile(), key + "[" + std::to_string(i) + "]");
  return out;
}

fs::path resolve(const YamlMap& m, const std::string& key, const std::string& name) {
  const fs::path p = fs::path(m.getFile()).parent_path() / name;
  std::error_code ec;  // a name the file system rejects (too long, ...) is a missing file too
  if (!fs::is_regular_file(p, ec)) m.fail(key, "no such file: " + p.string() + (ec ? " (" + ec.message() + ")" : ""));
  return p;
}

[[noreturn]] void failRow(const CsvTable& t, size_t i, const std::string& column, const std::string& msg) {
  throw InputError({t.source, t.lineNumbers[i], 0, column}, msg);
}

// Why a measured speed (m/s) is refused, or "": speeds lie in [0, kMaxMeasuredSpeed].
std::string checkSpeed(double v) {
  if (v >= 0 && v <= kMaxMeasuredSpeed) return "";
  return "a measured speed must lie between 0 and " + formatNumber(kMaxMeasuredSpeed, 6) + " m/s (got " +
         formatNumber(v, 6) + ")";
}

// Why a standard deviation (noise, stderr) is refused, or "": 0 (unknown, where allowed) or within
// [kMinStd, kMaxStd], so that its square and inverse square, which weight the fits, stay finite.
std::string checkStd(double s, bool zeroAllowed) {
  if ((zeroAllowed && s == 0) || (s >= kMinStd && s <= kMaxStd)) return "";
  return std::string("a standard deviation must be ") + (zeroAllowed ? "0 (unknown) or " : "") + "between " +
         formatNumber(kMinStd, 3) + " and " + formatNumber(kMaxStd, 3) + " (got " + formatNumber(s, 6) +
         "): its square weights the fit";
}

int requireColumn(const CsvTable& t, const std::string& name) {
  for (size_t j = 0; j < t.header.size(); ++j)
    if (t.header[j] == name) return static_cast<int>(j);
  throw InputError({t.source, t.headerLine, 0, name}, "missing column '" + name + "'");
}

int findColumn(const CsvTable& t, const std::string& name) {
  const auto it = std::find(t.header.begin(), t.header.end(), name);
  return it == t.header.end() ? -1 : static_cast<int>(it - t.header.begin());
}

// Checks a steer_controller mapping as the scenario's section is read (InputError at its keys).
void checkSteerController(YamlMap m) {
  readSteerController(m);
  m.finish();
}

// "steer_controller.<scalar key>": a per-row controller setting; else "".
std::string getControllerKey(const std::string& column) {
  const std::string prefix = "steer_controller.";
  if (column.rfind(prefix, 0) != 0) return "";
  const auto& keys = getSteerControllerScalarKeys();
  const std::string key = column.substr(prefix.size());
  return std::find(keys.begin(), keys.end(), key) == keys.end() ? "" : key;
}

// `controller: {key: value, ...}` of an eigenvalue file or a response run: steer_controller overrides,
// each checked here as the scenario's steer_controller section is (a negative delay, a non-positive gain
// factor, an unsorted schedule are errors at this file's line and column).
std::vector<std::string> readController(YamlMap& m) {
  std::vector<std::string> out;
  if (!m.has("controller")) return out;
  YamlMap c = m.getMap("controller");
  checkSteerController(YamlMap(c.getNode(), c.getFile(), c.getPath()));
  const auto& keys = getSteerControllerScalarKeys();
  for (const auto& kv : c.getNode()) {
    const std::string key = kv.first.Scalar();
    if (key == "schedule") {
      YAML::Emitter e;
      e << YAML::Flow << kv.second;
      out.push_back("steer_controller.schedule=" + std::string(e.c_str()));
      c.markUsed(key);
    } else if (std::find(keys.begin(), keys.end(), key) != keys.end()) {
      out.push_back(formatOverride("steer_controller." + key, c.getDouble(key)));
    }
  }
  c.finish();  // an unknown key fails here, at its line and column
  return out;
}

void checkEigenvalueColumns(const CsvTable& t) {
  static const std::vector<std::string> known{"speed_mps", "mode", "real", "imag", "real_stderr",
                                              "imag_stderr", "speed_min_mps", "speed_max_mps"};
  for (const auto& h : t.header)
    if (std::find(known.begin(), known.end(), h) == known.end() && getControllerKey(h).empty())
      throw InputError({t.source, t.headerLine, 0, h}, "unknown column '" + h + "'");
  if ((findColumn(t, "speed_min_mps") < 0) != (findColumn(t, "speed_max_mps") < 0))
    throw InputError({t.source, t.headerLine, 0, "speed_min_mps"}, "speed_min_mps and speed_max_mps go together");
}

MeasuredEigenvalue readEigenvalueRow(const CsvTable& t, size_t i) {
  const auto& r = t.rows[i];
  auto opt = [&](const char* c) { const int j = findColumn(t, c); return j < 0 ? 0.0 : r[j]; };
  MeasuredEigenvalue e;
  e.speed = r[requireColumn(t, "speed_mps")];
  e.real = r[requireColumn(t, "real")];
  e.imag = r[requireColumn(t, "imag")];
  e.realStderr = opt("real_stderr");
  e.imagStderr = opt("imag_stderr");
  e.where = {t.source, t.lineNumbers[i], 0, ""};
  for (size_t j = 0; j < t.header.size(); ++j) {
    const std::string key = getControllerKey(t.header[j]);
    if (key.empty()) continue;
    YAML::Node cell(YAML::NodeType::Map);  // checked as the scenario's steer_controller.<key> is
    cell[key] = formatNumber(r[j]);
    try {
      checkSteerController(YamlMap(cell, t.source, "steer_controller"));
    } catch (const InputError& bad) {
      failRow(t, i, t.header[j], bad.getReason());
    }
    e.controller.push_back(formatOverride(t.header[j], r[j]));
  }
  e.hasRange = findColumn(t, "speed_min_mps") >= 0;
  e.speedMin = e.hasRange ? opt("speed_min_mps") : e.speed;
  e.speedMax = e.hasRange ? opt("speed_max_mps") : e.speed;
  if (const std::string why = checkSpeed(e.speed); !why.empty()) failRow(t, i, "speed_mps", why);
  if (e.imag < 0) failRow(t, i, "imag", "one row per complex pair, with imag >= 0");
  if (const std::string why = checkStd(e.realStderr, true); !why.empty()) failRow(t, i, "real_stderr", why);
  if (const std::string why = checkStd(e.imagStderr, true); !why.empty()) failRow(t, i, "imag_stderr", why);
  if (e.hasRange && !(e.speedMin >= 0 && e.speedMin <= e.speed && e.speed <= e.speedMax))
    failRow(t, i, "speed_min_mps", "need 0 <= speed_min_mps <= speed_mps <= speed_max_mps");
  if (const std::string why = checkSpeed(e.speedMax); e.hasRange && !why.empty()) failRow(t, i, "speed_max_mps", why);
  const std::string& mode = t.text[i][0];
  if (!mode.empty()) {
    e.mode = analysis::parseModeLabel(mode);
    if (!e.mode) failRow(t, i, "mode", "unknown mode label '" + mode + "'");
  }
  return e;
}

void readEigenvalueFile(YamlMap entry, MeasuredData& data) {
  const fs::path p = resolve(entry, "file", entry.getString("file"));
  const std::vector<std::string> controller = readController(entry);
  entry.finish();
  const CsvTable t = readCsv(p, {"mode"});
  requireColumn(t, "mode");
  checkEigenvalueColumns(t);
  if (t.rows.empty()) throw InputError({t.source, t.headerLine, 0, ""}, "no rows");
  for (size_t i = 0; i < t.rows.size(); ++i) {
    MeasuredEigenvalue e = readEigenvalueRow(t, i);
    e.controller.insert(e.controller.begin(), controller.begin(), controller.end());
    data.eigenvalues.push_back(e);
  }
  data.eigenvalueFiles.push_back(p.string());
}

// Samples of `column` with time in [w0, w1].
std::vector<double> cut(const CsvTable& t, int column, const std::vector<bool>& keep) {
  std::vector<double> out;
  for (size_t i = 0; i < t.rows.size(); ++i)
    if (keep[i]) out.push_back(t.rows[i][column]);
  return out;
}

ResponseSignal readSignal(YamlMap s, const CsvTable& t, const std::vector<bool>& keep) {
  ResponseSignal sig;
  sig.column = s.getString("column");
  sig.quantity = parseQuantity(s, "quantity");
  if (s.has("scale")) {
    const YAML::Node n = s.getNode()["scale"];
    if (n.IsScalar() && n.Scalar() == "free") {
      sig.freeScale = true;
      s.markUsed("scale");
    } else {
      sig.scale = s.getDouble("scale");
      if (!(std::abs(sig.scale) >= kMinStd && std::abs(sig.scale) <= kMaxStd))
        s.fail("scale", "must be 'free' or a factor to rad or rad/s of magnitude between " + formatNumber(kMinStd, 3) +
                            " and " + formatNumber(kMaxStd, 3));
    }
  }
  s.finish();
  const int j = findColumn(t, sig.column);
  if (j < 0) s.fail("column", "no column '" + sig.column + "' in " + t.source + " (line " + std::to_string(t.headerLine) + ")");
  sig.values = cut(t, j, keep);
  for (size_t i = 0, k = 0; i < t.rows.size(); ++i)  // in rad or rad/s, each sample squared by the fit
    if (keep[i] && !(std::abs(sig.values[k++] * sig.scale) <= kMaxStd))
      failRow(t, i, sig.column, "a sample of magnitude above " + formatNumber(kMaxStd, 3) + " rad or rad/s");
  return sig;
}

void readNoise(YamlMap& run, ResponseRun& r) {
  if (!run.has("noise_std")) return;
  YamlMap noise = run.getMap("noise_std");
  for (auto& sig : r.signals)
    if (noise.has(sig.column)) {
      sig.noiseStd = noise.getPositive(sig.column);
      if (const std::string why = checkStd(sig.noiseStd, false); !why.empty()) noise.fail(sig.column, why);
    }
  noise.finish();
}

// A run must cover its window (to within half a sample interval at each end).
void checkWindowCovered(YamlMap& run, const std::vector<double>& time, double w0, double w1) {
  const double half = 0.5 * (time.back() - time.front()) / std::max<size_t>(time.size() - 1, 1);
  if (w0 < time.front() - half || w1 > time.back() + half)
    run.fail("window_s", "the run's samples span [" + formatNumber(time.front(), 6) + ", " + formatNumber(time.back(), 6) +
                             "] s: shorter than its window");
}

std::vector<bool> selectWindow(YamlMap& run, const std::vector<double>& time) {
  double w0 = -HUGE_VAL, w1 = HUGE_VAL;
  if (run.has("window_s")) {
    const auto w = run.getDoubleList("window_s");
    if (w.size() != 2 || !(w[0] < w[1])) run.fail("window_s", "expected [start, end] with start < end (s)");
    w0 = w[0];
    w1 = w[1];
  }
  std::vector<bool> keep(time.size());
  int n = 0;
  for (size_t i = 0; i < time.size(); ++i) n += (keep[i] = time[i] >= w0 && time[i] <= w1);
  if (n < 20) run.fail(run.has("window_s") ? "window_s" : "file", "the window holds " + std::to_string(n) + " samples; need at least 20");
  if (run.has("window_s")) checkWindowCovered(run, time, w0, w1);
  return keep;
}

void checkTimeIncreasing(const CsvTable& t, int column) {
  for (size_t i = 1; i < t.rows.size(); ++i)
    if (!(t.rows[i][column] > t.rows[i - 1][column])) failRow(t, i, t.header[column], "time must increase");
}

// `speed_trace: {file, time_column, speed_column}`: a speed record of its own (e.g. a speedometer
// at its own sampling), linearly interpolated at the run's sample times; it must cover the window.
std::vector<double> readSpeedTrace(YamlMap& run, const std::vector<double>& time) {
  YamlMap m = run.getMap("speed_trace");
  const CsvTable t = readCsv(resolve(m, "file", m.getString("file")));
  const std::string tk = m.getString("time_column"), vk = m.getString("speed_column");
  if (findColumn(t, tk) < 0) m.fail("time_column", "no column '" + tk + "' in " + t.source);
  if (findColumn(t, vk) < 0) m.fail("speed_column", "no column '" + vk + "' in " + t.source);
  m.finish();
  checkTimeIncreasing(t, findColumn(t, tk));
  const std::vector<double> ts = t.getColumn(tk), vs = t.getColumn(vk);
  if (ts.size() < 2 || ts.front() > time.front() || ts.back() < time.back())
    m.fail("file", "the speed trace does not cover the run's window");
  std::vector<double> out;
  for (double x : time) {
    const size_t k = std::min<size_t>(std::upper_bound(ts.begin(), ts.end(), x) - ts.begin(), ts.size() - 1);
    const double w = (x - ts[k - 1]) / (ts[k] - ts[k - 1]);
    out.push_back((1 - w) * vs[k - 1] + w * vs[k]);
    if (const std::string why = checkSpeed(out.back()); !why.empty()) m.fail("speed_column", why);
  }
  return out;
}

ResponseRun readRun(YamlMap run) {
  ResponseRun r;
  r.where = run.locate();
  const fs::path p = resolve(run, "file", run.getString("file"));
  r.file = p.string();
  const CsvTable t = readCsv(p);
  const std::string timeKey = run.getString("time_column");
  const int tc = findColumn(t, timeKey);
  if (tc < 0) run.fail("time_column", "no column '" + timeKey + "' in " + t.source);
  checkTimeIncreasing(t, tc);
  const std::vector<bool> keep = selectWindow(run, t.getColumn(timeKey));
  r.time = cut(t, tc, keep);
  if (run.has("speed_mps") + run.has("speed_column") + run.has("speed_trace") != 1)
    run.fail("", "give exactly one of speed_mps, speed_column and speed_trace");
  if (run.has("speed_mps")) {
    r.speed = run.getNonNegative("speed_mps");
    if (const std::string why = checkSpeed(r.speed); !why.empty()) run.fail("speed_mps", why);
  } else if (run.has("speed_trace")) {
    r.speeds = readSpeedTrace(run, r.time);
    for (double x : r.speeds) r.speed += x / r.speeds.size();
  } else {
    const std::string sc = run.getString("speed_column");
    const int j = findColumn(t, sc);
    if (j < 0) run.fail("speed_column", "no column '" + sc + "' in " + t.source);
    r.speeds = cut(t, j, keep);
    for (size_t i = 0; i < t.rows.size(); ++i)
      if (const std::string why = checkSpeed(t.rows[i][j]); keep[i] && !why.empty()) failRow(t, i, sc, why);
    for (double x : r.speeds) r.speed += x / r.speeds.size();
  }
  auto signals = getMapList(run, "signals");
  if (signals.empty()) run.fail("signals", "a run needs at least one signal");
  for (auto& s : signals) r.signals.push_back(readSignal(s, t, keep));
  readNoise(run, r);
  r.controller = readController(run);
  run.finish();
  return r;
}

}  // namespace

std::string getQuantityName(Quantity q) {
  switch (q) {
    case Quantity::RollAngle: return "roll_angle";
    case Quantity::RollRate: return "roll_rate";
    case Quantity::SteerAngle: return "steer_angle";
    case Quantity::SteerRate: return "steer_rate";
    case Quantity::YawRate: return "yaw_rate";
  }
  return "";
}

std::vector<std::string> getModeLabels() {
  std::vector<std::string> labels;
  for (int m = 0; m < analysis::kNumModeLabels; ++m) labels.push_back(analysis::toString(static_cast<analysis::ModeLabel>(m)));
  return labels;
}

MeasuredData loadMeasuredData(const std::string& path) {
  YamlMap root = loadYamlFile(path);
  MeasuredData data;
  data.file = path;
  data.name = root.getString("name", fs::path(path).stem().string());
  for (auto& e : getMapList(root, "eigenvalues")) readEigenvalueFile(e, data);
  for (auto& r : getMapList(root, "responses")) data.responses.push_back(readRun(r));
  for (auto& f : getMapList(root, "findings")) data.findings.push_back(readFinding(f));
  data.steerRateAmplitude = root.getPositive("steer_rate_amplitude_rad_s", 0.0);
  root.finish();
  if (data.eigenvalues.empty() && data.responses.empty() && data.findings.empty())
    root.fail("", "no measurements: give eigenvalues, responses and/or findings");
  return data;
}

}  // namespace motostab::diagnosis

#include "diagnosis/findings.h"

#include <algorithm>
#include <cmath>

#include "io/csv.h"
#include "io/input_error.h"
#include "io/number.h"
#include "plugins/builtin.h"
#include "scenario/parameter_overrides.h"

namespace motostab::diagnosis {

using io::YamlMap;
using io::formatNumber;

namespace {

constexpr FindingKind kKinds[] = {FindingKind::Stable, FindingKind::Unstable, FindingKind::FrequencyWithin,
                                  FindingKind::MostStableNear, FindingKind::ChangeBelow};

// The tolerance key of each kind (its unit in the name).
const char* getToleranceKey(FindingKind kind) {
  switch (kind) {
    case FindingKind::Stable:
    case FindingKind::Unstable: return "tolerance_per_s";
    case FindingKind::FrequencyWithin: return "tolerance_hz";
    case FindingKind::MostStableNear: return "tolerance_mps";
    case FindingKind::ChangeBelow: return "tolerance_percent";
  }
  return "";
}

FindingKind parseKind(YamlMap& m) {
  const std::string s = m.getString("kind");
  for (FindingKind k : kKinds)
    if (s == getFindingKindName(k)) return k;
  m.fail("kind", "unknown finding kind '" + s + "' (stable, unstable, frequency_within, most_stable_near, change_below)");
}

// A two-number list [lo, hi] with lo <= hi, each within [lowest, highest].
std::pair<double, double> readInterval(YamlMap& m, const std::string& key, double lowest, double highest,
                                       const std::string& unit) {
  const std::vector<double> v = m.getDoubleList(key);
  if (v.size() != 2 || !(v[0] <= v[1]))
    m.fail(key, "expected [low, high] with low <= high (" + unit + ")");
  if (!(v[0] >= lowest && v[1] <= highest))
    m.fail(key, "must lie between " + formatNumber(lowest, 6) + " and " + formatNumber(highest, 6) + " " + unit);
  return {v[0], v[1]};
}

// `key: {key.path: value, ...}` (change, variant): --set assignments, each parsed as --set parses it.
std::vector<std::string> readAssignments(YamlMap& m, const std::string& mapKey) {
  YamlMap c = m.getMap(mapKey);
  std::vector<std::string> out;
  for (const auto& kv : c.getNode()) {
    const std::string key = kv.first.Scalar();
    YAML::Emitter e;
    e << YAML::Flow << kv.second;
    out.push_back(key + "=" + std::string(e.c_str()));
    try {
      scenario::ParameterOverrides check({out.back()});
    } catch (const io::InputError& bad) {
      c.fail(key, bad.getReason());
    }
    c.markUsed(key);
  }
  c.finish();
  if (out.empty()) m.fail(mapKey, "needs at least one key: value");
  return out;
}

void readKindFields(YamlMap& m, Finding& f) {
  if (f.kind == FindingKind::FrequencyWithin)
    std::tie(f.frequencyMin, f.frequencyMax) = readInterval(m, "frequency_hz", 0, io::kMaxMagnitude, "Hz");
  if (f.kind == FindingKind::MostStableNear) {
    f.speed = m.getNonNegative("speed_mps");
    if (!(f.speed >= f.speedMin && f.speed <= f.speedMax)) m.fail("speed_mps", "must lie within speeds_mps");
  }
  if (f.kind == FindingKind::ChangeBelow) {
    f.percent = m.getNonNegative("percent");
    f.change = readAssignments(m, "change");
  }
  if (f.kind == FindingKind::MostStableNear && !(f.speedMax > f.speedMin))
    m.fail("speeds_mps", "most_stable_near needs a speed range with low < high");
}

// The speed of the lowest real part over `v` (uniform), refined by the parabola through the lowest
// point and its neighbours when it is interior.
double findMostStableSpeed(const std::vector<double>& v, const std::complex<double>* l) {
  size_t k = 0;
  for (size_t i = 1; i < v.size(); ++i)
    if (l[i].real() < l[k].real()) k = i;
  if (k == 0 || k + 1 == v.size()) return v[k];
  const double a = l[k - 1].real(), b = l[k].real(), c = l[k + 1].real();
  const double curvature = a - 2 * b + c;
  if (!(curvature > 0)) return v[k];
  return v[k] + 0.5 * (v[k + 1] - v[k]) * (a - c) / curvature;
}

double calcHinge(const Finding& f, const std::complex<double>& l, const std::complex<double>* changed) {
  switch (f.kind) {
    case FindingKind::Stable: return std::max(0.0, l.real());
    case FindingKind::Unstable: return std::max(0.0, -l.real());
    case FindingKind::FrequencyWithin: {
      const double hz = std::abs(l.imag()) / (2 * M_PI);
      return std::max({0.0, f.frequencyMin - hz, hz - f.frequencyMax});
    }
    case FindingKind::ChangeBelow:
      return std::max(0.0, 100 * std::abs(*changed - l) / std::max(std::abs(l), 1e-300) - f.percent);
    case FindingKind::MostStableNear: break;
  }
  return 0;
}

}  // namespace

const char* getFindingKindName(FindingKind kind) {
  switch (kind) {
    case FindingKind::Stable: return "stable";
    case FindingKind::Unstable: return "unstable";
    case FindingKind::FrequencyWithin: return "frequency_within";
    case FindingKind::MostStableNear: return "most_stable_near";
    case FindingKind::ChangeBelow: return "change_below";
  }
  return "";
}

const char* getFindingUnit(FindingKind kind) {
  switch (kind) {
    case FindingKind::Stable:
    case FindingKind::Unstable: return "1/s";
    case FindingKind::FrequencyWithin: return "Hz";
    case FindingKind::MostStableNear: return "m/s";
    case FindingKind::ChangeBelow: return "%";
  }
  return "";
}

Finding readFinding(YamlMap m) {
  Finding f;
  f.where = m.locate();
  f.kind = parseKind(m);
  const std::string mode = m.getString("mode");
  const auto label = analysis::parseModeLabel(mode);
  if (!label) m.fail("mode", "unknown mode label '" + mode + "'");
  f.mode = *label;
  std::tie(f.speedMin, f.speedMax) = readInterval(m, "speeds_mps", 0, kMaxMeasuredSpeed, "m/s");
  readKindFields(m, f);
  if (m.has("variant")) f.variant = readAssignments(m, "variant");
  const char* tolKey = getToleranceKey(f.kind);
  for (FindingKind other : kKinds)
    if (m.has(getToleranceKey(other)) && std::string(getToleranceKey(other)) != tolKey)
      m.fail(getToleranceKey(other), std::string("a ") + getFindingKindName(f.kind) + " finding states its tolerance as " + tolKey);
  f.tolerance = m.getPositive(tolKey);
  if (!(f.tolerance <= kMaxStd)) m.fail(tolKey, "must be at most " + formatNumber(kMaxStd, 3));
  f.source = m.getString("source", "");
  m.finish();
  return f;
}

std::vector<double> getFindingSpeeds(const Finding& f) {
  if (!(f.speedMax > f.speedMin)) return {f.speedMin};
  const int n = std::clamp(static_cast<int>(std::ceil(f.speedMax - f.speedMin - 1e-9)) + 1, 3, 101);
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = f.speedMin + (f.speedMax - f.speedMin) * i / (n - 1);
  return v;
}

size_t countProbeRows(const Finding& f) {
  return getFindingSpeeds(f).size() * (f.kind == FindingKind::ChangeBelow ? 2 : 1);
}

std::vector<MeasuredEigenvalue> makeProbeRows(const std::vector<Finding>& findings) {
  std::vector<MeasuredEigenvalue> out;
  for (const Finding& f : findings)
    for (int changed = 0; changed < (f.kind == FindingKind::ChangeBelow ? 2 : 1); ++changed)
      for (double v : getFindingSpeeds(f)) {
        MeasuredEigenvalue e;
        e.speed = e.speedMin = e.speedMax = v;
        e.mode = f.mode;
        e.where = f.where;
        e.controller = f.variant;
        if (changed) e.controller.insert(e.controller.end(), f.change.begin(), f.change.end());
        out.push_back(e);
      }
  return out;
}

double calcFindingViolation(const Finding& f, const std::complex<double>* probes) {
  const std::vector<double> v = getFindingSpeeds(f);
  if (f.kind == FindingKind::MostStableNear) return findMostStableSpeed(v, probes) - f.speed;
  double sum = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const double h = calcHinge(f, probes[i], f.kind == FindingKind::ChangeBelow ? &probes[v.size() + i] : nullptr);
    sum += h * h;
  }
  return std::sqrt(sum / v.size());
}

void checkFindingChanges(const scenario::ScenarioSource& source, const scenario::ParameterOverrides& base,
                         const std::vector<Finding>& findings) {
  for (const Finding& f : findings)
    for (const char* key : {"variant", "change"}) {
      const std::vector<std::string>& extra = std::string(key) == "variant" ? f.variant : f.change;
      if (extra.empty()) continue;
      scenario::ParameterOverrides all = base;
      all.append(scenario::ParameterOverrides(f.variant));
      all.append(scenario::ParameterOverrides(extra));
      try {
        scenario::Scenario s = source.load(all);
        plugins::makeBuiltinRegistry().readScenarioSections(s);  // extension sections too, as a build would read them
      } catch (const io::InputError& bad) {
        io::InputLocation at = f.where;
        at.key = key;
        throw io::InputError(at, std::string("the scenario refuses this ") + key + ": " + bad.what());
      }
    }
}

std::vector<std::string> getFindingPaths(const std::vector<Finding>& findings) {
  std::vector<std::string> paths;
  for (const Finding& f : findings)
    for (const auto* list : {&f.variant, &f.change}) {
      const scenario::ParameterOverrides set(*list);
      for (const auto& item : set.getItems()) paths.push_back(item.path);
    }
  std::sort(paths.begin(), paths.end());
  paths.erase(std::unique(paths.begin(), paths.end()), paths.end());
  return paths;
}

}  // namespace motostab::diagnosis

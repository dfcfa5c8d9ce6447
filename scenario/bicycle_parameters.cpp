#include "scenario/bicycle_parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include <Eigen/Dense>

#include "io/atomic_file.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "io/input_file.h"
#include "io/number.h"
#include "io/output_folder.h"
#include "scenario/bicycle_parameters_uncertainty.h"
#include "scenario/scenario.h"

namespace motostab::scenario {

using io::InputError;
using io::formatNumber;
using io::parseFiniteNumber;


namespace {

// The first words of every scenario `import` writes: a file that starts so may be replaced by an import.
constexpr const char* kImportHeader = "# Written by motostab import from ";

// The names of the benchmark parameter files (Moore et al. 2010; BicycleParameters' data/*/Parameters):
// g, w, c, lam; per wheel (R rear, F front) r, m and inertias; per body (B rear frame, H front frame,
// and G, S, the parts of H some data sets add) m, x, y, z and the six inertias.
bool isBicycleParameterName(const std::string& name) {
  static const std::set<std::string> known = [] {
    std::set<std::string> k{"g", "w", "c", "lam"};
    for (const std::string wheel : {"R", "F"})
      for (const std::string q : {"r", "m", "I@xx", "I@yy", "I@zz"}) k.insert(q[0] == 'I' ? "I" + wheel + q.substr(2) : q + wheel);
    for (const std::string body : {"B", "H", "G", "S"}) {
      for (const std::string q : {"m", "x", "y", "z"}) k.insert(q + body);
      for (const std::string axes : {"xx", "yy", "zz", "xy", "xz", "yz"}) k.insert("I" + body + axes);
    }
    return k;
  }();
  return known.count(name) > 0;
}

// One `value[+/-sigma]` item of a line; InputError at `where` if malformed.
std::pair<double, double> parseItem(const std::string& item, const io::InputLocation& where) {
  const auto pm = item.find("+/-");
  const std::string v = item.substr(0, pm);
  const auto x = parseFiniteNumber(v);
  if (!x) throw InputError(where, "not a finite number: '" + v + "'");
  if (pm == std::string::npos) return {*x, 0.0};
  const std::string sigmaText = item.substr(pm + 3);
  const auto sigma = parseFiniteNumber(sigmaText);
  if (!sigma || *sigma < 0)
    throw InputError(where, "the standard deviation after '+/-' must be a finite number >= 0 (got '" + sigmaText + "')");
  return {*x, *sigma};
}

}  // namespace

std::map<std::string, BicycleParameter> readBicycleParameterFile(const std::string& file) {
  std::istringstream in{std::string(io::stripByteOrderMark(io::readInputFile(file)))};
  std::map<std::string, BicycleParameter> out;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    const auto eq = line.find('=');
    std::string key = eq == std::string::npos ? "" : line.substr(0, eq);
    key.erase(0, key.find_first_not_of(" \t"));
    key.erase(key.find_last_not_of(" \t") + 1);
    if (key.empty()) throw InputError({file, lineNo, 0, ""}, "expected 'name = value+/-sigma'");
    if (!isBicycleParameterName(key))
      throw InputError({file, lineNo, 0, key}, "unknown parameter name (the benchmark names: g, w, c, lam; rR, mR, "
                                               "IRxx, IRyy, rF, mF, IFxx, IFyy; mB, xB, yB, zB, IBxx, IByy, IBzz, IBxy, "
                                               "IBxz, IByz and the same for H, G and S)");
    if (const auto it = out.find(key); it != out.end())
      throw InputError({file, lineNo, 0, key}, "given twice (first on line " + std::to_string(it->second.line) + ")");
    const std::vector<std::string> items = io::splitFields(line.substr(eq + 1), ',');
    double sum = 0, sumSquares = 0;
    for (const std::string& item : items) {
      const auto [value, sigma] = parseItem(item, {file, lineNo, 0, key});
      sum += value;
      sumSquares += sigma * sigma;
    }
    const double n = static_cast<double>(items.size());
    out[key] = {sum / n, std::sqrt(sumSquares) / n, lineNo};
  }
  return out;
}

std::map<std::string, double> readBicycleParameters(const std::string& file) {
  std::map<std::string, double> out;
  for (const auto& [name, p] : readBicycleParameterFile(file)) out[name] = p.value;
  return out;
}

namespace {

double getOr(const std::map<std::string, double>& p, const std::string& k, double fallback) {
  const auto it = p.find(k);
  return it == p.end() ? fallback : it->second;
}

// Inertia tensor of frame s in the benchmark frame (only the xx, yy, zz, xz keys are required).
Eigen::Matrix3d getFrameInertia(const std::map<std::string, double>& p, const std::string& s) {
  const std::string I = "I" + s;
  const double xy = getOr(p, I + "xy", 0), yz = getOr(p, I + "yz", 0), xz = getOr(p, I + "xz", 0);
  Eigen::Matrix3d M;
  M << getOr(p, I + "xx", 0), xy, xz, xy, getOr(p, I + "yy", 0), yz, xz, yz, getOr(p, I + "zz", 0);
  return M;
}

// Scenario comment lines recording each repaired inertia.
std::string formatRepairComments(const std::vector<InertiaRepair>& changes) {
  std::string c;
  for (const auto& r : changes)
    c += "# --repair-inertia: " + r.key + (r.after < r.before ? " lowered" : " raised") + " from " + formatNumber(r.before, 15) + " to " +
         formatNumber(r.after, 15) + " kg m^2 (" + r.explanation + ")\n";
  return c;
}

bool hasFrameInertia(const std::map<std::string, double>& p, const std::string& s) {
  for (const char* k : {"xx", "yy", "zz", "xz"})
    if (!p.count("I" + s + k)) return false;
  return true;
}

}  // namespace

std::string explainFrameInertia(const std::map<std::string, double>& p, const std::string& s) {
  if (!hasFrameInertia(p, s)) return "";
  const Eigen::Matrix3d M = getFrameInertia(p, s);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M);
  const Eigen::Vector3d l = es.eigenvalues();
  const double excess = l[2] - l[0] - l[1];
  if (excess <= 1e-12 * l.sum()) return "";
  const Eigen::Vector3d e = es.eigenvectors().col(2);
  int axis = 0;
  e.cwiseAbs().maxCoeff(&axis);
  char text[400];
  std::snprintf(text, sizeof text,
                "I%s: principal moments %.6g, %.6g, %.6g kg m^2 break the triangle inequality: the largest (%.6g, "
                "about an axis within %.1f deg of %c) exceeds the sum of the other two (%.6g) by %.4g kg m^2 "
                "(%.2f %%), which no rigid body can do",
                s.c_str(), l[0], l[1], l[2], l[2], std::acos(std::min(1.0, std::abs(e[axis]))) * 180 / M_PI, "xyz"[axis],
                l[0] + l[1], excess, 100 * excess / (l[0] + l[1]));
  return text;
}

std::vector<InertiaRepair> repairFrameInertias(std::map<std::string, double>& p, const std::string& file) {
  std::vector<InertiaRepair> out;
  for (const std::string s : {"B", "H"}) {
    const std::string why = explainFrameInertia(p, s), key = "I" + s + "yy";
    if (why.empty()) continue;
    const Eigen::Matrix3d M = getFrameInertia(p, s);
    if (M(0, 1) != 0 || M(1, 2) != 0)
      throw InputError({file, 0, 0, key}, why + "; --repair-inertia needs a frame symmetric about the x-z plane "
                                               "(I" + s + "xy = I" + s + "yz = 0)");
    // y is principal; the x-z block has moments m -/+ r. The triangle inequality holds for
    // |l_xz1 - l_xz2| = 2 r <= I_yy <= l_xz1 + l_xz2 = I_xx + I_zz: clamp I_yy onto the violated bound.
    const double r = std::hypot(0.5 * (M(0, 0) - M(2, 2)), M(0, 2));
    const double after = std::clamp(M(1, 1), 2 * r, M(0, 0) + M(2, 2));
    p[key] = after;
    out.push_back({key, M(1, 1), after, why});
  }
  return out;
}

std::string quoteYamlString(const std::string& text) {
  std::string q = "\"";
  for (const char ch : text) {
    if (ch == '"' || ch == '\\') q += '\\', q += ch;
    else if (static_cast<unsigned char>(ch) < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02x", static_cast<unsigned char>(ch));
      q += b;
    } else q += ch;
  }
  return q + "\"";
}

namespace {

// A frame inertia with a principal moment <= 0 is no body's, and no change of I_yy makes it one: an
// InputError at the line of its I<s>xx, before the triangle inequality and its repair are considered.
void checkPositiveDefinite(const std::map<std::string, BicycleParameter>& entries, const std::map<std::string, double>& p,
                           const std::string& file) {
  for (const std::string s : {"B", "H"}) {
    if (!hasFrameInertia(p, s)) continue;
    const Eigen::Vector3d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(getFrameInertia(p, s)).eigenvalues();
    if (l[0] > 0) continue;
    char text[300];
    std::snprintf(text, sizeof text,
                  "the %s frame's inertia tensor (I%sxx, I%syy, I%szz, I%sxz) is not positive definite: principal "
                  "moments %.6g, %.6g, %.6g kg m^2, and no body has a moment of inertia <= 0",
                  s == "B" ? "rear" : "front", s.c_str(), s.c_str(), s.c_str(), s.c_str(), l[0], l[1], l[2]);
    throw InputError({file, entries.at("I" + s + "xx").line, 0, "I" + s + "xx"}, text);
  }
}

// Without repair an impossible frame inertia is an InputError with the explanation and the way out.
std::vector<InertiaRepair> applyInertiaPolicy(std::map<std::string, double>& p, const std::string& file, bool repair) {
  if (repair) return repairFrameInertias(p, file);
  for (const std::string s : {"B", "H"}) {
    const std::string why = explainFrameInertia(p, s);
    if (!why.empty())
      throw InputError({file, 0, 0, "I" + s + "yy"},
                       why + ". --repair-inertia moves I" + s + "yy just onto the bound: the linearised Whipple model "
                       "(Meijaard et al. 2007) does not use the frames' I_yy, so its eigenvalues stay those of the file");
  }
  return {};
}

}  // namespace

std::string convertBicycleParametersToScenario(const std::string& file, const std::string& name,
                                               const BicycleImportOptions& options, std::vector<InertiaRepair>* repairs) {
  const auto entries = readBicycleParameterFile(file);
  std::map<std::string, double> p;
  for (const auto& [key, e] : entries) p[key] = e.value;
  checkPositiveDefinite(entries, p, file);
  const auto changes = applyInertiaPolicy(p, file, options.repairInertia);
  if (repairs) *repairs = changes;
  auto get = [&](const std::string& k) {
    const auto it = p.find(k);
    if (it == p.end()) throw InputError({file, 0, 0, k}, "missing parameter");
    return it->second;
  };
  auto opt = [&](const std::string& k, double fallback) { return p.count(k) ? p.at(k) : fallback; };
  auto num = [](double v) { return formatNumber(v, 15); };
  std::ostringstream y;
  y << kImportHeader << file << " (BicycleParameters benchmark format, Moore et al. 2010).\n"
    << "# Benchmark frame (y right, z down) converted to the design frame (y left, z up): z and I_xz change sign.\n"
    << formatRepairComments(changes) << "name: " << quoteYamlString(name) << "\n"
    << "description: imported benchmark parameters\n"
    << "gravity_mps2: " << num(get("g")) << "\n"
    << "speeds_mps: {start: 0, stop: 10, step: 0.1}\n"
    << "geometry:\n"
    << "  wheelbase_m: " << num(get("w")) << "\n"
    << "  trail_m: " << num(get("c")) << "\n"
    << "  steer_axis_tilt_deg: " << num(get("lam") * 180.0 / M_PI) << "\n";
  auto body = [&](const char* key, const char* s) {
    const std::string S(s);
    y << key << ":\n"
      << "  mass_kg: " << num(get("m" + S)) << "\n"
      << "  com_m: [" << num(get("x" + S)) << ", " << num(-opt("y" + S, 0)) << ", " << num(-get("z" + S)) << "]\n"
      << "  inertia_kgm2: {xx: " << num(get("I" + S + "xx")) << ", yy: " << num(get("I" + S + "yy"))
      << ", zz: " << num(get("I" + S + "zz")) << ", xy: " << num(-opt("I" + S + "xy", 0))
      << ", xz: " << num(-get("I" + S + "xz")) << ", yz: " << num(opt("I" + S + "yz", 0)) << "}\n";
  };
  auto wheel = [&](const char* key, const char* s) {
    const std::string S(s);
    const double diametral = get("I" + S + "xx");
    if (p.count("I" + S + "zz") && std::abs(p.at("I" + S + "zz") - diametral) > 1e-12)
      throw InputError({file, 0, 0, "I" + S + "zz"}, "wheel must be a body of revolution (I" + S + "zz = I" + S + "xx)");
    y << key << ":\n"
      << "  radius_m: " << num(get("r" + S)) << "\n"
      << "  crown_radius_m: 0\n"
      << "  mass_kg: " << num(get("m" + S)) << "\n"
      << "  spin_inertia_kgm2: " << num(get("I" + S + "yy")) << "\n"
      << "  diametral_inertia_kgm2: " << num(diametral) << "\n";
  };
  body("rear_frame", "B");
  body("front_frame", "H");
  wheel("rear_wheel", "R");
  wheel("front_wheel", "F");
  y << "contact: {model: rolling_no_slip}\n";
  return y.str();
}

namespace {

// `e`, an error in the scenario converted from the parameter file `file`, at the parameters behind its
// key path (getScenarioPathOfBicycleParameter): the file's line of the first, and their names.
InputError locateInParameterFile(const InputError& e, const std::string& file,
                                 const std::map<std::string, BicycleParameter>& parameters) {
  const std::string key = e.getLocation().key;
  std::string names;
  int line = 0;
  for (const auto& [name, p] : parameters) {
    const std::string path = getScenarioPathOfBicycleParameter(name).first;
    const bool behind = !key.empty() && (path == key || path.rfind(key + ".", 0) == 0 || path.rfind(key + "[", 0) == 0);
    if (!behind) continue;
    names += (names.empty() ? "" : ", ") + name;
    if (line == 0 || p.line < line) line = p.line;
  }
  return InputError({file, line, 0, names}, e.getReason() + " (in the converted scenario at " +
                                                (key.empty() ? std::string("its top level") : key) + ")");
}

}  // namespace

void writeBicycleParametersScenario(const std::string& file, const std::string& name, const std::filesystem::path& out,
                                    const BicycleImportOptions& options, std::vector<InertiaRepair>* repairs) {
  const auto parameters = readBicycleParameterFile(file);
  if (const std::string why = io::describeBadFolderName(name); !why.empty())
    throw InputError({"command line", 0, 0, "--name"}, "the scenario name '" + name + "' " + why);
  io::checkFileReplaceable(out, kImportHeader);
  const std::string text = convertBicycleParametersToScenario(file, name, options, repairs) +
                           formatBicycleParametersUncertainty(readBicycleParameterSigmas(file));
  io::writeFileAtomically(out, text, [&](const std::filesystem::path& temporary) {
    try {
      loadScenario(temporary.string());
    } catch (const InputError& e) {
      throw locateInParameterFile(e, file, parameters);
    }
  });
}

}  // namespace motostab::scenario

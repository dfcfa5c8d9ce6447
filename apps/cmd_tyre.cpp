// motostab tyre FILE.tir | SCENARIO.yaml --wheel front|rear, --fz N --slip-deg A:B:STEP --camber-deg G
// [--slip-ratio K] --out DIR: the steady-state forces of a tyre over a slip-angle range, to check a
// supplier's .tir file or a scenario's tyre before a sweep (DIR/forces.csv, DIR/fy_vs_slip and
// DIR/mz_vs_slip plots). A scenario's tyre is read as its contact plugin reads it: magic_formula in
// every variant (inline or from a file) or relaxation_linear's linear law.
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <utility>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "apps/option_checks.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "io/output_folder.h"
#include "io/yaml_map.h"
#include "output/tyre_curve_output.h"
#include "plugins/builtin.h"
#include "scenario/scenario.h"
#include "tyres/magic_formula.h"
#include "tyres/magic_formula_tyre.h"
#include "tyres/relaxation_linear.h"

namespace motostab::cli {

using io::InputError;
using io::OutputFolder;
using io::YamlMap;
using io::formatNumber;
using output::TyreCurvePoint;
using output::writeTyreCurve;
using scenario::Scenario;
using scenario::loadScenario;
using tyres::MagicFormulaVariant;
using tyres::MotorcyclePaperAxes;
using tyres::MotorcycleSlipVariable;
using tyres::TyreForceLaw;

namespace {

struct TyreArgs {
  std::string file, slipRange, out, wheel;
  std::vector<std::string> overrides;
  double fz = 0, camberDeg = 0, slipRatio = 0, speed = NAN;
};

// The tyre to draw: its law, what to call it, and the contact's relaxation length (NaN: the law's).
struct InspectedTyre {
  std::shared_ptr<const TyreForceLaw> law;
  std::string kind;   ///< "Magic Formula 61", "relaxation_linear", ...
  std::string name;   ///< the file, or "SCENARIO front tyre"
  std::string outStem;
  double relaxationLength = NAN;
};

// "A:B:STEP" in degrees: finite, A <= B, STEP > 0, at most 1e5 points.
std::vector<double> parseSlipRange(const std::string& text) {
  const std::vector<double> v =
      parseRangeFields(text, "--slip-deg", false, "A:B:STEP in degrees, finite, with A <= B, STEP > 0 and at most 1e5 points");
  return makeSlipAngles(v[0], v[1], v[2], {"--slip-deg", 0, 0, text});
}

bool isScenarioPath(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".yaml" || ext == ".yml";
}

InspectedTyre loadTirTyre(const std::string& path) {
  TirForceLaw tir = loadTirForCurve(path, std::cerr);
  InspectedTyre t;
  t.law = std::move(tir.law);
  t.kind = "Magic Formula " + std::to_string(tir.file.getFitType());
  t.name = path;
  t.outStem = std::filesystem::path(path).stem().string();
  return t;
}

std::string describeMagicFormula(const tyres::MagicFormulaTyre& t) {
  if (t.variant == MagicFormulaVariant::MF61) return "Magic Formula 61";
  if (t.variant == MagicFormulaVariant::MF62) return "Magic Formula 62";
  return std::string("motorcycle Magic Formula (paper_axes ") +
         (t.conventions.axes == MotorcyclePaperAxes::ZDown ? "z_down" : "z_up") + ", slip_variable " +
         (t.conventions.slip == MotorcycleSlipVariable::Angle ? "angle" : "tangent") + ")";
}

// The wheel's tyre of a scenario's contact section, read (both tyres, strictly) as its plugin reads it.
InspectedTyre readContactTyre(const Scenario& s, const std::string& wheel) {
  YamlMap contact(s.contact.params, s.contact.file, s.contact.path, s.inputs);
  contact.markUsed("model");
  InspectedTyre t;
  const bool front = wheel == "front";
  if (s.contact.model == "magic_formula") {
    const tyres::MagicFormulaTyre frontTyre = tyres::readMagicFormulaTyre(contact.getMap("front"));
    const tyres::MagicFormulaTyre rearTyre = tyres::readMagicFormulaTyre(contact.getMap("rear"));
    const tyres::MagicFormulaTyre& tyre = front ? frontTyre : rearTyre;
    checkCrownRadius(tyre, wheel + "_wheel", (front ? s.frontWheel : s.rearWheel).crownRadius);
    t.law = tyre.law;
    t.kind = describeMagicFormula(tyre);
    t.relaxationLength = tyre.relaxationLength;
  } else if (s.contact.model == "relaxation_linear") {
    const auto [frontTyre, rearTyre] = tyres::readRelaxationLinearTyres(contact);
    t.law = tyres::makeLinearTyreForceLaw(front ? frontTyre : rearTyre);
    t.kind = "relaxation_linear";
  } else {
    contact.fail("model", "the contact model '" + s.contact.model +
                              "' has no tyre force law to draw (motostab tyre takes magic_formula and relaxation_linear)");
  }
  contact.finish();
  t.name = s.sourceFile + " " + wheel + " tyre";
  t.outStem = s.name + "-" + wheel;
  return t;
}

InspectedTyre loadScenarioTyre(const TyreArgs& a) {
  if (a.wheel != "front" && a.wheel != "rear")
    throw InputError({"command line", 0, 0, "--wheel"}, "'" + a.wheel + "': expected front or rear");
  const Scenario s = loadScenario(a.file, a.overrides);
  try {
    InspectedTyre t = readContactTyre(s, a.wheel);
    plugins::makeBuiltinRegistry().createExtensionModels(s, s.inputs);  // its extension sections, checked
    for (const io::InputWarning& w : s.inputs->getWarnings())
      std::cerr << "motostab: warning: " << w.where.describe() << ": " << w.message << "\n";
    return t;
  } catch (const InputError& e) {
    scenario::rethrowNamingOverride(e, s.overrides);
  }
}

InspectedTyre loadTyre(const TyreArgs& a) {
  const bool scenarioForm = !a.wheel.empty();
  if (!scenarioForm && isScenarioPath(a.file))
    throw InputError({"command line", 0, 0, "--wheel"}, "a scenario's tyre needs --wheel front|rear");
  if (!scenarioForm && !a.overrides.empty())
    throw InputError({"command line", 0, 0, "--set"}, "--set changes a scenario: give SCENARIO.yaml --wheel front|rear");
  if (scenarioForm && !isScenarioPath(a.file))
    throw InputError({"command line", 0, 0, "--wheel"}, "--wheel picks a scenario's tyre: give a SCENARIO.yaml (.yaml or .yml)");
  return scenarioForm ? loadScenarioTyre(a) : loadTirTyre(a.file);
}

// The relaxation length line: the contact's constant, or the law's at the speeds `speeds`.
std::string describeRelaxation(const InspectedTyre& t, double Fz, double camber, const std::vector<double>& speeds) {
  std::ostringstream s;
  if (!std::isnan(t.relaxationLength)) {
    s << formatNumber(t.relaxationLength, 6) << " m (the scenario's relaxation_length_m)";
    return s.str();
  }
  if (std::isnan(t.law->calcRelaxationLength(Fz, camber, speeds.front())))
    return "not given (the coefficients have none; a scenario gives relaxation_length_m)";
  for (size_t i = 0; i < speeds.size(); ++i)
    s << (i ? ", " : "") << formatNumber(t.law->calcRelaxationLength(Fz, camber, speeds[i]), 6) << " m at "
      << formatNumber(speeds[i], 6) << " m/s";
  return s.str();
}

// The longitudinal relaxation length line (reported only): the law's, or why there is none.
std::string describeLongitudinalRelaxation(const TyreForceLaw& law, double Fz) {
  const double sigma = law.calcLongitudinalRelaxationLength(Fz);
  if (std::isnan(sigma)) return "not given (MF 6.x only, from LONGITUDINAL_STIFFNESS, which these coefficients lack)";
  return formatNumber(sigma, 6) + " m (reported only)";
}

void runTyre(const TyreArgs& a) {
  const std::vector<double> slips = parseSlipRange(a.slipRange);
  const InspectedTyre tyre = loadTyre(a);
  const TyreForceLaw& law = *tyre.law;
  // The speed of the rows (it enters MF 6.x rolling resistance only) and of the relaxation lengths.
  const double reference = law.getReferenceSpeed();
  std::vector<double> speeds{20};
  if (!std::isnan(a.speed)) speeds = {a.speed};
  else if (!std::isnan(reference)) speeds = {reference};
  else if (std::isnan(tyre.relaxationLength)) speeds = {10, 20, 40};
  const double camber = a.camberDeg * M_PI / 180;
  const std::vector<TyreCurvePoint> points = calcTyreCurve(law, a.fz, slips, camber, a.slipRatio, speeds.front());
  const std::filesystem::path target = getOutputFolder(a.out, tyre.outStem, "tyre");
  OutputFolder folder(target);
  std::ostringstream title;
  title << std::filesystem::path(tyre.name).filename().string() << ", Fz " << a.fz << " N, camber " << a.camberDeg
        << " deg, slip ratio " << a.slipRatio;
  writeTyreCurve(folder.getPath(), title.str(), points);
  folder.commit();
  std::cout << tyre.kind << " tyre " << tyre.name << " at Fz = " << a.fz << " N (ISO signs):\n"
            << "  cornering stiffness dFy/dalpha = " << formatNumber(law.calcCorneringStiffness(a.fz), 6) << " N/rad\n"
            << "  camber stiffness    dFy/dgamma = " << formatNumber(law.calcCamberStiffness(a.fz), 6) << " N/rad\n"
            << "  slip stiffness      dFx/dkappa = " << formatNumber(law.calcLongitudinalStiffness(a.fz), 6) << " N\n"
            << "  relaxation length   sigma      = " << describeRelaxation(tyre, a.fz, camber, speeds) << "\n"
            << "  longitudinal relaxation length = " << describeLongitudinalRelaxation(law, a.fz) << "\n"
            << "Wrote " << (target / "forces.csv").string() << " (" << points.size() << " rows) and "
            << (target / "{fy,mz}_vs_slip.{png,svg,gp}").string() << "\n";
}

}  // namespace

void registerTyreCommands(CLI::App& app) {
  auto a = std::make_shared<TyreArgs>();
  CLI::App* cmd = app.add_subcommand(
      "tyre", "Steady-state forces of a tyre over slip angle: a Magic Formula .tir file (MF 6.1/6.2), or a scenario's tyre (--wheel)");
  cmd->add_option("file", a->file, "Tyre property file (.tir, FITTYP 61 or 62), or a scenario (.yaml) with --wheel")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--wheel", a->wheel, "With a scenario: the tyre to draw, front or rear");
  cmd->add_option("--set", a->overrides, "With a scenario: override a value, e.g. --set contact.front.paper_axes=z_up");
  cmd->add_option("--fz", a->fz, "Normal load, N")->required()->check(makeNumberCheck(kTyreLoadN));
  cmd->add_option("--slip-deg", a->slipRange, "Slip angles A:B:STEP, degrees (ISO sign)")->required();
  cmd->add_option("--camber-deg", a->camberDeg, "Camber (inclination) angle, degrees (ISO sign: top leaning right > 0)")
      ->required()
      ->check(makeNumberCheck(kCamberDeg));
  cmd->add_option("--slip-ratio", a->slipRatio, "Longitudinal slip ratio")->capture_default_str()->check(makeNumberCheck(kSlipRatio));
  cmd->add_option("--speed", a->speed,
                  "Forward speed, m/s: rolling resistance and the relaxation length (default: the coefficients' LONGVL; "
                  "without one the relaxation length is shown at 10, 20 and 40 m/s)")
      ->check(makeNumberCheck(kSpeedMps));
  addOutOption(*cmd, a->out, "FILE's stem, or SCENARIO's name-WHEEL,");
  cmd->callback([a] { runTyre(*a); });
}

}  // namespace motostab::cli

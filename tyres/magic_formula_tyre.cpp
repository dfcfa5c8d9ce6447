#include "tyres/magic_formula_tyre.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace motostab::tyres {

using io::YamlMap;

namespace {

// The scenario's `scaling` map: names of the variant's factors, values findScalingProblem accepts.
std::map<std::string, double> readScaling(YamlMap& m, MagicFormulaVariant variant) {
  std::map<std::string, double> out;
  if (!m.has("scaling")) return out;
  YamlMap s = m.getMap("scaling");
  const auto& names = getScalingNames(variant);
  for (const auto& kv : s.getNode()) {
    const std::string name = kv.first.as<std::string>();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      std::string known;
      for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
      s.fail(name, "not a scaling factor of this Magic Formula variant (known: " + known + ")");
    }
    out[name] = s.getDouble(name);
    const std::string problem = findScalingProblem(name, out[name]);
    if (!problem.empty()) s.fail(name, problem);
  }
  s.finish();
  return out;
}

// A radial law value: the scenario's key, else the coefficient `fileKey` of the source.
double readRadial(YamlMap& m, const char* key, const CoefficientSource& source, const char* fileKey, bool positive) {
  const auto fromFile = source.find(fileKey);  // read always, so that an inline map's key counts as used
  if (m.has(key)) return positive ? m.getPositive(key) : m.getNonNegative(key);
  if (!fromFile) m.fail(key, std::string("missing: give it here or as ") + fileKey + " with the coefficients");
  if (positive ? !(*fromFile > 0) : !(*fromFile >= 0)) source.fail(fileKey, positive ? "must be positive" : "must be >= 0");
  return *fromFile;
}

// The motorcycle variant's reading of the paper (paper_axes, slip_variable); refused for MF 6.x.
MotorcycleConventions readConventions(YamlMap& m, MagicFormulaVariant variant) {
  MotorcycleConventions c;
  for (const char* key : {"paper_axes", "slip_variable"})
    if (m.has(key) && variant != MagicFormulaVariant::Motorcycle) m.fail(key, "only for variant: motorcycle");
  if (m.has("paper_axes")) {
    const auto axes = parseMotorcyclePaperAxes(m.getString("paper_axes"));
    if (!axes) m.fail("paper_axes", "unknown axes (known: z_down, z_up)");
    c.axes = *axes;
  }
  if (m.has("slip_variable")) {
    const auto slip = parseMotorcycleSlipVariable(m.getString("slip_variable"));
    if (!slip) m.fail("slip_variable", "unknown slip variable (known: angle, tangent)");
    c.slip = *slip;
  }
  return c;
}

}  // namespace

MagicFormulaTyre readMagicFormulaTyre(YamlMap m) {
  if (m.has("tir") == m.has("coefficients")) m.fail("tir", "give exactly one of `tir: FILE` and `coefficients: {...}`");
  std::optional<MagicFormulaVariant> variant;
  if (m.has("variant")) {
    variant = parseMagicFormulaVariant(m.getString("variant"));
    if (!variant) m.fail("variant", "unknown Magic Formula variant (known: mf61, mf62, motorcycle)");
  }
  std::optional<double> pressure;
  if (m.has("pressure_Pa")) pressure = m.getPositive("pressure_Pa");
  MagicFormulaTyre t;
  auto build = [&](const CoefficientSource& source) {
    t.variant = *variant;
    t.conventions = readConventions(m, *variant);
    t.law = makeTyreForceLaw(*variant, source, pressure, t.conventions);
    t.radial.stiffness = readRadial(m, "radial_stiffness_N_per_m", source, "VERTICAL_STIFFNESS", true);
    t.radial.damping = readRadial(m, "radial_damping_Ns_per_m", source, "VERTICAL_DAMPING", false);
  };
  if (m.has("tir")) {
    const std::string path = m.getFilePath("tir");
    if (!std::filesystem::is_regular_file(path)) m.fail("tir", "cannot open the tyre property file " + path);
    const TirFile file = TirFile::parse(m.readFileText("tir", TirFile::kMaxBytes), path);
    if (!variant) variant = file.getFitType() == 62 ? MagicFormulaVariant::MF62 : MagicFormulaVariant::MF61;
    const auto scaling = readScaling(m, *variant);
    const auto source = makeTirSource(file, &scaling);
    build(*source);
    const std::string unused = describeUnused(*source, path);
    if (!unused.empty()) m.warn("tir", unused);
  } else {
    if (!variant) m.fail("variant", "required with inline coefficients (mf61, mf62 or motorcycle)");
    const auto scaling = readScaling(m, *variant);
    YamlMap coefficients = m.getMap("coefficients");
    build(*makeYamlSource(coefficients, &scaling));
    coefficients.finish();
  }
  if (m.has("relaxation_length_m")) t.relaxationLength = m.getZeroOrAtLeast("relaxation_length_m", kMinRelaxationLength, "m", 0);
  t.where = m.locate();
  if (std::isnan(t.relaxationLength) && std::isnan(t.law->calcRelaxationLength(t.law->getNominalLoad(), 0, 0)))
    m.fail("relaxation_length_m", "required: this Magic Formula variant has no relaxation length of its own");
  m.finish();
  return t;
}

void checkCrownRadius(const MagicFormulaTyre& tyre, const std::string& wheel, double crownRadius) {
  const double crown = tyre.law->getCrownRadius();
  if (!std::isnan(crown) && std::abs(crown - crownRadius) > 1e-9)
    throw io::InputError(tyre.where, "CROWN_RADIUS " + std::to_string(crown) + " m of the coefficients differs from " + wheel +
                                         ".crown_radius_m " + std::to_string(crownRadius) + " m");
}

}  // namespace motostab::tyres

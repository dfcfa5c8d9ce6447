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
double readRadial(YamlMap& m, const io::Field& field, const CoefficientSource& source, const char* fileKey) {
  const char* key = field.key.c_str();
  const bool positive = field.range == io::Range::Positive;
  const auto fromFile = source.find(fileKey);  // read always, so that an inline map's key counts as used
  if (m.has(key)) return io::readNumber(m, field);
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

const io::SectionFields& getMagicFormulaTyreFields() {
  using io::Field;
  using io::Range;
  using io::Shape;
  static const io::SectionFields f{
      "",
      {Field::of(Shape::Other, "tir", "", "", "an MF 6.1/6.2 property file, relative to the scenario; or `coefficients`").optional(),
       Field::of(Shape::Other, "coefficients", "", "", "inline coefficients `{NAME: value}` (names of the .tir file), with `variant`")
           .optional(),
       Field::of(Shape::Other, "variant", "", "", "`mf61`, `mf62` or `motorcycle`; beside `tir` its FITTYP by default").optional(),
       Field::of(Shape::Other, "scaling", "", "", "scaling factors `{LKY: ...}` of the variant (tyres.md)").optional(),
       Field::number("pressure_Pa", "Pa", Range::Positive, "inflation pressure; absent: INFLPRES, else NOMPRES").optional(),
       Field::number("relaxation_length_m", "m", Range::Any,
                     "sigma (0: no lag); required only when the law has no relaxation length of its own")
           .within("0 or >= 1e-4")
           .optional(),
       Field::number("radial_stiffness_N_per_m", "N/m", Range::Positive, "radial stiffness; absent: VERTICAL_STIFFNESS").optional(),
       Field::number("radial_damping_Ns_per_m", "N s/m", Range::NonNegative, "radial damping; absent: VERTICAL_DAMPING").optional(),
       Field::of(Shape::Other, "paper_axes", "", "", "`z_down` (default) or `z_up`: how the paper's equations are read (variant `motorcycle`)")
           .optional(),
       Field::of(Shape::Other, "slip_variable", "", "", "`angle` (default) or `tangent` (variant `motorcycle`)").optional()}};
  return f;
}

MagicFormulaTyre readMagicFormulaTyre(YamlMap m) {
  const io::SectionFields& f = getMagicFormulaTyreFields();
  if (m.has("tir") == m.has("coefficients")) m.fail("tir", "give exactly one of `tir: FILE` and `coefficients: {...}`");
  std::optional<MagicFormulaVariant> variant;
  if (m.has("variant")) {
    variant = parseMagicFormulaVariant(m.getString("variant"));
    if (!variant) m.fail("variant", "unknown Magic Formula variant (known: mf61, mf62, motorcycle)");
  }
  std::optional<double> pressure;
  if (m.has("pressure_Pa")) pressure = io::readNumber(m, f.get("pressure_Pa"));
  MagicFormulaTyre t;
  auto build = [&](const CoefficientSource& source) {
    t.variant = *variant;
    t.conventions = readConventions(m, *variant);
    t.law = makeTyreForceLaw(*variant, source, pressure, t.conventions);
    t.radial.stiffness = readRadial(m, f.get("radial_stiffness_N_per_m"), source, "VERTICAL_STIFFNESS");
    t.radial.damping = readRadial(m, f.get("radial_damping_Ns_per_m"), source, "VERTICAL_DAMPING");
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
  if (m.has("relaxation_length_m"))
    t.relaxationLength = m.getZeroOrAtLeast(f.get("relaxation_length_m").key, kMinRelaxationLength, "m", 0);
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

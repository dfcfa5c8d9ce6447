// The declared fields of every scenario section (io/field.h): the docs tables are the declarations',
// each reader refuses a value outside its field's declared range at that key, and the parameter list
// takes the measured fields with their declared quantity.
#include <gtest/gtest.h>

#include "tests/support/text_file.h"

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/portable_random.h"
#include "tests/support/temp_dir.h"
#include "io/field.h"
#include "io/number.h"
#include "plugins/builtin.h"
#include "scenario/parameter_paths.h"
#include "scenario/scenario.h"
#include "scenario/scenario_source.h"
#include "vehicle/vehicle_model.h"

namespace motostab::extensions {

using core::PortableRandom;
using io::Field;
using io::Range;
using io::SectionFields;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

// The enduro with every built-in extension, each with all its optional numbers given.
const std::vector<std::string> kEverySection{
    "swingarm.suspension={wheel_rate_N_per_m: 20000, damping_Ns_per_m: 1500}",
    "aerodynamics={drag_area_m2: 0.45, air_density_kgpm3: 1.2, centre_of_pressure_m: [0.7, 0, 0.9]}",
    "steer_damper={damping_Nms_per_rad: 2, coulomb_Nm: 0.3, coulomb_smoothing_rad_per_s: 0.2}",
    "rider_arms={inertia_kgm2: 0.2, stiffness_Nm_per_rad: 50, damping_Nms_per_rad: 6, grip_half_width_m: 0.3}",
    "steer_controller={roll_angle_Nm_per_rad: -5, roll_rate_Nms_per_rad: -1, steer_angle_Nm_per_rad: 2, "
    "steer_rate_Nms_per_rad: 0.5, gain_factor: 1.1, schedule: {below_mps: 6}, delay_s: 0.01, torque_limit_Nm: 30}",
    "rider_lean={hinge_height_m: 0.9, mass_kg: 30, com_m: [0.45, 0, 1.2], inertia_kgm2: {xx: 1.4, yy: 1.5, zz: 0.5, xy: 0, "
    "xz: 0, yz: 0}, stiffness_Nm_per_rad: 1500, damping_Nms_per_rad: 50}",
    "fork_compliance={stiffness_Nm_per_rad: 40000, damping_Nms_per_rad: 20, axis_distance_along_steer_m: 0.7, "
    "carrier_mass_fraction: 0.3, torsion: {stiffness_Nm_per_rad: 30000, damping_Nms_per_rad: 10}}",
    "steer_head_friction={torque_Nm: 0.5, smoothing_rad_per_s: 0.1}"};

// The scenario tree of the enduro with every section.
YAML::Node makeExtendedTree() { return scenario::ScenarioSource(kEnduro).makeTree(scenario::ParameterOverrides(kEverySection)); }

std::vector<SectionFields> getDeclaredSections() { return plugins::listSectionFields(plugins::makeBuiltinRegistry()); }

// docs/scenario-format.md holds each declared section's table verbatim (`motostab fields` prints
// them), and no table of that form without a declaration.
TEST(DeclaredFields, DocsTablesAreTheDeclarations) {
  const std::string docs = readText(std::string(MOTOSTAB_SOURCE_DIR) + "/docs/scenario-format.md");
  const std::vector<SectionFields> sections = getDeclaredSections();
  for (const SectionFields& s : sections) {
    const std::string table = io::formatFieldTable(s);
    EXPECT_NE(docs.find(io::formatSectionHeading(s) + "\n\n" + table), std::string::npos)
        << "docs/scenario-format.md lacks or differs from the table of `" << s.path << "` (motostab fields " << s.path
        << "):\n" << table;
  }
  const std::string header = "| key | unit | range | default | meaning |";
  size_t count = 0;
  for (size_t at = docs.find(header); at != std::string::npos; at = docs.find(header, at + 1)) ++count;
  EXPECT_EQ(count, sections.size()) << "tables in the docs without a declared section";
}

// Every number field present in the fully extended enduro, set outside its declared range (a value
// drawn in the test), is an InputError at that key when the model is built.
TEST(DeclaredFields, ReadersRefuseValuesOutsideTheDeclaredRange) {
  const Scenario base = loadScenario(kEnduro, kEverySection);
  ASSERT_NO_THROW(VehicleModel{base});
  const YAML::Node tree = makeExtendedTree();
  PortableRandom rng(20261129);
  int checked = 0;
  for (const SectionFields& s : getDeclaredSections())
    for (const Field& f : s.fields) {
      if (!s.isSelectedIn(tree) || f.shape != io::Shape::Number || !io::findKeyPath(tree, s.getKeyPath(f.key))) continue;
      const double u = rng.drawUniform(0.01, 10);
      double bad = 0;
      switch (f.range) {
        case Range::Positive: bad = rng.drawUniform() < 0.3 ? 0.0 : -u; break;
        case Range::NonNegative: bad = -u; break;
        case Range::Fraction: bad = rng.drawUniform() < 0.5 ? 1 + u : -u; break;
        default: continue;
      }
      const std::string path = s.getKeyPath(f.key);
      try {
        const VehicleModel model(loadScenario(kEnduro, [&] {
          std::vector<std::string> o = kEverySection;
          o.push_back(scenario::formatOverride(path, bad));
          return o;
        }()));
        ADD_FAILURE() << path << " = " << bad << " accepted";
      } catch (const io::InputError& e) {
        EXPECT_EQ(e.getLocation().key, path) << e.what();
      }
      ++checked;
    }
  EXPECT_GE(checked, 30);  // the core sections' and every extension's ranged numbers
  // A dotted top-level key is no section name (the rear suspension is written inside the swingarm).
  const std::string dotted = (makeTempDir("declared_fields") / "dotted.yaml").string();
  std::ofstream(dotted) << readText(kEnduro) << "\"swingarm.suspension\": {wheel_rate_N_per_m: 2.0e4, damping_Ns_per_m: 1.0e3}\n";
  try {
    const VehicleModel model(loadScenario(dotted));
    ADD_FAILURE() << "a dotted top-level section was accepted";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no '.'"), std::string::npos) << e.what();
  }
}

// The parameter list is the measured fields present, with their declared quantity; fields that are
// settings of an element (a damper's damping, a suspension's rate) are not measured properties.
TEST(DeclaredFields, ParameterListIsTheMeasuredFields) {
  const YAML::Node tree = makeExtendedTree();
  const std::vector<SectionFields> sections = getDeclaredSections();
  std::map<std::string, io::Quantity> listed;
  for (const auto& p : scenario::listScalarParameters(tree, sections)) EXPECT_TRUE(listed.emplace(p.path, p.kind).second) << p.path;
  EXPECT_EQ(listed.at("rider_arms.grip_half_width_m"), io::Quantity::Length);
  EXPECT_EQ(listed.at("rider_arms.inertia_kgm2"), io::Quantity::Inertia);
  EXPECT_EQ(listed.at("rider_lean.inertia_kgm2.xz"), io::Quantity::Inertia);
  EXPECT_EQ(listed.at("rider_lean.com_m[2]"), io::Quantity::Length);
  EXPECT_EQ(listed.count("rider_lean.com_m[1]"), 0u);  // in the plane of symmetry: y is 0, no parameter
  // A fit keeps the sign of masses, radii, trails and positive settings, not of a product of inertia.
  std::map<std::string, bool> positive;
  for (const auto& p : scenario::listScalarParameters(tree, sections)) positive[p.path] = p.positive;
  for (const char* kept : {"total.mass_kg", "geometry.normal_trail_m", "rear_wheel.crown_radius_m", "rider_lean.inertia_kgm2.xx",
                           "rider_lean.stiffness_Nm_per_rad"})
    EXPECT_TRUE(positive.at(kept)) << kept;
  for (const char* free : {"rider_lean.inertia_kgm2.xz", "total.com_m[0]", "steer_controller.roll_angle_Nm_per_rad"})
    EXPECT_FALSE(positive.at(free)) << free;
  EXPECT_EQ(listed.at("steer_controller.schedule.below_mps"), io::Quantity::Other);
  EXPECT_EQ(listed.at("steer_controller.delay_s"), io::Quantity::Other);
  EXPECT_EQ(listed.at("geometry.steer_axis_tilt_deg"), io::Quantity::Angle);
  EXPECT_EQ(listed.at("swingarm.pivot_m[2]"), io::Quantity::Length);
  for (const char* setting : {"steer_damper.damping_Nms_per_rad", "swingarm.suspension.wheel_rate_N_per_m",
                              "aerodynamics.drag_area_m2", "fork_compliance.stiffness_Nm_per_rad", "steer_head_friction.torque_Nm"})
    EXPECT_EQ(listed.count(setting), 0u) << setting;
  // Each entry belongs to a measured field (its path up to the field's key is declared and measured).
  std::set<std::string> measured;
  for (const SectionFields& s : sections)
    for (const Field& f : s.fields)
      if (f.measured) measured.insert(s.getKeyPath(f.key));
  for (const auto& [path, kind] : listed) {
    bool found = measured.count(path) > 0;
    for (const std::string& m : measured) found |= path.rfind(m + ".", 0) == 0 || path.rfind(m + "[", 0) == 0;
    EXPECT_TRUE(found) << path;
  }
}

}  // namespace
}  // namespace motostab::extensions

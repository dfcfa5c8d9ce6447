// Declared fields (io/field.h): a number is read with its declared range and default; the docs
// table prints one row per field.
#include "io/field.h"

#include <gtest/gtest.h>

#include <string>

#include "core/portable_random.h"
#include "io/input_error.h"
#include "io/number.h"

namespace motostab::io {

using core::PortableRandom;

namespace {

YamlMap makeMap(const std::string& yaml) { return YamlMap(YAML::Load(yaml), "test.yaml", "section"); }

TEST(Field, NumbersAreReadWithinTheirDeclaredRange) {
  PortableRandom rng(20261129);
  const Field positive = Field::number("k_Nm_per_rad", "N m/rad", Range::Positive, "stiffness");
  const Field nonNegative = Field::number("c_Nms_per_rad", "N m s/rad", Range::NonNegative, "damping");
  const Field fraction = Field::number("share", "", Range::Fraction, "a share");
  const Field any = Field::number("gain", "N m/rad", Range::Any, "a gain");
  for (int i = 0; i < 20; ++i) {
    const double v = 1e-3 + 1e3 * rng.drawUniform(), u = rng.drawUniform();
    YamlMap ok = makeMap("{k_Nm_per_rad: " + formatNumber(v) + ", c_Nms_per_rad: 0, share: " + formatNumber(0.01 + 0.98 * u) +
                         ", gain: " + formatNumber(-v) + "}");
    EXPECT_EQ(readNumber(ok, positive), v);
    EXPECT_EQ(readNumber(ok, nonNegative), 0.0);
    EXPECT_EQ(readNumber(ok, fraction), 0.01 + 0.98 * u);
    EXPECT_EQ(readNumber(ok, any), -v);
    ok.finish();
    YamlMap bad = makeMap("{k_Nm_per_rad: 0, c_Nms_per_rad: " + formatNumber(-v) + ", share: " + formatNumber(1 + u) + "}");
    for (const Field* f : {&positive, &nonNegative, &fraction}) {
      try {
        readNumber(bad, *f);
        ADD_FAILURE() << f->key << " accepted out of range";
      } catch (const InputError& e) {
        EXPECT_EQ(e.getLocation().key, "section." + f->key) << e.what();
        EXPECT_EQ(e.getLocation().line, 1) << e.what();
      }
    }
  }
}

TEST(Field, AnAbsentOptionalNumberTakesItsDefault) {
  const Field smoothing = Field::number("smoothing_rad_per_s", "rad/s", Range::Positive, "").withDefault(0.1);
  YamlMap empty = makeMap("{}");
  EXPECT_EQ(readNumber(empty, smoothing), 0.1);
  YamlMap given = makeMap("{smoothing_rad_per_s: 0.25}");
  EXPECT_EQ(readNumber(given, smoothing), 0.25);
  // Required and absent: the reader names the missing key.
  EXPECT_THROW(readNumber(empty, Field::number("torque_Nm", "N m", Range::NonNegative, "")), InputError);
  // Optional without a default must be asked with has() first; asking for an undeclared key is a bug.
  EXPECT_THROW(readNumber(empty, Field::number("limit_Nm", "N m", Range::Positive, "").optional()), std::logic_error);
  const SectionFields section{"s", {smoothing}};
  EXPECT_THROW(section.get("smoothing"), std::logic_error);
  EXPECT_EQ(&section.get("smoothing_rad_per_s"), &section.fields[0]);
}

TEST(Field, TableHasOneRowPerFieldWithUnitRangeAndDefault) {
  const SectionFields section{
      "steer_thing",
      {Field::number("torque_Nm", "N m", Range::NonNegative, "T_f, breakaway torque"),
       Field::number("smoothing_rad_per_s", "rad/s", Range::Positive, "omega_s").withDefault(0.1),
       Field::number("share", "", Range::Fraction, "a share").optional(),
       Field::number("delay_s", "s", Range::Any, "tau").within("0, or >= 1e-4").withDefault(0),
       Field::of(Shape::Vector3, "point_m", "m", "", "a point")}};
  const std::string expected =
      "| key | unit | range | default | meaning |\n"
      "|---|---|---|---|---|\n"
      "| `torque_Nm` | N m | >= 0 | required | T_f, breakaway torque |\n"
      "| `smoothing_rad_per_s` | rad/s | > 0 | 0.1 | omega_s |\n"
      "| `share` | - | 0 < x < 1 | none | a share |\n"
      "| `delay_s` | s | 0, or >= 1e-4 | 0 | tau |\n"
      "| `point_m` [x, y, z] | m | any | required | a point |\n";
  EXPECT_EQ(formatFieldTable(section), expected);
}

// A key one typing error from a declared one (drawn: a letter replaced, dropped or added) is suggested;
// a key far from all lists the section's keys; a path no section declares gets no hint.
TEST(Field, UnknownKeysGetTheDeclaredKeyMeant) {
  const std::vector<SectionFields> sections{
      {"geometry",
       {Field::number("wheelbase_m", "m", Range::Positive, "w"), Field::number("trail_m", "m", Range::Any, "c"),
        Field::number("steer_axis_tilt_deg", "deg", Range::Any, "lambda")}}};
  PortableRandom rng(31);
  for (int trial = 0; trial < 30; ++trial) {
    const std::string key = sections[0].fields[static_cast<size_t>(rng.drawUniform() * 3) % 3].key;
    std::string typo = key;
    const size_t at = static_cast<size_t>(rng.drawUniform() * typo.size()) % typo.size();
    const char letter = static_cast<char>('a' + static_cast<int>(rng.drawUniform() * 26) % 26);
    switch (trial % 3) {
      case 0: typo[at] = typo[at] == letter ? 'q' : letter; break;
      case 1: typo.erase(at, 1); break;
      default: typo.insert(at, 1, letter);
    }
    EXPECT_EQ(describeDeclaredKeys(sections, "geometry." + typo), " (did you mean `" + key + "`?)") << typo;
  }
  EXPECT_EQ(describeDeclaredKeys(sections, "geometry.colour"), " (`geometry` declares: wheelbase_m, trail_m, steer_axis_tilt_deg)");
  EXPECT_EQ(describeDeclaredKeys(sections, "nowhere.trial_m"), "");
  // A section with a selector (a contact model's) and the top level give no hint.
  std::vector<SectionFields> selected{sections[0].selectedBy("contact.model", "x")};
  EXPECT_EQ(describeDeclaredKeys(selected, "geometry.trial_m"), "");
  std::vector<SectionFields> top{{"", {Field::number("gravity_mps2", "m/s^2", Range::NonNegative, "g")}}};
  EXPECT_EQ(describeDeclaredKeys(top, "gravity_mps3"), "");
}

}  // namespace
}  // namespace motostab::io

// Whole-vehicle input (`total:`): the rear frame is the total minus every other body, exactly. Random
// vehicles (seeded) are composed here, independently of the loader (own parallel-axis sums, own
// swingarm frame), written as scenarios with `total:`, loaded, and built: the rear frame comes back
// and the Simbody model's own totals (SimbodyMatterSubsystem::calcSystemMass, ...MassCenterLocation,
// ...CentralInertia) equal the drawn total to 1e-9. The bundled motorcycles reproduce the seed's
// Table 6; bad totals are errors at file:line:col.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "core/portable_random.h"
#include "scenario/scenario.h"
#include "scenario/whole_vehicle.h"
#include "tests/support/temp_dir.h"
#include "vehicle/vehicle_model.h"

namespace motostab::scenario {

using core::PortableRandom;
using io::InputError;
using vehicle::VehicleModel;

namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;
using V3 = std::array<double, 3>;

// A body of the test's own: mass, CoM, inertia about the CoM (full matrix).
struct Body {
  double m = 0;
  V3 c{0, 0, 0};
  Mat3 I{};
};

Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

Mat3 transpose(const Mat3& a) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = a[j][i];
  return r;
}

// Rotation about axis k by angle t.
Mat3 rotation(int k, double t) {
  Mat3 r{};
  const int a = (k + 1) % 3, b = (k + 2) % 3;
  r[k][k] = 1;
  r[a][a] = r[b][b] = std::cos(t);
  r[a][b] = -std::sin(t);
  r[b][a] = std::sin(t);
  return r;
}

// A physical inertia: second moments A, B, C > 0 along principal axes (moments B+C, A+C, A+B satisfy
// the triangle inequality), turned by a random rotation (`planar`: about y only, a symmetric body).
Mat3 drawInertia(PortableRandom& rng, double scale, bool planar) {
  Mat3 P{};
  const double A = scale * rng.drawUniform(0.2, 1), B = scale * rng.drawUniform(0.05, 0.5), C = scale * rng.drawUniform(0.2, 1);
  P[0][0] = B + C, P[1][1] = A + C, P[2][2] = A + B;
  Mat3 R = rotation(1, rng.drawUniform(-1, 1));
  if (!planar) R = multiply(rotation(0, rng.drawUniform(-0.5, 0.5)), multiply(R, rotation(2, rng.drawUniform(-0.5, 0.5))));
  return multiply(R, multiply(P, transpose(R)));
}

// Parallel-axis composition.
Body compose(const std::vector<Body>& parts) {
  Body t;
  for (const Body& p : parts) {
    t.m += p.m;
    for (int i = 0; i < 3; ++i) t.c[i] += p.m * p.c[i];
  }
  for (int i = 0; i < 3; ++i) t.c[i] /= t.m;
  for (const Body& p : parts) {
    const V3 r{p.c[0] - t.c[0], p.c[1] - t.c[1], p.c[2] - t.c[2]};
    const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) t.I[i][j] += p.I[i][j] + p.m * ((i == j ? r2 : 0) - r[i] * r[j]);
  }
  return t;
}

std::string num(double v) {
  std::ostringstream os;
  os << std::setprecision(17) << v;
  return os.str();
}

std::string inertiaYaml(const Mat3& I) {
  return "{xx: " + num(I[0][0]) + ", yy: " + num(I[1][1]) + ", zz: " + num(I[2][2]) + ", xy: " + num(I[0][1]) + ", xz: " +
         num(I[0][2]) + ", yz: " + num(I[1][2]) + "}";
}

// mass_kg, com_m and inertia_kgm2 of a body, without braces.
std::string bodyKeys(const Body& b) {
  return "mass_kg: " + num(b.m) + ", com_m: [" + num(b.c[0]) + ", " + num(b.c[1]) + ", " + num(b.c[2]) +
         "], inertia_kgm2: " + inertiaYaml(b.I);
}

std::string bodyYaml(const Body& b) { return "{" + bodyKeys(b) + "}"; }

struct RandomVehicle {
  std::string yaml;  ///< the scenario with `total:`
  Body rear, total;
  double wheelbase = 0;
};

// A wheel: its yaml and its body at the hub.
Body drawWheel(PortableRandom& rng, double x, double& radius, std::string& yaml) {
  radius = rng.drawUniform(0.25, 0.35);
  const double m = rng.drawUniform(5, 15), spin = rng.drawUniform(0.3, 0.8), diam = spin * rng.drawUniform(0.55, 0.9);
  yaml = "{radius_m: " + num(radius) + ", crown_radius_m: 0.05, mass_kg: " + num(m) + ", spin_inertia_kgm2: " + num(spin) +
         ", diametral_inertia_kgm2: " + num(diam) + "}";
  Body w;
  w.m = m, w.c = {x, 0, radius};
  w.I[0][0] = w.I[2][2] = diam, w.I[1][1] = spin;
  return w;
}

// The swingarm in D from its frame S (origin at the pivot, x towards the rear hub, z up in the x-z plane).
Body drawSwingarm(PortableRandom& rng, double rearRadius, std::string& yaml) {
  const V3 P{rng.drawUniform(0.5, 0.6), 0, rng.drawUniform(0.35, 0.45)};
  Body S;
  S.m = rng.drawUniform(4, 8);
  S.c = {rng.drawUniform(0.15, 0.3), 0, rng.drawUniform(0, 0.03)};
  S.I = drawInertia(rng, 0.1, true);
  yaml = "swingarm: {pivot_m: [" + num(P[0]) + ", 0, " + num(P[2]) + "], " + bodyKeys(S) + ", compliance: rigid}\n";
  const double dx = -P[0], dz = rearRadius - P[2], L = std::hypot(dx, dz);
  const V3 x{dx / L, 0, dz / L};
  V3 z{-x[2], 0, x[0]};
  if (z[2] < 0) z = {-z[0], 0, -z[2]};
  const V3 y{z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]};
  Mat3 R{};
  for (int i = 0; i < 3; ++i) R[i][0] = x[i], R[i][1] = y[i], R[i][2] = z[i];
  Body D;
  D.m = S.m;
  for (int i = 0; i < 3; ++i) D.c[i] = P[i] + R[i][0] * S.c[0] + R[i][1] * S.c[1] + R[i][2] * S.c[2];
  D.I = multiply(R, multiply(S.I, transpose(R)));
  return D;
}

RandomVehicle drawVehicle(PortableRandom& rng, bool swingarm, bool riderLean, bool forkCompliance) {
  RandomVehicle v;
  v.wheelbase = rng.drawUniform(1.2, 1.6);
  std::string rearWheel, frontWheel, arm;
  double rR = 0, rF = 0;
  std::vector<Body> parts;
  v.rear.m = rng.drawUniform(150, 250);
  v.rear.c = {rng.drawUniform(0.5, 0.8), riderLean ? 0 : rng.drawUniform(-0.02, 0.02), rng.drawUniform(0.6, 0.8)};
  v.rear.I = drawInertia(rng, 10, false);
  parts.push_back(v.rear);
  Body front;
  front.m = rng.drawUniform(10, 20);
  front.c = {v.wheelbase - rng.drawUniform(0.1, 0.2), rng.drawUniform(-0.01, 0.01), rng.drawUniform(0.5, 0.7)};
  front.I = drawInertia(rng, 0.4, false);
  parts.push_back(front);
  parts.push_back(drawWheel(rng, 0, rR, rearWheel));
  parts.push_back(drawWheel(rng, v.wheelbase, rF, frontWheel));
  if (swingarm) parts.push_back(drawSwingarm(rng, rR, arm));
  v.total = compose(parts);
  std::ostringstream y;
  y << "name: random\ngravity_mps2: 9.81\ngeometry: {wheelbase_m: " << num(v.wheelbase) << ", trail_m: "
    << num(rng.drawUniform(0.08, 0.12)) << ", steer_axis_tilt_deg: " << num(rng.drawUniform(20, 30)) << "}\n"
    << "total: " << bodyYaml(v.total) << "\nfront_frame: " << bodyYaml(front) << "\nrear_wheel: " << rearWheel
    << "\nfront_wheel: " << frontWheel << "\ncontact: {model: rolling_no_slip}\n" << arm;
  if (riderLean) {  // a slice of the rear frame: 0.3 of its mass at its CoM, 0.3 of its inertia
    Body u = v.rear;
    u.m *= 0.3;
    for (auto& row : u.I)
      for (double& e : row) e *= 0.3;
    y << "rider_lean: {hinge_height_m: 0.6, " << bodyKeys(u) << ", stiffness_Nm_per_rad: 2000, damping_Nms_per_rad: 60}\n";
  }
  if (forkCompliance) y << "fork_compliance: {stiffness_Nm_per_rad: 40000, damping_Nms_per_rad: 20}\n";
  v.yaml = y.str();
  return v;
}

std::string writeScenario(const std::string& name, const std::string& text) {
  const auto p = makeTempDir("whole_vehicle") / (name + ".yaml");
  std::ofstream(p) << text;
  return p.string();
}

double relativeDifference(const Body& a, const BodySpec& b) {
  const InertiaSpec& I = b.inertia;
  const double bi[3][3] = {{I.xx, I.xy, I.xz}, {I.xy, I.yy, I.yz}, {I.xz, I.yz, I.zz}};
  double d = std::abs(a.m - b.mass) / a.m, norm = 0;
  for (int i = 0; i < 3; ++i) {
    d = std::max(d, std::abs(a.c[i] - b.com[i]));
    for (int j = 0; j < 3; ++j) norm = std::max(norm, std::abs(a.I[i][j]));
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d = std::max(d, std::abs(a.I[i][j] - bi[i][j]) / norm);
  return d;
}

// The Simbody model's own totals at the design pose, about the CoM, D axes; CoM in D from the rear hub.
double compareWithSimbody(const Scenario& s, const Body& total) {
  const VehicleModel model(s);
  SimTK::State st = model.getDefaultState();
  model.getSystem().realize(st, SimTK::Stage::Position);
  const auto& m = model.getMatter();
  const SimTK::Vec3 hub = model.getRearWheel().getBodyOriginLocation(st);
  const SimTK::Vec3 c = m.calcSystemMassCenterLocationInGround(st) - hub + SimTK::Vec3(0, 0, s.rearWheel.radius);
  const SimTK::Mat33 J = m.calcSystemCentralInertiaInGround(st).toMat33();
  BodySpec b;
  b.mass = m.calcSystemMass(st);
  b.com = {c[0], c[1], c[2]};
  b.inertia = {J(0, 0), J(1, 1), J(2, 2), J(0, 1), J(0, 2), J(1, 2)};
  return relativeDifference(total, b);
}

std::string errorOf(const std::string& path) {
  try {
    loadScenario(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(WholeVehicle, RandomTotalsReproduceToOneInABillion) {
  PortableRandom rng(3141);
  for (int k = 0; k < 16; ++k) {
    const bool arm = k % 2 == 1, lean = k % 4 >= 2, fork = k % 8 >= 4;
    const RandomVehicle v = drawVehicle(rng, arm, lean, fork);
    const Scenario s = loadScenario(writeScenario("random" + std::to_string(k), v.yaml));
    ASSERT_TRUE(s.hasTotal);
    EXPECT_LT(relativeDifference(v.rear, s.rearFrame), 1e-9) << "case " << k << "\n" << v.yaml;
    EXPECT_LT(relativeDifference(v.total, calcVehicleTotal(s)), 1e-9) << "case " << k;
    EXPECT_LT(compareWithSimbody(s, v.total), 1e-9) << "case " << k << " (swingarm " << arm << ", rider lean " << lean
                                                    << ", fork compliance " << fork << ")";
  }
}

// Seed Table 6 (vehicle + rider): mass 166.2 + 77.5 kg, CoG (x, height), roll, pitch, yaw inertias and
// the product about the CoG, read as our xz (docs/motorcycle-parameters.md).
TEST(WholeVehicle, BundledMotorcyclesAreTable6) {
  struct Row {
    const char* file;
    double m, x, h, roll, pitch, yaw, product;
  };
  for (const Row& r : {Row{"supersport", 166.2 + 77.5, 0.698, 0.672, 26.7, 51.0, 28.1, 3.2},
                       Row{"supersport-mf", 166.2 + 77.5, 0.698, 0.672, 26.7, 51.0, 28.1, 3.2},
                       Row{"enduro", 190.4 + 77.5, 0.623, 0.697, 33.4, 64.9, 39.4, 1.98}}) {
    const Scenario s = loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/" + r.file + ".yaml");
    Body t;
    t.m = r.m, t.c = {r.x, 0, r.h};
    t.I = {{{r.roll, 0, r.product}, {0, r.pitch, 0}, {r.product, 0, r.yaw}}};
    EXPECT_TRUE(s.hasTotal) << r.file;
    EXPECT_LT(compareWithSimbody(s, t), 1e-9) << r.file;
    EXPECT_TRUE(s.warnings.empty()) << r.file << ": " << (s.warnings.empty() ? "" : s.warnings.front().message);
  }
}

// What a split needs and the data seldom give (front assembly, wheel masses and inertias) is assumed
// from the documented defaults, each named; the default front frame follows its documented rule.
TEST(WholeVehicle, LeftOutValuesAreAssumedAndNamed) {
  const std::string text =
      "name: minimal\ngravity_mps2: 9.81\ngeometry: {wheelbase_m: 1.45, normal_trail_m: 0.1, steer_axis_tilt_deg: 25}\n"
      "total: {mass_kg: 260, com_m: [0.68, 0, 0.66], inertia_kgm2: {xx: 30, yy: 55, zz: 30, xy: 0, xz: 3, yz: 0}}\n"
      "rear_wheel: {radius_m: 0.3, crown_radius_m: 0.08}\nfront_wheel: {radius_m: 0.31, crown_radius_m: 0.06}\n"
      "contact: {model: rolling_no_slip}\n";
  const Scenario s = loadScenario(writeScenario("minimal", text));
  std::vector<std::string> keys;
  for (const AssumedValue& a : s.assumed) keys.push_back(a.key);
  const std::vector<std::string> expected{"rear_wheel.mass_kg", "rear_wheel.spin_inertia_kgm2", "rear_wheel.diametral_inertia_kgm2",
                                          "front_wheel.mass_kg", "front_wheel.spin_inertia_kgm2",
                                          "front_wheel.diametral_inertia_kgm2", "front_frame"};
  EXPECT_EQ(keys, expected);
  // docs/scenario-format.md: 11.9 / 0.60 / 0.32 (front), 13.3 / 0.65 / 0.41 (rear).
  EXPECT_EQ(s.frontWheel.mass, 11.9);
  EXPECT_EQ(s.rearWheel.diametralInertia, 0.41);
  // Front frame: 14 kg at height 2 r_F, 0.02 m ahead of the steer axis; moments 0.35 / 0.75 / 0.85 about
  // the steer axis, the lateral axis and their normal.
  const double lambda = 25 * M_PI / 180, trail = 0.1 / std::cos(lambda), z = 2 * 0.31;
  EXPECT_NEAR(s.frontFrame.com[0], 1.45 + trail - z * std::tan(lambda) + 0.02, 1e-12);
  EXPECT_NEAR(s.frontFrame.com[2], z, 1e-12);
  const double sl = std::sin(lambda), cl = std::cos(lambda);
  EXPECT_NEAR(s.frontFrame.inertia.xx, 0.35 * sl * sl + 0.85 * cl * cl, 1e-12);
  EXPECT_NEAR(s.frontFrame.inertia.zz, 0.35 * cl * cl + 0.85 * sl * sl, 1e-12);
  EXPECT_NEAR(s.frontFrame.inertia.xz, (0.85 - 0.35) * sl * cl, 1e-12);
  EXPECT_EQ(s.frontFrame.inertia.yy, 0.75);
  Body t;
  t.m = 260, t.c = {0.68, 0, 0.66};
  t.I = {{{30, 0, 3}, {0, 55, 0}, {3, 0, 30}}};
  EXPECT_LT(compareWithSimbody(s, t), 1e-9);
}

TEST(WholeVehicle, BadTotalsAreErrorsAtTheTotal) {
  const std::string head = "name: bad\ngravity_mps2: 9.81\ngeometry: {wheelbase_m: 1.45, trail_m: 0.1, steer_axis_tilt_deg: 25}\n";
  const std::string tail =
      "front_frame: {mass_kg: 14, com_m: [1.27, 0, 0.62], inertia_kgm2: {xx: 0.77, yy: 0.75, zz: 0.43, xy: 0, xz: 0.18, yz: 0}}\n"
      "rear_wheel: {radius_m: 0.3, crown_radius_m: 0, mass_kg: 13, spin_inertia_kgm2: 0.65, diametral_inertia_kgm2: 0.4}\n"
      "front_wheel: {radius_m: 0.31, crown_radius_m: 0, mass_kg: 12, spin_inertia_kgm2: 0.6, diametral_inertia_kgm2: 0.32}\n"
      "contact: {model: rolling_no_slip}\n";
  auto total = [](const std::string& mass, const std::string& com, const std::string& inertia) {
    return "total: {mass_kg: " + mass + ", com_m: " + com + ", inertia_kgm2: " + inertia + "}\n";
  };
  const std::string goodI = "{xx: 30, yy: 55, zz: 30, xy: 0, xz: 3, yz: 0}";
  // A yaw inertia smaller than the wheels' and the front frame's share about the CoG: the remainder is no body.
  EXPECT_NE(errorOf(writeScenario("small", head + total("260", "[0.68, 0, 0.66]", "{xx: 30, yy: 38, zz: 10, xy: 0, xz: 3, yz: 0}") + tail))
                .find(":4:1: total: the rear frame left by the total"),
            std::string::npos);
  EXPECT_NE(errorOf(writeScenario("light", head + total("30", "[0.68, 0, 0.66]", goodI) + tail)).find("4:1: total: the other bodies"),
            std::string::npos);
  EXPECT_NE(errorOf(writeScenario("ahead", head + total("260", "[1.68, 0, 0.66]", goodI) + tail)).find("total.com_m: the centre of mass"),
            std::string::npos);
  EXPECT_NE(errorOf(writeScenario("notensor", head + total("260", "[0.68, 0, 0.66]", "{xx: 30, yy: 55, zz: 90, xy: 0, xz: 3, yz: 0}") + tail))
                .find("total.inertia_kgm2: inertia tensor violates the triangle inequality"),
            std::string::npos);
  EXPECT_NE(errorOf(writeScenario("missing", head + tail)).find("missing key 'rear_frame' (or 'total'"), std::string::npos);
  const std::string both = head + total("260", "[0.68, 0, 0.66]", goodI) +
                           "rear_frame: {mass_kg: 200, com_m: [0.6, 0, 0.7], inertia_kgm2: " + goodI + "}\n" + tail;
  EXPECT_NE(errorOf(writeScenario("both", both)).find("5:1: rear_frame: give only one of rear_frame and total"), std::string::npos);
}

}  // namespace motostab::scenario

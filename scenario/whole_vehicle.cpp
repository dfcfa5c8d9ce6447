#include "scenario/whole_vehicle.h"

#include <Eigen/Dense>
#include <cmath>

namespace motostab::scenario {

namespace {

Eigen::Matrix3d toMatrix(const InertiaSpec& I) {
  Eigen::Matrix3d M;
  M << I.xx, I.xy, I.xz, I.xy, I.yy, I.yz, I.xz, I.yz, I.zz;
  return M;
}

InertiaSpec toInertia(const Eigen::Matrix3d& M) { return {M(0, 0), M(1, 1), M(2, 2), M(0, 1), M(0, 2), M(1, 2)}; }

}  // namespace

const char* const kWholeVehicleDefaultSource =
    "default for a sport motorcycle with 17-inch wheels (docs/scenario-format.md#whole-vehicle-total)";

BodySpec makeWheelBody(const WheelSpec& w, const Vec3d& hub_D) {
  BodySpec b;
  b.mass = w.mass;
  b.com = hub_D;
  b.inertia = {w.diametralInertia, w.axialInertia, w.diametralInertia, 0, 0, 0};
  return b;
}

BodySpec calcSwingarmBodyInD(const Scenario& s) {
  const SwingarmFrame f = calcSwingarmFrame(s);
  Eigen::Matrix3d R;  // columns: the axes of S in D
  for (int i = 0; i < 3; ++i) R(i, 0) = f.x[i], R(i, 1) = f.y[i], R(i, 2) = f.z[i];
  const BodySpec& b_S = s.swingarm.body;
  const Eigen::Vector3d c = Eigen::Vector3d(f.origin[0], f.origin[1], f.origin[2]) +
                            R * Eigen::Vector3d(b_S.com[0], b_S.com[1], b_S.com[2]);
  BodySpec b;
  b.mass = b_S.mass;
  b.com = {c(0), c(1), c(2)};
  b.inertia = toInertia(R * toMatrix(b_S.inertia) * R.transpose());
  return b;
}

std::vector<NamedBody> listOtherBodies(const Scenario& s) {
  std::vector<NamedBody> out{{"front_frame", s.frontFrame},
                             {"rear_wheel", makeWheelBody(s.rearWheel, {0, 0, s.rearWheel.radius})},
                             {"front_wheel", makeWheelBody(s.frontWheel, {s.geometry.wheelbase, 0, s.frontWheel.radius})}};
  if (s.hasSwingarm) out.push_back({"swingarm", calcSwingarmBodyInD(s)});
  return out;
}

BodySpec composeBodies(const std::vector<BodySpec>& parts) {
  BodySpec t;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (const BodySpec& p : parts) {
    t.mass += p.mass;
    moment += p.mass * Eigen::Vector3d(p.com[0], p.com[1], p.com[2]);
  }
  const Eigen::Vector3d G = moment / t.mass;
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  for (const BodySpec& p : parts) {
    const Eigen::Vector3d r = Eigen::Vector3d(p.com[0], p.com[1], p.com[2]) - G;
    J += toMatrix(p.inertia) + p.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  t.com = {G(0), G(1), G(2)};
  t.inertia = toInertia(J);
  return t;
}

BodySpec calcVehicleTotal(const Scenario& s) {
  std::vector<BodySpec> parts{s.rearFrame};
  for (const NamedBody& b : listOtherBodies(s)) parts.push_back(b.body);
  return composeBodies(parts);
}

BodySpec calcRearFrameFromTotal(const Scenario& s, const BodySpec& total) {
  std::vector<BodySpec> others;
  for (const NamedBody& b : listOtherBodies(s)) others.push_back(b.body);
  return calcBodyRemainder(total, composeBodies(others));
}

VehicleTable calcVehicleTable(const Scenario& s) {
  VehicleTable t;
  t.total = calcVehicleTotal(s);
  t.wheelLoads = calcStaticWheelLoads(s);
  t.wheelbase = s.geometry.wheelbase;
  t.steerAxisTiltDeg = s.geometry.steerAxisTilt * 180 / M_PI;
  t.trail = s.geometry.trail;
  t.normalTrail = calcNormalTrail(s.geometry);
  t.forkOffset = calcForkOffset(s);
  return t;
}

WheelDefaults getDefaultWheel(bool front) { return front ? WheelDefaults{11.9, 0.60, 0.32} : WheelDefaults{13.3, 0.65, 0.41}; }

BodySpec makeDefaultFrontFrame(const GeometrySpec& g, double frontRadius) {
  const double lambda = g.steerAxisTilt, z = 2 * frontRadius;
  BodySpec b;
  b.mass = 14.0;
  // The steer axis meets the ground at x = w + c and leans back by lambda.
  b.com = {g.wheelbase + g.trail - z * std::tan(lambda) + 0.02, 0, z};
  const Eigen::Vector3d along(-std::sin(lambda), 0, std::cos(lambda)), lateral(0, 1, 0), normal(std::cos(lambda), 0, std::sin(lambda));
  const Eigen::Matrix3d J = 0.35 * along * along.transpose() + 0.75 * lateral * lateral.transpose() +
                            0.85 * normal * normal.transpose();
  b.inertia = toInertia(J);
  return b;
}

}  // namespace motostab::scenario

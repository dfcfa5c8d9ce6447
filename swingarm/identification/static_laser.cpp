#include "swingarm/identification/static_laser.h"

#include <cmath>
#include <cstdio>
#include <set>

#include "io/csv.h"
#include "io/input_error.h"
#include "io/result_error.h"
#include "swingarm/identification/yaml_input.h"

namespace motostab::swingarm::identification {

StaticTest readStaticTest(const std::filesystem::path& file) {
  YamlMap root = openTestFile(file, "static");
  StaticTest t;
  t.file = file;
  t.frame = root.getString("frame", "");
  t.forcePoint = readForcePoint(root);
  std::set<std::string> names;
  std::vector<PlatePoint> points;
  for (YamlMap& m : root.getMapList("sensors")) {
    PlateSensor s{m.getString("name"), {m.getDouble("x"), m.getDouble("z")}};
    if (!names.insert(s.name).second) m.fail("name", "duplicate sensor name '" + s.name + "'");
    m.finish();
    points.push_back(s.position);
    t.sensors.push_back(s);
  }
  const std::string why = checkPlaneGeometry(points);
  if (!why.empty()) root.fail("sensors", why);
  t.readings = root.getFilePath("readings");
  t.sensorResolution = root.getPositive("sensor_resolution_m", 4e-6);
  root.finish();
  return t;
}

StaticReadings readStaticReadings(const StaticTest& test) {
  const CsvTable csv = readCsv(test.readings);
  StaticReadings r;
  r.force = csv.getColumn("force_N");
  r.dy.resize(csv.rows.size(), test.sensors.size());
  for (size_t j = 0; j < test.sensors.size(); ++j) {
    const auto col = csv.getColumn(test.sensors[j].name + "_m");
    for (size_t i = 0; i < col.size(); ++i) r.dy(i, j) = col[i];
  }
  const std::string src = test.readings.string();
  bool unloaded = false;
  std::set<double> levels;
  for (double f : r.force) {
    unloaded = unloaded || f == 0;
    if (f != 0) levels.insert(f);
  }
  if (!unloaded) throw InputError({src, 0, 0, "force_N"}, "no unloaded row (force_N = 0): the reference plane is missing");
  if (levels.size() < 2)
    throw InputError({src, 0, 0, "force_N"}, "need at least two load levels besides the unloaded row, found " +
                                                 std::to_string(levels.size()));
  return r;
}

namespace {

// The plate's rotation per newton, |(dz, dx)| of the compliance plane, must stand out of its standard
// error (three of them): a plate that only translates, to within the readings' noise, has no twist axis.
void requireRotation(const Eigen::Vector3d& slope, const Eigen::Matrix3d& covariance, const StaticTest& test) {
  const double rotation = std::hypot(slope[1], slope[2]);
  const Eigen::Matrix2d c = covariance.bottomRightCorner<2, 2>();
  const double stderr_ = rotation > 0 ? std::sqrt(slope.tail<2>().dot(c * slope.tail<2>())) / rotation
                                      : std::sqrt(c.trace());
  if (rotation > 3 * stderr_) return;
  throw io::ResultError("the plate only translates: its rotation, " + io::formatNumber(rotation, 3) + " +/- " +
                        io::formatNumber(stderr_, 3) + " rad/N, is not distinguishable from zero, so " +
                        test.readings.string() + " gives no twist axis (are the sensors' names and positions right?)");
}

}  // namespace

StaticResult identifyStatic(const StaticTest& test, const StaticReadings& rd) {
  std::vector<PlatePoint> pts;
  for (const auto& s : test.sensors) pts.push_back(s.position);
  const Eigen::MatrixXd P = calcPlaneFitOperator(pts), A = calcPlaneDesignMatrix(pts);
  const int nl = static_cast<int>(rd.force.size()), ns = static_cast<int>(pts.size());
  StaticResult res;
  double fMean = 0;
  for (double f : rd.force) fMean += f / nl, res.maxForce = std::max(res.maxForce, std::abs(f));
  double sxx = 0;
  Eigen::Vector3d slope = Eigen::Vector3d::Zero();
  for (int i = 0; i < nl; ++i) {
    LoadLevelFit lv;
    lv.force = rd.force[i];
    const Eigen::VectorXd y = rd.dy.row(i).transpose();
    lv.plane = P * y;
    lv.residualRms = std::sqrt((y - A * lv.plane).squaredNorm() / ns);
    res.levels.push_back(lv);
    sxx += (lv.force - fMean) * (lv.force - fMean);
    slope += (lv.force - fMean) * lv.plane;
  }
  slope /= sxx;
  res.compliancePlane = slope;
  // Residuals of the full model: reading = sensor offset + F * plane(slope).
  const Eigen::VectorXd perN = A * slope;
  const Eigen::VectorXd offsets = rd.dy.colwise().mean().transpose() - fMean * perN;
  double ss = 0;
  for (int i = 0; i < nl; ++i) ss += (rd.dy.row(i).transpose() - offsets - rd.force[i] * perN).squaredNorm();
  res.residualDof = nl * ns - ns - 3;
  res.sigmaResidual = res.residualDof > 0 ? std::sqrt(ss / res.residualDof) : 0.0;
  res.sigma = std::max(res.sigmaResidual, test.sensorResolution / std::sqrt(12.0));
  res.complianceCovariance = res.sigma * res.sigma * (A.transpose() * A).inverse() / sxx;
  requireRotation(slope, res.complianceCovariance, test);

  res.axis = calcTwistAxis(slope, test.forcePoint);
  const double beta0 = res.axis.betaDeg;
  // Derived quantities as a function of the slope plane, for propagation.
  auto derive = [&](const Eigen::VectorXd& s) {
    const TwistAxis a = calcTwistAxis(s, test.forcePoint);
    Eigen::VectorXd v(8);
    const double kLat = 1.0 / a.forcePointMotion;
    v << kLat, a.arm, kLat * a.arm * a.arm, beta0 + wrapDegrees(a.betaDeg - beta0), a.rotation, a.forcePointMotion,
        a.point[0], a.point[1];
    return v;
  };
  const Eigen::VectorXd v = derive(slope);
  const Eigen::MatrixXd cv = propagateCovariance(derive, slope, res.complianceCovariance);
  auto se = [&](int i) { return std::sqrt(std::max(cv(i, i), 0.0)); };
  res.kLat = v[0], res.kLatStderr = se(0);
  res.aTw = v[1], res.aTwStderr = se(1);
  res.kTw = v[2], res.kTwStderr = se(2);
  res.betaDeg = v[3], res.betaStderrDeg = se(3);
  res.rotationPerN = v[4], res.rotationPerNStderr = se(4);
  res.yLatPerN = v[5], res.yLatPerNStderr = se(5);
  res.axisPointStderr = Eigen::Vector2d(se(6), se(7));
  return res;
}

}  // namespace motostab::swingarm::identification

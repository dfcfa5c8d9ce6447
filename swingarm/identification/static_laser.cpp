#include "swingarm/identification/static_laser.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>

#include "io/atomic_file.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "swingarm/identification/axes_plot.h"
#include "swingarm/identification/yaml_input.h"

namespace motostab::swingarm::identification {

using io::CsvTable;
using io::InputError;
using io::YamlMap;
using io::readCsv;
using io::writeFileAtomically;


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

void writeStaticOutputs(const StaticTest& test, const StaticResult& r, const std::filesystem::path& dir) {
  using nlohmann::json;
  const Eigen::Vector2d dirStderr = Eigen::Vector2d(std::abs(std::sin(r.betaDeg * M_PI / 180)),
                                                    std::abs(std::cos(r.betaDeg * M_PI / 180))) *
                                    (r.betaStderrDeg * M_PI / 180);
  json j;
  j["test"] = test.file.string();
  j["frame"] = test.frame;
  j["k_lat_N_per_m"] = r.kLat;
  j["k_lat_N_per_m_stderr"] = r.kLatStderr;
  j["a_tw_m"] = r.aTw;
  j["a_tw_m_stderr"] = r.aTwStderr;
  j["k_tw_Nm_per_rad"] = r.kTw;
  j["k_tw_Nm_per_rad_stderr"] = r.kTwStderr;
  j["beta_deg"] = r.betaDeg;
  j["beta_deg_stderr"] = r.betaStderrDeg;
  j["axis_point_m"] = {r.axis.point[0], 0.0, r.axis.point[1]};
  j["axis_point_m_stderr"] = {r.axisPointStderr[0], 0.0, r.axisPointStderr[1]};
  j["axis_direction"] = {r.axis.direction[0], 0.0, r.axis.direction[1]};
  j["axis_direction_stderr"] = {dirStderr[0], 0.0, dirStderr[1]};
  j["rotation_per_N_rad_per_N"] = r.rotationPerN;
  j["rotation_per_N_rad_per_N_stderr"] = r.rotationPerNStderr;
  j["y_lat_per_N_m_per_N"] = r.yLatPerN;
  j["y_lat_per_N_m_per_N_stderr"] = r.yLatPerNStderr;
  j["y_lat_at_max_load_m"] = r.yLatPerN * r.maxForce;
  j["y_lat_at_max_load_m_stderr"] = r.yLatPerNStderr * r.maxForce;
  j["max_load_N"] = r.maxForce;
  j["force_point_m"] = {test.forcePoint.x, 0.0, test.forcePoint.z};
  j["reading_sigma_m"] = r.sigma;
  j["reading_sigma_residual_m"] = r.sigmaResidual;
  j["residual_dof"] = r.residualDof;
  j["sensor_resolution_m"] = test.sensorResolution;
  json levels = json::array();
  for (const auto& lv : r.levels)
    levels.push_back({{"force_N", lv.force}, {"d0_m", lv.plane[0]}, {"dx_rad", lv.plane[1]}, {"dz_rad", lv.plane[2]},
                      {"residual_rms_m", lv.residualRms}});
  j["load_levels"] = levels;
  j["conventions"] =
      "axis point = foot of the perpendicular from the force point, in (x, y, z) with y = 0 the plate plane; "
      "axis_direction is oriented so that a_tw > 0 (y at the force point = theta * a_tw); beta_deg = atan2(e_z, e_x)";
  writeFileAtomically(dir / "static.json", j.dump(2) + "\n");
  std::vector<PlotMarker> sensors;
  for (const auto& s : test.sensors) sensors.push_back({s.name, s.position});
  char title[160];
  std::snprintf(title, sizeof title, "Static twist axis: {/Symbol b} = %.2f deg, a_{tw} = %.4f m, k_{tw} = %.4g Nm/rad",
                r.betaDeg, r.aTw, r.kTw);
  writeAxesPlot(dir, "static_axis", title, sensors, test.forcePoint, {{"static twist axis", r.axis.point, r.axis.direction}});
}

}  // namespace motostab::swingarm::identification

#include "swingarm/identification/mass_properties.h"

#include <cmath>
#include <set>
#include <sstream>

#include "io/csv.h"
#include "io/input_error.h"
#include "swingarm/identification/plate_motion.h"
#include "swingarm/identification/yaml_input.h"

namespace motostab::swingarm::identification {

namespace {

struct MeanStat {
  double mean = 0, stderr_ = 0;
};

MeanStat calcMean(const std::vector<double>& v, double floorSd) {
  MeanStat m;
  for (double x : v) m.mean += x / v.size();
  double s = 0;
  for (double x : v) s += (x - m.mean) * (x - m.mean);
  const double sd = v.size() > 1 ? std::sqrt(s / (v.size() - 1)) : 0.0;
  m.stderr_ = std::max(sd, floorSd) / std::sqrt(static_cast<double>(v.size()));
  return m;
}

}  // namespace

CogTest readCogTest(const std::filesystem::path& file) {
  YamlMap root = openTestFile(file, "cog");
  CogTest t;
  t.file = file;
  t.frame = root.getString("frame", "");
  std::vector<PlatePoint> pts;
  std::set<std::string> names;
  for (YamlMap& m : root.getMapList("load_cells")) {
    LoadCell c{m.getString("name"), m.getDouble("x"), m.getDouble("y")};
    if (!names.insert(c.name).second) m.fail("name", "duplicate load cell name");
    m.finish();
    pts.push_back({c.x, c.y});
    t.cells.push_back(c);
  }
  const std::string why = checkPlaneGeometry(pts);
  if (!why.empty()) root.fail("load_cells", "load cells: " + why);
  t.g = root.getPositive("g_mps2", t.g);
  t.cellResolution = root.getPositive("load_cell_resolution_N", t.cellResolution);
  if (root.has("part_origin_m")) {
    const auto o = root.getDoubleList("part_origin_m", 3);
    t.partOrigin = Eigen::Vector3d(o[0], o[1], o[2]);
  }
  auto readTable = [&](const std::filesystem::path& csvPath, std::vector<double>& tilt, Eigen::MatrixXd& loads) {
    const CsvTable csv = readCsv(csvPath);
    tilt = csv.getColumn("tilt_deg");
    loads.resize(tilt.size(), t.cells.size());
    for (size_t j = 0; j < t.cells.size(); ++j) {
      const auto col = csv.getColumn(t.cells[j].name + "_N");
      for (size_t i = 0; i < col.size(); ++i) loads(i, j) = col[i];
    }
    const int tc = csv.getColumnIndex("tilt_deg") + 1;
    for (size_t i = 0; i < tilt.size(); ++i)
      if (tilt[i] < 0 || tilt[i] > 60)
        throw InputError({csvPath.string(), csv.lineNumbers[i], tc, "tilt_deg"}, "tilt angle outside 0..60 deg");
  };
  const std::filesystem::path readings = root.getFilePath("readings");
  readTable(readings, t.tiltDeg, t.loads);
  std::set<double> angles(t.tiltDeg.begin(), t.tiltDeg.end());
  if (angles.size() < 2 || *angles.rbegin() == 0)
    throw InputError({readings.string(), 0, 0, "tilt_deg"}, "need at least two distinct tilt angles, one of them non-zero");
  if (root.has("tare")) {
    const std::filesystem::path tare = root.getFilePath("tare");
    std::vector<double> tt;
    Eigen::MatrixXd tl;
    readTable(tare, tt, tl);
    if (tt != t.tiltDeg)
      throw InputError({tare.string(), 0, 0, "tilt_deg"}, "tare rows must have the same tilt angles as the readings");
    t.loads -= tl;
  }
  root.finish();
  return t;
}

CogResult identifyCog(const CogTest& t) {
  const int n = static_cast<int>(t.tiltDeg.size());
  Eigen::MatrixXd a(n, 2);
  Eigen::VectorXd xp(n);
  std::vector<double> yp, mass;
  double floorX = 0;
  for (int i = 0; i < n; ++i) {
    const double alpha = t.tiltDeg[i] * M_PI / 180, w = t.loads.row(i).sum();
    if (!(w > 0)) throw InputError({t.file.string(), 0, 0, "readings"}, "load cells sum to zero or less at a tilt");
    double sx = 0, sy = 0, sxx = 0;
    for (size_t j = 0; j < t.cells.size(); ++j) {
      sx += t.cells[j].x * t.loads(i, j);
      sy += t.cells[j].y * t.loads(i, j);
    }
    xp[i] = sx / w;
    for (const auto& c : t.cells) sxx += (c.x - xp[i]) * (c.x - xp[i]);
    floorX = std::max(floorX, t.cellResolution / std::sqrt(12.0) * std::sqrt(sxx) / w);
    yp.push_back(sy / w);
    mass.push_back(w / (t.g * std::cos(alpha)));
    a.row(i) << 1.0, -std::tan(alpha);
  }
  const Eigen::Vector2d p = (a.transpose() * a).ldlt().solve(a.transpose() * xp);
  const Eigen::VectorXd r = xp - a * p;
  CogResult res;
  res.centreOfPressureX.assign(xp.data(), xp.data() + n);
  res.residualRms = std::sqrt(r.squaredNorm() / n);
  const double sigma = std::max(n > 2 ? std::sqrt(r.squaredNorm() / (n - 2)) : 0.0, floorX);
  const Eigen::Matrix2d cov = sigma * sigma * (a.transpose() * a).inverse();
  const MeanStat y = calcMean(yp, floorX), m = calcMean(mass, t.cellResolution / std::sqrt(12.0) / t.g);
  res.mass = m.mean;
  res.massStderr = m.stderr_;
  res.cog = Eigen::Vector3d(p[0], y.mean, p[1]) - t.partOrigin;
  res.cogStderr = Eigen::Vector3d(std::sqrt(cov(0, 0)), y.stderr_, std::sqrt(cov(1, 1)));
  return res;
}

namespace {

// A non-empty list of positive periods, s.
std::vector<double> readPeriods(YamlMap& m, const std::string& key) {
  const auto v = m.getDoubleList(key);
  if (v.empty()) m.fail(key, "needs at least one period");
  for (size_t i = 0; i < v.size(); ++i)
    if (!(v[i] > 0)) m.failElement(key, i, "periods must be positive");
  return v;
}

}  // namespace

InertiaTest readInertiaTest(const std::filesystem::path& file) {
  YamlMap root = openTestFile(file, "inertia");
  InertiaTest t;
  t.file = file;
  root.getString("frame", "");  // documentation only
  YamlMap p = root.getMap("pendulum");
  t.wireLength = p.getPositive("wire_length_m");
  t.radius = p.getPositive("radius_m");
  t.plateMass = p.getPositive("plate_mass_kg");
  p.finish();
  t.g = root.getPositive("g_mps2", t.g);
  t.periodResolution = root.getPositive("period_resolution_s", t.periodResolution);
  t.partMass = root.getPositive("part_mass_kg");
  t.platePeriods = readPeriods(root, "plate_periods_s");
  std::vector<YamlMap> setups = root.getMapList("setups");
  if (setups.size() < 3) root.fail("setups", "expected a list of at least three set-ups");
  for (YamlMap& m : setups) {
    PendulumSetup u;
    u.name = m.getString("name");
    const auto ax = m.getDoubleList("axis", 3);
    u.axis = Eigen::Vector3d(ax[0], ax[1], ax[2]);
    if (u.axis.norm() < 1e-9) m.fail("axis", "axis must not be zero");
    u.axis.normalize();
    u.cogOffset = m.getNonNegative("cog_offset_m");
    u.periods = readPeriods(m, "periods_s");
    m.finish();
    t.setups.push_back(u);
  }
  root.finish();
  return t;
}

double calcTrifilarInertia(double mass, double g, double radius, double wireLength, double period) {
  return mass * g * radius * radius * period * period / (4 * M_PI * M_PI * wireLength);
}

InertiaResult identifyInertia(const InertiaTest& t) {
  InertiaResult r;
  const double floorT = t.periodResolution / std::sqrt(12.0);
  auto inertia = [&](double mass, const std::vector<double>& periods, double& stderr_) {
    const MeanStat T = calcMean(periods, floorT);
    const double i = calcTrifilarInertia(mass, t.g, t.radius, t.wireLength, T.mean);
    stderr_ = 2 * i * T.stderr_ / T.mean;
    return i;
  };
  r.plateInertia = inertia(t.plateMass, t.platePeriods, r.plateInertiaStderr);
  const int n = static_cast<int>(t.setups.size());
  Eigen::MatrixXd a(n, 6);
  Eigen::VectorXd b(n), w(n);
  for (int i = 0; i < n; ++i) {
    const auto& u = t.setups[i];
    double se = 0;
    const double total = inertia(t.plateMass + t.partMass, u.periods, se);
    const double ip = total - r.plateInertia - t.partMass * u.cogOffset * u.cogOffset;
    const double sp = std::hypot(se, r.plateInertiaStderr);
    r.setupInertia.push_back(ip);
    r.setupInertiaStderr.push_back(sp);
    const Eigen::Vector3d e = u.axis;
    // n^T I n = Ixx ex^2 + Iyy ey^2 + Izz ez^2 + 2 Ixy ex ey + 2 Ixz ex ez + 2 Iyz ey ez
    a.row(i) << e[0] * e[0], e[1] * e[1], e[2] * e[2], 2 * e[0] * e[1], 2 * e[0] * e[2], 2 * e[1] * e[2];
    b[i] = ip;
    w[i] = 1.0 / sp;
  }
  const Eigen::MatrixXd aw = w.asDiagonal() * a;
  r.fullTensor = n >= 6 && Eigen::FullPivLU<Eigen::MatrixXd>(aw).rank() == 6;
  const int nc = r.fullTensor ? 6 : 3;
  const Eigen::MatrixXd as = aw.leftCols(nc);
  if (Eigen::FullPivLU<Eigen::MatrixXd>(as).rank() < nc)
    throw InputError({t.file.string(), 0, 0, "setups"},
                     "the set-up axes do not determine the moments of inertia (need x, y and z directions)");
  const Eigen::MatrixXd ninv = (as.transpose() * as).inverse();
  const Eigen::VectorXd x = ninv * as.transpose() * (w.asDiagonal() * b);
  Eigen::VectorXd se = ninv.diagonal().cwiseSqrt();
  const int idx[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  for (int k = 0; k < nc; ++k) {
    r.tensor(idx[k][0], idx[k][1]) = r.tensor(idx[k][1], idx[k][0]) = x[k];
    r.tensorStderr(idx[k][0], idx[k][1]) = r.tensorStderr(idx[k][1], idx[k][0]) = se[k];
  }
  return r;
}

}  // namespace motostab::swingarm::identification

#include "swingarm/identification/plate_motion.h"

#include <cmath>
#include <stdexcept>

#include "io/result_error.h"

namespace motostab::swingarm::identification {

std::string checkPlaneGeometry(const std::vector<PlatePoint>& points) {
  if (points.size() < 3)
    return "a plane fit needs at least three points, found " + std::to_string(points.size());
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : points) mean += Eigen::Vector2d(p.x, p.z) / points.size();
  Eigen::Matrix2d c = Eigen::Matrix2d::Zero();
  for (const auto& p : points) {
    const Eigen::Vector2d d = Eigen::Vector2d(p.x, p.z) - mean;
    c += d * d.transpose();
  }
  const Eigen::Vector2d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(c).eigenvalues();
  if (ev[1] <= 0 || std::sqrt(ev[0] / ev[1]) < 1e-3) return "the points are collinear (no plane can be fitted)";
  return "";
}

Eigen::MatrixXd calcPlaneDesignMatrix(const std::vector<PlatePoint>& points) {
  Eigen::MatrixXd a(points.size(), 3);
  for (size_t i = 0; i < points.size(); ++i) a.row(i) << 1.0, points[i].x, points[i].z;
  return a;
}

Eigen::MatrixXd calcPlaneFitOperator(const std::vector<PlatePoint>& points) {
  const std::string why = checkPlaneGeometry(points);
  if (!why.empty()) throw std::logic_error("calcPlaneFitOperator: " + why);  // the readers check the geometry
  const Eigen::MatrixXd a = calcPlaneDesignMatrix(points);
  return (a.transpose() * a).ldlt().solve(a.transpose());
}

TwistAxis calcTwistAxis(const Eigen::Vector3d& plane, const PlatePoint& f) {
  const Eigen::Vector2d omega(-plane[2], plane[1]);
  TwistAxis t;
  t.rotation = omega.norm();
  if (!(t.rotation > 0)) throw io::ResultError("the plate only translates: no twist axis");
  const double y = plane[0] + plane[1] * f.x + plane[2] * f.z;
  t.direction = (y >= 0 ? 1.0 : -1.0) * omega / t.rotation;
  t.forcePointMotion = std::abs(y);
  t.arm = t.forcePointMotion / t.rotation;
  t.betaDeg = std::atan2(t.direction[1], t.direction[0]) * 180 / M_PI;
  const Eigen::Vector2d n(t.direction[1], -t.direction[0]);
  t.point = Eigen::Vector2d(f.x, f.z) - t.arm * n;
  return t;
}

double calcArmAt(const Eigen::Vector2d& p, double betaDeg, const PlatePoint& r) {
  const double b = betaDeg * M_PI / 180;
  return std::sin(b) * (r.x - p[0]) - std::cos(b) * (r.z - p[1]);
}

Eigen::MatrixXd propagateCovariance(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f,
                                    const Eigen::VectorXd& x, const Eigen::MatrixXd& cov) {
  const Eigen::VectorXd y0 = f(x);
  Eigen::MatrixXd jac(y0.size(), x.size());
  for (int i = 0; i < x.size(); ++i) {
    const double sd = std::sqrt(std::max(cov(i, i), 0.0));
    const double h = sd > 0 ? 1e-3 * sd : 1e-8 * std::max(std::abs(x[i]), 1e-12);
    Eigen::VectorXd xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    jac.col(i) = (f(xp) - f(xm)) / (2 * h);
  }
  return jac * cov * jac.transpose();
}

double wrapDegrees(double a) {
  a = std::fmod(a, 360.0);
  if (a <= -180) a += 360;
  if (a > 180) a -= 360;
  return a;
}

}  // namespace motostab::swingarm::identification
